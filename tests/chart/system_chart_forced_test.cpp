// The one chart (ChartSystem, system_chart.hpp) on the forced oscillator, a
// system with a clock (studies/seed_forced.ini's (Omega, A) rectangle): its
// LP, PD and GR curves of stroboscopic orbits lie on those the forced chart's
// own tracer drew before it was replaced (2 x 2 test determinants, its own
// rephasing and seeds: tests/chart/data/seed_forced_forced_tracer_curves.tsv)
// to that chart's chord accuracy, and at points of its PD curves the branch
// in A (the one branch driver, which locates PD by bisection on the test's
// sign along the branch) has its PD at the curve's A.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "../app_test_util.hpp"
#include "stickslip/chart/system_chart.hpp"
#include "stickslip/continuation/orbit_branch.hpp"
#include "stickslip/systems/forced/forced.hpp"

namespace stickslip {
namespace {

ForcedBeltParams SeedForced() {
  ForcedBeltParams p;  // the seed's cubic law, beta 0.05, v 0.25
  p.force = 0.3, p.omega = 0.6;
  return p;
}

const SystemChart& Chart() {
  static const SystemChart chart = [] {
    const ForcedBelt s(SeedForced());
    SystemChartOptions o;
    o.plane.p1 = s.ParameterIndex("omega"), o.plane.p2 = s.ParameterIndex("force");
    o.plane.from1 = 0.3, o.plane.to1 = 1.2, o.plane.from2 = 0.05, o.plane.to2 = 0.6;
    o.branch = OrbitBranchOptions(ForcedBelt::FlowDefaults());
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
  EXPECT_EQ(c.status, ChartStatus::kOk) << c.message;
  // The forced chart's curves by kind and period multiple, as polylines.
  const testing_util::Tsv f = testing_util::ReadTsv(testing_util::ReadFile(
      STICKSLIP_SOURCE_DIR "/tests/chart/data/seed_forced_forced_tracer_curves.tsv"));
  struct P {
    double p1, p2;
  };
  std::map<std::string, std::vector<P>> forced;  // "LP 1 3": kind, m, id
  for (const auto& row : f.rows)
    forced[row[f.Column("curve")] + " " + row[f.Column("m")] + " " + row[f.Column("id")]].push_back(
        {std::stod(row[0]), std::stod(row[1])});
  std::map<std::string, int> count;  // "LP 1": curves
  for (const SystemCurve& cv : c.curves) {
    const std::string key =
        std::string(CurveLabel(cv.kind)) + " " + std::to_string(cv.section.turns) + " ";
    ++count[key];
    std::vector<double> d;
    for (const SystemCurvePoint& p : cv.points) {
      double best = HUGE_VAL;
      for (const auto& [name, points] : forced)
        if (name.rfind(key, 0) == 0) best = std::min(best, Distance(points, p.p1, p.p2));
      d.push_back(best);
    }
    std::sort(d.begin(), d.end());
    // Most points within the forced polylines' chord error. Near a point
    // where the map stops being smooth each chart ends its curve on its own
    // test, a few points apart; two doubled PD curves go on past the forced
    // chart's ends (branch jumps there), one round a turn: there the distance
    // is the gap between the two ends.
    EXPECT_LT(d[d.size() / 4], 1e-4) << cv.seed;
    if (cv.section.turns == 1) {
      EXPECT_LT(d[d.size() / 2], 1e-4) << cv.seed;
    }
  }
  // As many curves of each kind and m as the forced chart has.
  EXPECT_EQ(count["LP 1 "], 4);
  EXPECT_EQ(count["PD 1 "], 3);
  EXPECT_EQ(count["GR 1 "], 3);
  EXPECT_EQ(count["PD 2 "], 6);
  EXPECT_EQ(count["LP 2 "], 2);
}

// At points of every PD curve of 20 points or more (period multiple m = 1 or
// a doubled m = 2), the branch in A from 5e-4 below (the one branch driver,
// which locates PD by bisection on the test's sign along the branch) has its
// PD at the curve's A.
TEST(SystemChartForced, PeriodDoublingCurveMeetsTheForcedBranchesPD) {
  int checked = 0, doubled = 0;
  for (const SystemCurve& cv : Chart().curves) {
    if (cv.kind != CurveKind::kPeriodDoubling || cv.points.size() < 20) continue;
    for (const std::size_t i : {cv.points.size() / 4, cv.points.size() / 2}) {
      const SystemCurvePoint& p = cv.points[i];
      ForcedBeltParams q = SeedForced();
      q.omega = p.p1, q.force = p.p2 - 5e-4;
      const ForcedBelt s(q);
      OrbitBranchOptions o(ForcedBelt::FlowDefaults());
      o.palc.ds = o.palc.ds_max = 1e-4;
      // From the curve's orbit (its section phase and m), as a guess 5e-4
      // below in A (Newton pulls it on).
      const OrbitBranch b =
          ContinueOrbits(s, ForcedBelt::kForceIndex, p.orbit.start, cv.section, p.p2 + 5e-4, o);
      double found = -1;
      for (const OrbitRow& r : b.special)
        if (r.label == SpecialKind::kPeriodDoubling) found = r.p;
      EXPECT_NEAR(found, p.p2, 1e-9)
          << "omega " << p.p1 << ", m " << cv.section.turns << ": " << b.message;
      ++checked;
      doubled += cv.section.turns == 2;
    }
  }
  EXPECT_GE(checked, 8);
  EXPECT_GE(doubled, 4);  // two points on each of two doubled PD curves at least
}

}  // namespace
}  // namespace stickslip
