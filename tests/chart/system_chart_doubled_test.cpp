// The one chart (ChartSystem, system_chart.hpp) follows period-doubled
// branches (ContinueDoubled, AUTO-07p's ISW = -1 at a PD label) for its seeds:
// on the Stribeck cascade scene (studies/stribeck_forced.ini) it draws the
// curves where the m = 2 orbits double again, and with max_m = 4 the next
// step. Each curve point checked is compared with a chain of one-parameter
// runs at that point's force, started from rest and independent of the
// two-parameter tracer: the m = 1 branch in Omega, switched at its PD onto
// the doubled branch, whose own PD is located by the branch's bisection.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "forced_reference.hpp"
#include "forced_trace.hpp"
#include "stickslip/chart/system_chart.hpp"
#include "stickslip/continuation/orbit_branch.hpp"
#include "stickslip/orbits/shooting.hpp"

namespace stickslip {
namespace system_doubled {

ForcedBeltParams Stribeck(double a, double w) { return forced_reference::StribeckBelt(0.25, a, w); }

// The Omegas of the PD points of the period-`target` orbits at force a.
void CollectPds(double a, const OrbitBranch& b, int m, int target, OrbitBranchOptions o,
                std::vector<double>* pds) {
  for (const OrbitRow& r : b.special) {
    if (r.label != SpecialKind::kPeriodDoubling || PeriodMultiple(b) != m) continue;
    if (m == target) {
      pds->push_back(r.p);
      continue;
    }
    const ForcedBelt at(Stribeck(a, r.p));
    const FlowPoint pd = testing_util::StrobePoint(r.start.z[0], r.start.z[1]);
    const OrbitBranch d = ContinueDoubled(at, ParameterAxis(Parameter::kOmega).index(), pd,
                                          PoincareSection::Stroboscopic(at, pd.z, m), 0.5, 0.8, o);
    CollectPds(a, d, 2 * m, target, o, pds);
  }
}

std::vector<double> DoubledPds(double a, int m) {
  OrbitBranchOptions o(ForcedBelt::FlowDefaults());
  o.palc.ds = o.palc.ds_max = 0.01;
  const OrbitBranch b = testing_util::TraceOmega(Stribeck(a, 0.8), 0.8, 0.5, o);
  std::vector<double> pds;
  CollectPds(a, b, 1, m, o, &pds);
  return pds;
}

// The scene's curves, seeded on the lines force 0.325 and Omega 0.85.
SystemChart CascadeChart(int max_m) {
  const ForcedBelt s(Stribeck(0.3, 0.6));
  SystemChartOptions o;
  o.plane.p1 = s.ParameterIndex("omega"), o.plane.p2 = s.ParameterIndex("force");
  o.plane.from1 = 0.5, o.plane.to1 = 1.2, o.plane.from2 = 0.05, o.plane.to2 = 0.6;
  o.branch = OrbitBranchOptions(ForcedBelt::FlowDefaults());
  o.seed_lines = 1;
  o.max_m = max_m;
  return ChartSystem(s, o);
}

// The nearest PD of the chain of runs at the point's force, to its Omega.
double NearestRunPd(const SystemCurvePoint& p, int m) {
  double best = NAN;
  for (const double w : DoubledPds(p.p2, m))
    if (!(std::abs(best - p.p1) <= std::abs(w - p.p1))) best = w;
  return best;
}

TEST(SystemChartDoubled, SecondDoublingCurveMatchesOneParameterRuns) {
  const SystemChart r = CascadeChart(2);
  ASSERT_EQ(r.status, ChartStatus::kOk) << r.message;
  int curves = 0, checked = 0;
  for (const SystemCurve& c : r.curves) {
    if (c.kind != CurveKind::kPeriodDoubling || c.section.turns != 2) continue;
    ++curves;
    for (const double level : {0.3, 0.4}) {  // 2 points a curve
      const SystemCurvePoint* p = nullptr;   // nearest inner point (an end may be a kink)
      for (std::size_t i = 1; i + 1 < c.points.size(); ++i)
        if (!p || std::abs(c.points[i].p2 - level) < std::abs(p->p2 - level)) p = &c.points[i];
      if (!p || std::abs(p->p2 - level) > 0.01) continue;
      const double best = NearestRunPd(*p, 2);
      std::printf("[ measured ] m = 2 PD curve at force %.10f: Omega %.12f, runs %.12f (%.1e)\n",
                  p->p2, p->p1, best, std::abs(best - p->p1));
      EXPECT_NEAR(p->p1, best, 1e-11) << "force " << p->p2 << ", seed " << c.seed;
      ++checked;
    }
  }
  EXPECT_GE(curves, 2);
  EXPECT_GE(checked, 4);
}

// The multiplier of the period-m orbit at a curve point nearest -1, by a
// fresh shooting of its stroboscopic map at the point (no continuation, no
// test function).
double NearestToMinusOne(const SystemCurvePoint& p, int m) {
  const ForcedBelt model(Stribeck(p.p2, p.p1));
  ShootingOptions o;
  o.flow.rtol = o.flow.atol = 1e-13;
  Shooting shooting(model, o);
  const PeriodicOrbit orbit =
      shooting.Find(p.orbit.start, PoincareSection::Stroboscopic(model, p.orbit.start.z, m));
  EXPECT_TRUE(orbit.ok()) << orbit.message;
  double best = INFINITY;
  for (const auto& mu : orbit.multipliers) best = std::min(best, std::abs(mu + 1.0));
  return best;
}

// With max_m = 4 the m = 4 orbits' PD curves are drawn too. Where the chain
// of runs finds the PD at the point's force it is there; where it does not (a
// branch of the chain ends or closes before it), the point's orbit has a
// multiplier at -1.
TEST(SystemChartDoubled, ThirdDoublingCurveMatchesOneParameterRuns) {
  const SystemChart r = CascadeChart(4);
  ASSERT_EQ(r.status, ChartStatus::kOk) << r.message;
  int curves = 0, matched = 0;
  for (const SystemCurve& c : r.curves) {
    if (c.kind != CurveKind::kPeriodDoubling || c.section.turns != 4) continue;
    ++curves;
    const SystemCurvePoint& p = c.points[c.points.size() / 2];  // an inner point
    const double best = NearestRunPd(p, 4), mu = NearestToMinusOne(p, 4);
    std::printf(
        "[ measured ] m = 4 PD curve at force %.10f: Omega %.12f, runs %.12f (%.1e), "
        "|mu + 1| %.1e\n",
        p.p2, p.p1, best, std::abs(best - p.p1), mu);
    EXPECT_LE(mu, 1e-9) << "force " << p.p2 << ", seed " << c.seed;
    if (!(std::abs(best - p.p1) < 1e-6)) continue;
    EXPECT_NEAR(p.p1, best, 1e-11) << "force " << p.p2 << ", seed " << c.seed;
    ++matched;
  }
  EXPECT_GE(curves, 2);
  EXPECT_GE(matched, 2);
}

}  // namespace system_doubled
}  // namespace stickslip
