// The chart driver (chart.hpp): the rectangle's validation, and the region
// classification against direct one-parameter runs (Continue of
// continuation.hpp) at interior cells of every region.
#include "stickslip/chart/chart.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "chart/chart_regions.hpp"
#include "stickslip/continuation/continuation.hpp"
#include "stickslip/errors.hpp"

namespace stickslip {
namespace {

bool Contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

TEST(Chart, RectangleValidated) {
  const Params base;
  auto err = [&](Plane pl) { return pl.ValidationError(base); };
  EXPECT_EQ(err(Plane{}), "");
  EXPECT_TRUE(Contains(err(Plane{Parameter::kV, Parameter::kV, 0.1, 0.5, 0.1, 0.5}),
                       "the two axes must differ"));
  EXPECT_TRUE(Contains(UnknownAxisError("gamma", "param"), "'gamma' is no parameter"));
  EXPECT_EQ(UnknownAxisError("beta", "param"), "");
  EXPECT_TRUE(Contains(err(Plane{Parameter::kV, Parameter::kDelta, 0.1, 0.5, 0, 0.1}),
                       "does not apply to the cubic"));
  EXPECT_TRUE(Contains(err(Plane{Parameter::kV, Parameter::kBeta, 0.5, 0.5, 0, 0.1}),
                       "the rectangle is empty"));
  EXPECT_TRUE(Contains(err(Plane{Parameter::kV, Parameter::kBeta, 0.5, 0.1, 0, 0.1}),
                       "the rectangle is inverted"));
  EXPECT_TRUE(Contains(err(Plane{Parameter::kV, Parameter::kBeta, 0.1, 0.5, 0.1, 0.05}),
                       "from2 = 0.1 must be <"));
  EXPECT_TRUE(Contains(err(Plane{Parameter::kV, Parameter::kBeta, -0.1, 0.5, 0, 0.1}),
                       "leaves the model's domain"));
  EXPECT_TRUE(Contains(err(Plane{Parameter::kV, Parameter::kMuS, 0.1, 0.5, 0.2, 0.5}),
                       "mu_m = 0.25 must be < mu_s"));
  Params quintic;
  quintic.k5 = 0.24;  // mu(v) < 0 beyond v ~ 1.3
  EXPECT_TRUE(
      Contains(Plane{Parameter::kV, Parameter::kBeta, 0.1, 1.5, 0, 0.1}.ValidationError(quintic),
               "k5 = 0.24"));
  ChartOptions o;
  o.plane = Plane{Parameter::kV, Parameter::kV, 0.1, 0.5, 0.1, 0.5};
  EXPECT_THROW(Chart(base, o), InvalidArgument);
}

// Degenerate ranges and steps are refused up front: they once gave 10 curves
// of 39,999 identical rows (--to 0.0500000000000001) or 160 MB of fragments
// (--max_step 1e-9), reported complete.
TEST(Chart, DegenerateRangesAndStepsRefused) {
  const Params base;
  const PlaneError e =
      Plane{Parameter::kV, Parameter::kBeta, 0.05, 0.0500000000000001, 0, 0.25}.Check(base);
  EXPECT_EQ(e.input, PlaneInput::kTo);
  EXPECT_TRUE(Contains(e.message, "to = 0.0500000000000001 is too close to from = 0.05"))
      << e.message;
  EXPECT_TRUE(Contains(
      Plane{Parameter::kV, Parameter::kBeta, 0.05, 0.6, 0.1, 0.1 + 1e-9}.ValidationError(base),
      "to2 = 0.100000001 is too close"));
  const Plane tiny{Parameter::kV, Parameter::kBeta, 0.05, 0.6, 0,
                   1e-12};  // from2 = 0: relative to 1e-12
  EXPECT_EQ(tiny.ValidationError(base), "");
  ChartOptions o;
  o.max_step = 1e-9;
  EXPECT_TRUE(Contains(o.ValidationError(base), "max_step = 1e-09 must be in [5e-05, 0.2]"));
  o.max_step = 1.0 / kMaxCurvePoints;
  EXPECT_EQ(o.ValidationError(base), "");
  // The belt's chart follows HB and GR seeds; LP, PD and NS (a forced
  // orbit's curves, the one CurveKind) are refused by name.
  o.seeds = {{CurveKind::kGrazing, 0.3, 0.05}};
  EXPECT_EQ(o.ValidationError(base), "");
  for (const CurveKind k : {CurveKind::kFold, CurveKind::kPeriodDoubling, CurveKind::kTorus}) {
    o.seeds = {{k, 0.3, 0.05}};
    EXPECT_TRUE(Contains(o.ValidationError(base),
                         std::string("seed ") + Name(k) + " at (0.3, 0.05): only HB and GR"))
        << o.ValidationError(base);
  }
}

// A range end outside the model's domain is blamed on that end, at the value
// given (not at a grid point such as beta = 1062500).
TEST(Chart, RangeEndErrorsNameTheEnd) {
  const Params base;
  PlaneError e = Plane{Parameter::kV, Parameter::kBeta, 0.05, 0.6, 0, 5e6}.Check(base);
  EXPECT_EQ(e.input, PlaneInput::kTo2);
  EXPECT_STREQ(PlaneInputKey(e.input), "to2");
  EXPECT_TRUE(Contains(e.message, "beta = 5000000 is outside [0, 1000000]")) << e.message;
  e = Plane{Parameter::kV, Parameter::kBeta, 0.05, 0.6, -0.1, 0.1}.Check(base);
  EXPECT_EQ(e.input, PlaneInput::kFrom2);
  e = Plane{Parameter::kV, Parameter::kMuS, 0.05, 0.6, 0.1, 0.5}.Check(base);  // mu_s < mu_m = 0.25
  EXPECT_EQ(e.input, PlaneInput::kFrom2) << e.message;
  Params quintic;
  quintic.k5 = 0.24;
  e = Plane{Parameter::kV, Parameter::kBeta, 0.1, 1.5, 0, 0.1}.Check(quintic);
  EXPECT_EQ(e.input, PlaneInput::kTo);
  EXPECT_TRUE(Contains(e.message, "v = 1.5")) << e.message;
}

// A curve cut short inside the rectangle makes the chart partial, naming it.
TEST(Chart, CutShortCurveMakesTheChartPartial) {
  ChartOptions o;
  o.plane =
      Plane{Parameter::kV, Parameter::kBeta, 0.466, 0.5, 0, 0.03};  // HB crosses it diagonally
  o.max_step = 1.0 / kMaxCurvePoints;  // a crossing takes ~1.4 / max_step points
  o.grazing_curves = o.fold_curves = false;
  const ChartResult r = Chart(Params{}, o);
  EXPECT_EQ(r.status, ChartStatus::kPartial);
  EXPECT_STREQ(Name(r.status), "partial");
  EXPECT_TRUE(Contains(r.message, "HB curve from v = 0.466"));
  EXPECT_TRUE(Contains(r.message, "cut short: max-points")) << r.message;
  o.max_step = 0.01;
  EXPECT_EQ(Chart(Params{}, o).status, ChartStatus::kOk);
}

constexpr double kHalfRange = 0.003;

// The region at (v, beta) from one-parameter runs over v +- kHalfRange.
Region RegionFromContinuation(Params p, double v, double beta) {
  p.beta = beta;
  ContinuationOptions o;
  o.param = ParameterAxis("v");
  o.from = v - kHalfRange;
  o.to = v + kHalfRange;
  const ContinuationResult r = Continue(p, o);
  EXPECT_FALSE(r.partial()) << r.message;
  bool stable = false, stick_slip = false, pure_slip = false;
  double nearest = HUGE_VAL;
  for (const BranchPoint& b : r.points) {
    if (b.kind == PointKind::kEquilibrium && std::abs(b.p - v) < nearest)
      nearest = std::abs(b.p - v), stable = b.stable;
    stick_slip = stick_slip || b.kind == PointKind::kStickSlip;
    pure_slip = pure_slip || (b.kind == PointKind::kPureSlip && b.stable);
  }
  if (!stable) return stick_slip ? Region::kStickSlip : Region::kPureSlip;
  return stick_slip || pure_slip ? Region::kBistable : Region::kSteadyOnly;
}

// For each region of the grid, the first cell whose region holds over its
// centre's v +- kHalfRange (ClassifyPoint at both ends), against Continue there.
void ExpectRegionsAgreeWithContinuation(const Params& base, const Plane& plane, int n,
                                        int expected_regions) {
  ChartOptions o;
  o.plane = plane;
  o.region_n1 = o.region_n2 = n;
  o.fold_curves = false;
  const ChartResult r = Chart(base, o);
  OrbitFinder finder(Model(base), o.orbit);
  std::map<Region, std::pair<int, int>> cells;
  for (int i = 0; i < n; ++i) {
    for (int j = 1; j + 1 < n; ++j) {
      const Region here = r.regions.at(i, j);
      if (cells.count(here)) continue;
      bool holds = true;
      for (double dv : {-kHalfRange, kHalfRange})
        holds =
            holds && ClassifyPoint(finder, plane.At(base, r.regions.x1[i] + dv, r.regions.x2[j]),
                                   true) == here;
      if (holds) cells.emplace(here, std::make_pair(i, j));
    }
  }
  EXPECT_EQ(static_cast<int>(cells.size()), expected_regions);
  for (const auto& [region, ij] : cells) {
    const double v = r.regions.x1[ij.first], beta = r.regions.x2[ij.second];
    EXPECT_EQ(RegionFromContinuation(base, v, beta), region)
        << Name(region) << " at v = " << v << ", beta = " << beta;
  }
}

TEST(Chart, SeedRegionsAgreeWithOneParameterRuns) {
  // Stick-slip, pure-slip and steady sliding only (no bistability: supercritical).
  ExpectRegionsAgreeWithContinuation(
      Params{}, Plane{Parameter::kV, Parameter::kBeta, 0.02, 0.6, 0.0, 0.25}, 20, 3);
}

TEST(Chart, StribeckRegionsAgreeWithOneParameterRuns) {
  Params p;
  p.law = LawKind::kStribeck;
  p.mu_s = 0.4, p.mu_k = 0.25, p.v_s = 0.5;
  // Subcritical: stick-slip beside stable steady sliding in a band past HB.
  ExpectRegionsAgreeWithContinuation(
      p, Plane{Parameter::kV, Parameter::kBeta, 0.05, 0.6, 0.01, 0.14}, 20, 3);
}

TEST(Chart, QuinticRegionsAgreeWithOneParameterRuns) {
  Params p;
  p.k5 = 0.24;
  // All four: stick-slip, pure slip (above GR-LP), steady only, bistable (below GH).
  ExpectRegionsAgreeWithContinuation(
      p, Plane{Parameter::kV, Parameter::kBeta, 0.05, 0.58, 0.0, 0.12}, 20, 4);
}

}  // namespace
}  // namespace stickslip
