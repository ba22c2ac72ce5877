// Every row of the shipped forced studies' m = 1 branches against the
// independent long-double reference (forced_curve_reference.hpp): the
// stroboscopic point (x0, x'0), x_max, x_min and the multipliers, each
// relative to max(1, |value|), at the app's defaults (ss_continue --study
// studies/NAME.ini: rtol = atol = 1e-12, max_step 0.02 of the range, the start
// settled from rest as the app's). A row is compared with the reference point
// nearest it on the curve: Omega held away from folds, a state component near
// one (CurvePoint::fixed); there the row's Omega is compared too. No multiplier
// is compared at a sliding point (GR, CR, ...: the multiplier jumps there).
// Every special row and every stride-th row are compared (Study::stride, about
// 14 s in all); STICKSLIP_EVERY_ROW=1 compares every row (about 95 s).
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "cli/clock_start.hpp"
#include "forced_curve_reference.hpp"
#include "forced_trace.hpp"
#include "stickslip/systems/forced/flow.hpp"

namespace stickslip {
namespace {

namespace ref = forced_reference;
using ref::Real;

// The largest error of one column and the row where it occurs.
struct Worst {
  double err = 0, p = 0;
  int row = -1;
  std::string label;
  void Add(double e, int i, const OrbitRow& r) {
    if (!(e <= err)) err = e, row = i, p = r.p, label = Name(r.label);
  }
};

enum Column { kP, kX0, kXdot0, kXmax, kXmin, kMu, kColumns };
const char* const kNames[kColumns] = {"Omega", "x0", "xdot0", "x_max", "x_min", "mu"};

double Rel(double got, Real want) {
  return static_cast<double>(std::abs(got - want) / std::max(Real(1), std::abs(want)));
}

// The multipliers' distance, paired by the closer of the two pairings.
double MuError(const OrbitRow& r, const std::array<std::complex<Real>, 2>& mu) {
  auto d = [&](int i, int j) {
    const std::complex<Real> got(r.multipliers[i].real(), r.multipliers[i].imag());
    return static_cast<double>(std::abs(got - mu[j]) / std::max(Real(1), std::abs(mu[j])));
  };
  return std::min(std::max(d(0, 0), d(1, 1)), std::max(d(0, 1), d(1, 0)));
}

// The reference's difference quotients err by truncation (large near a
// sliding point: a short stick phase, a near graze) or by the map's rounding
// (~1e-17 / step): a row whose multipliers differ from the first step's by
// more than kOtherStepsAbove is compared with a larger and a smaller step's
// too, and its error is the closest one's (the true error exceeds it by at
// most the worst estimate's own).
constexpr Real kOtherSteps[2] = {3e-4L, 2.5e-5L};  // CurveReference::mu_step: 1e-4
constexpr double kOtherStepsAbove = 1e-13;

template <class Piece>
double MuError(const OrbitRow& r, const ref::CurveReference<Piece>& reference,
               const ref::CurvePoint& c) {
  double e = MuError(r, c.mu);
  for (const Real h : kOtherSteps)
    if (e > kOtherStepsAbove) e = std::min(e, MuError(r, reference.Multipliers(c, h)));
  return e;
}

bool Sliding(SpecialKind l) {
  return l != SpecialKind::kNone && l != SpecialKind::kFold && l != SpecialKind::kPeriodDoubling &&
         l != SpecialKind::kTorus;
}

struct Study {
  const char* name;
  ForcedBeltParams p;
  double from, to, max_amplitude;
  bool both_ends;  // unbounded resonance: the app traces from each end
  // Every stride-th row and every special one are compared (the reference
  // takes ~30 runs of its map per row); STICKSLIP_EVERY_ROW=1: every row.
  int stride;
};

// The app's branch (run_system.cpp, FirstPiece; clock_start.hpp): the state after the transient
// from rest, Newton at m = 1 there, ContinueOrbits on the stroboscopic section
// (testing_util::StrobeBranch) at the app's defaults.
OrbitBranch AppBranch(const Study& s, double from, double to) {
  OrbitBranchOptions o(ForcedBelt::FlowDefaults());
  o.palc.ds_max = 0.02 * std::abs(to - from);
  o.palc.ds = std::min(o.palc.ds, o.palc.ds_max);
  o.max_amplitude = s.max_amplitude;
  ForcedBeltParams at = s.p;
  ParameterAxis(Parameter::kOmega).Set(at, from);
  const ForcedBelt model(at);
  cli::ClockStart c;
  c.rest = ForcedStart(model, 0, 0, model.v()).z;
  c.opts = o;
  const Eigen::VectorXd z = cli::SettledState(model, c);
  return testing_util::StrobeBranch(s.p, Parameter::kOmega, from, to, z[0], z[1], 1, o);
}

template <class Piece>
std::array<Worst, kColumns> Measure(const Study& s) {
  const auto start = std::chrono::steady_clock::now();
  const char* every = std::getenv("STICKSLIP_EVERY_ROW");
  const int stride = every && std::string(every) == "1" ? 1 : s.stride;
  std::array<Worst, kColumns> worst;
  const ref::CurveReference<Piece> reference(s.p);
  int rows = 0, compared = 0, edge_rows = 0;
  for (int end = 0; end < (s.both_ends ? 2 : 1); ++end) {
    const OrbitBranch b = AppBranch(s, end ? s.to : s.from, end ? s.from : s.to);
    EXPECT_GT(b.rows.size(), 20u) << s.name << ": " << b.message;
    for (int i = 0; i < static_cast<int>(b.rows.size()); ++i, ++rows) {
      const OrbitRow& r = b.rows[i];
      if (PeriodMultiple(b) != 1 || (rows % stride != 0 && r.label == SpecialKind::kNone)) continue;
      const ref::CurvePoint c = reference.Near(r);
      // A sliding point at the end of its family (a stick phase lost with a
      // jump of the map) lies there to the shooting's Newton tolerance
      // (1e-12 in the state): 1e-12 beyond the reference's end, whose
      // Newton then finds no orbit of that sequence. At most one per study.
      if (!c.ok && Sliding(r.label) && ++edge_rows <= 1) continue;
      EXPECT_TRUE(c.ok) << s.name << " row " << i << " at Omega = " << r.p;
      if (!c.ok) continue;
      ++compared;
      worst[kP].Add(Rel(r.p, c.omega), rows, r);
      worst[kX0].Add(Rel(r.start.z[0], c.x0), rows, r);
      worst[kXdot0].Add(Rel(r.start.z[1], c.xdot0), rows, r);
      worst[kXmax].Add(Rel(RowExtrema(r).x_max, c.x_max), rows, r);
      worst[kXmin].Add(Rel(RowExtrema(r).x_min, c.x_min), rows, r);
      if (!Sliding(r.label)) worst[kMu].Add(MuError(r, reference, c), rows, r);
    }
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf(
      "[ measured ] %s: %d of %d rows compared, %d edge rows without a reference (%.1f s)\n",
      s.name, compared, rows, edge_rows, seconds);
  for (int k = 0; k < kColumns; ++k)
    std::printf("[ measured ] %s: %-5s worst %.2e at row %d (Omega = %.10g%s%s)\n", s.name,
                kNames[k], worst[k].err, worst[k].row, worst[k].p,
                worst[k].label.empty() ? "" : ", ", worst[k].label.c_str());
  return worst;
}

// The bounds the rows reach against the reference (measured on every row:
// 7.4e-14 in the state and the extremes, 1.9e-13 in the multipliers, the
// reference's own limit there; before each row was polished, 1.15e-11 in x_max
// and 1.1e-10 in the multipliers: docs/validation.md, docs/CHANGELOG.md).
constexpr double kStateBound = 3e-13, kMuBound = 1e-12;

void ExpectWithin(const std::array<Worst, kColumns>& worst, const char* name) {
  for (int k = 0; k < kColumns; ++k)
    EXPECT_LE(worst[k].err, k == kMu ? kMuBound : kStateBound)
        << name << ": " << kNames[k] << " at row " << worst[k].row << ", Omega = " << worst[k].p;
}

TEST(ForcedRowAccuracy, SeedForcedRows) {
  const Study s{"seed_forced", ref::SeedBelt(0.25, 0.3, 1), 1, 0.5, 50, false, 8};
  ExpectWithin(Measure<ref::FixedStepPiece>(s), s.name);
}

TEST(ForcedRowAccuracy, StribeckForcedRows) {
  const Study s{"stribeck_forced", ref::StribeckBelt(0.25, 0.3, 0.8), 0.8, 0.5, 50, false, 10};
  ExpectWithin(Measure<ref::FixedStepPiece>(s), s.name);
}

TEST(ForcedRowAccuracy, DenHartogRows) {
  const Study s{"den_hartog", ref::Coulomb(0.3, 0.3, 0, 0, 1, 0.75), 0.75, 2.5, 20, true, 10};
  ExpectWithin(Measure<ref::CoulombPiece>(s), s.name);
}

TEST(ForcedRowAccuracy, FloorStaticRows) {
  const Study s{"floor_static", ref::Coulomb(0.4, 0.3, 0.05, 0, 0.7, 0.3), 0.3, 2.5, 20, false, 2};
  ExpectWithin(Measure<ref::CoulombPiece>(s), s.name);
}

}  // namespace
}  // namespace stickslip
