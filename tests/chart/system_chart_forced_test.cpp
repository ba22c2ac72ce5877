// The one chart (ChartSystem, system_chart.hpp) on the forced oscillator, a
// system with a clock (studies/seed_forced.ini's (Omega, A) rectangle): its
// LP and PD curves of stroboscopic orbits lie on the forced chart's
// (ForcedChart: its own tracer, 2 x 2 test determinants and section
// rephasing; its curves as committed in docs/figures/seed_forced_chart) to
// that chart's chord accuracy, and at points of its PD curve
// the forced branch in A (ContinueForced, which locates PD by bisection on
// the test's sign along the branch) has its PD at the curve's A.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "../app_test_util.hpp"
#include "stickslip/chart/system_chart.hpp"
#include "stickslip/forced/branch.hpp"
#include "stickslip/model/forced.hpp"

namespace stickslip {
namespace {

ForcedParams SeedForced() {
  ForcedParams p;  // the seed's cubic law, beta 0.05, v 0.25
  p.force = 0.3, p.omega = 0.6;
  return p;
}

const SystemChart& Chart() {
  static const SystemChart chart = [] {
    const ForcedModel s(SeedForced());
    SystemChartOptions o;
    o.plane.p1 = s.ParameterIndex("omega"), o.plane.p2 = s.ParameterIndex("force");
    o.plane.from1 = 0.3, o.plane.to1 = 1.2, o.plane.from2 = 0.05, o.plane.to2 = 0.6;
    o.branch = OrbitBranchOptions(ForcedModel::FlowDefaults());
    return ChartSystem(s, o);
  }();
  return chart;
}

// The distance from (x, y) to the polyline through `points`, in units of
// the rectangle's sides.
template <class Points>
double Distance(const Points& points, double x, double y) {
  double best = HUGE_VAL;
  const double w1 = 0.9, w2 = 0.55;
  for (std::size_t i = 1; i < points.size(); ++i) {
    const double ax = points[i - 1].p1 / w1, ay = points[i - 1].p2 / w2;
    const double dx = points[i].p1 / w1 - ax, dy = points[i].p2 / w2 - ay;
    const double px = x / w1 - ax, py = y / w2 - ay, d2 = dx * dx + dy * dy;
    const double t = d2 > 0 ? std::clamp((px * dx + py * dy) / d2, 0.0, 1.0) : 0.0;
    best = std::min(best, std::hypot(px - t * dx, py - t * dy));
  }
  return best;
}

TEST(SystemChartForced, CurvesLieOnTheForcedChartsCurves) {
  const SystemChart& c = Chart();
  EXPECT_EQ(c.status, ChartStatus::kOk);
  // The forced chart's m = 1 curves of the kind, as polylines.
  const testing_util::Tsv f = testing_util::ReadTsv(
      testing_util::ReadFile(STICKSLIP_SOURCE_DIR "/docs/figures/seed_forced_chart/curves.tsv"));
  struct P {
    double p1, p2;
  };
  std::map<std::string, std::vector<P>> forced;  // "LP 3" -> points
  for (const auto& row : f.rows)
    if (row[f.Column("m")] == "1")
      forced[row[f.Column("curve")] + " " + row[f.Column("id")]].push_back(
          {std::stod(row[0]), std::stod(row[1])});
  int lp = 0, pd = 0;
  for (const SystemCurve& cv : c.curves) {
    ASSERT_TRUE(cv.kind == CurveKind::kFold || cv.kind == CurveKind::kPeriodDoubling);
    (cv.kind == CurveKind::kFold ? lp : pd) += 1;
    std::vector<double> d;
    for (const SystemCurvePoint& p : cv.points) {
      double best = HUGE_VAL;
      for (const auto& [name, points] : forced)
        if (name.rfind(std::string(CurveLabel(cv.kind)) + " ", 0) == 0)
          best = std::min(best, Distance(points, p.p1, p.p2));
      d.push_back(best);
    }
    std::sort(d.begin(), d.end());
    // Most points within the forced polylines' chord error. Near a point
    // where the map stops being smooth each chart ends its curve on its own
    // residual test, a few points apart: there the distance is the gap
    // between the two ends.
    EXPECT_LT(d[d.size() * 3 / 4], 1e-4) << cv.seed;
    EXPECT_LT(d.back(), 1e-2) << cv.seed;
  }
  EXPECT_GE(lp, 3);
  EXPECT_GE(pd, 2);
}

TEST(SystemChartForced, PeriodDoublingCurveMeetsTheForcedBranchesPD) {
  int checked = 0;
  for (const SystemCurve& cv : Chart().curves) {
    if (cv.kind != CurveKind::kPeriodDoubling || cv.points.size() < 20) continue;
    for (const std::size_t i : {cv.points.size() / 4, cv.points.size() / 2}) {
      const SystemCurvePoint& p = cv.points[i];
      ForcedParams q = SeedForced();
      q.omega = p.p1;
      OrbitBranchOptions o(ForcedModel::FlowDefaults());
      o.palc.ds = o.palc.ds_max = 5e-4;
      // From the curve's orbit, as a guess at A 0.002 below (Newton pulls it on).
      const OrbitBranch b = ContinueForced(q, Parameter::kForce, p.p2 - 0.002, p.p2 + 0.002,
                                           p.orbit.start.z[0], p.orbit.start.z[1], 1, o);
      double found = -1;
      for (const OrbitRow& r : b.special)
        if (r.label == SpecialKind::kPeriodDoubling) found = r.p;
      EXPECT_NEAR(found, p.p2, 1e-9) << "omega " << p.p1 << ": " << b.message;
      ++checked;
    }
  }
  EXPECT_GE(checked, 4);  // two points on each of two PD curves at least
}

}  // namespace
}  // namespace stickslip
