// The forced chart: a PD curve point (the one chart's, TraceOrbitCurve on
// ss_chart's forced settings) against a one-parameter run located at that
// curve point's second parameter, and the response grid's cells against the
// orbits FindOrbits finds there.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "forced_reference.hpp"
#include "forced_run.hpp"
#include "forced_trace.hpp"
#include "stickslip/chart/response_grid.hpp"
#include "stickslip/chart/system_chart.hpp"
#include "stickslip/orbits/forced_orbit.hpp"
#include "stickslip/orbits/orbit_search.hpp"

namespace stickslip {
namespace {

// The forced tools' chart settings (ss_chart's forced run) on the rectangle,
// at rtol = atol = 1e-13.
SystemChartOptions Options(ParameterAxis a1, double from1, double to1, ParameterAxis a2,
                           double from2, double to2) {
  SystemChartOptions o;
  o.plane.p1 = a1.index(), o.plane.p2 = a2.index();
  o.plane.from1 = from1, o.plane.to1 = to1, o.plane.from2 = from2, o.plane.to2 = to2;
  FlowOptions flow = ForcedBelt::FlowDefaults();
  flow.rtol = flow.atol = 1e-13;
  o.branch = OrbitBranchOptions(flow);
  o.branch.max_amplitude = 50;
  o.max_step = 0.02;
  return o;
}

// The stribeck_forced study's scene (studies/stribeck_forced.ini).
ForcedBeltParams StribeckChartParams(double a, double w) {
  return forced_reference::StribeckBelt(0.25, a, w);
}

// The m = 1 branch in Omega from 0.8 down at force a, from a settled state.
OrbitBranch OmegaRun(double a) {
  const ForcedBelt model(StribeckChartParams(a, 0.8));
  const FlowRun tr =
      testing_util::RunForced(model, ForcedStart(model, 0, 0, 0.25), 200 * model.period());
  OrbitBranchOptions o(ForcedBelt::FlowDefaults());
  o.shooting.flow.rtol = o.shooting.flow.atol = 1e-13;
  o.palc.ds = o.palc.ds_max = 0.006;
  return testing_util::StrobeBranch(StribeckChartParams(a, 0.8), Parameter::kOmega, 0.8, 0.5,
                                    tr.end.z[0], tr.end.z[1], 1, o);
}

const OrbitRow* First(const OrbitBranch& b, SpecialKind l) {
  for (const OrbitRow& r : b.special)
    if (r.label == l) return &r;
  return nullptr;
}

// A PD curve point at a force other than its seed's, against a one-parameter
// run in Omega at exactly that force (its own start, branch and bisection).
TEST(ForcedChart, PeriodDoublingCurvePointMatchesOneParameterRun) {
  const OrbitBranch seed_run = OmegaRun(0.3);
  const OrbitRow* pd = First(seed_run, SpecialKind::kPeriodDoubling);
  ASSERT_NE(pd, nullptr) << Name(seed_run.status);
  const SystemChartOptions o = Options(Parameter::kOmega, 0.5, 0.8, Parameter::kForce, 0.25, 0.35);
  const ForcedBelt model(StribeckChartParams(0.3, pd->p));
  const SystemCurve c = TraceOrbitCurve(model, o, CurveKind::kPeriodDoubling, pd->start, pd->p, 0.3,
                                        seed_run.section, 1);
  ASSERT_GT(c.points.size(), 5u) << c.ends.Text();
  int checked = 0;
  for (const double target : {0.27, 0.33}) {
    const SystemCurvePoint* best = &c.points[0];
    for (const SystemCurvePoint& p : c.points)
      if (std::abs(p.p2 - target) < std::abs(best->p2 - target)) best = &p;
    if (std::abs(best->p2 - target) > 0.01) continue;  // the curve ends before
    const OrbitBranch run = OmegaRun(best->p2);
    const OrbitRow* located = First(run, SpecialKind::kPeriodDoubling);
    ASSERT_NE(located, nullptr) << "force = " << best->p2;
    EXPECT_NEAR(best->p1, located->p, 1e-8) << "force = " << best->p2;
    std::printf(
        "[ measured ] PD curve at force %.10f: Omega %.12f, one-parameter run %.12f "
        "(difference %.1e)\n",
        best->p2, best->p1, located->p, std::abs(best->p1 - located->p));
    ++checked;
  }
  EXPECT_GE(checked, 1) << c.ends.Text();
}

// Response cells against FindOrbits at the cell centre: a periodic cell
// (m <= 4) has a stable orbit of that m and stick count there; a chaotic
// cell has no stable orbit of m <= 4.
TEST(ForcedChart, ResponseCellsAgreeWithTheOrbitsFoundThere) {
  const SystemChartOptions o = Options(Parameter::kOmega, 0.56, 1.0, Parameter::kForce, 0.1, 0.5);
  ResponseOptions ro;  // ss_chart's forced run's, at 1e-12
  ro.n1 = 8, ro.n2 = 5;
  ro.attractor.iterate.flow = ForcedBelt::FlowDefaults();
  const FlowOptions& flow = ro.attractor.iterate.flow;
  const ForcedBelt base(StribeckChartParams(0.3, 0.8));
  const ResponseGrid g = Responses(base, o.plane, ro);
  int periodic = 0, chaotic = 0;
  for (int j = 0; j < g.n2; ++j)
    for (int i = 0; i < g.n1; ++i) {
      const Attractor& a = g.at(i, j);
      const bool check =
          (a.kind == AttractorKind::kPeriodic && a.m <= 4) || a.kind == AttractorKind::kChaotic;
      if (!check) continue;
      const ForcedBelt model(StribeckChartParams(g.x2[j], g.x1[i]));
      OrbitSearchOptions so;
      so.orbit = ShootingOptions(flow);
      so.max_m = 4, so.max_sticks = 6;
      so.half_width = model.SearchBox();
      const FoundOrbits f = FindOrbits(model, so);
      bool match = false, any_stable = false;
      for (const FoundOrbit& s : f.orbits) {
        any_stable = any_stable || s.orbit.stable;
        match = match || (s.orbit.stable && s.m == a.m && s.orbit.sticks == a.sticks);
      }
      if (a.kind == AttractorKind::kPeriodic) {
        EXPECT_TRUE(match) << "Omega = " << g.x1[i] << ", force = " << g.x2[j] << ": m = " << a.m
                           << ", " << a.sticks << " sticks";
        ++periodic;
      } else {
        EXPECT_FALSE(any_stable) << "chaotic cell Omega = " << g.x1[i] << ", force = " << g.x2[j];
        ++chaotic;
      }
    }
  std::printf("[ measured ] %d periodic and %d chaotic cells of %d x %d checked\n", periodic,
              chaotic, g.n1, g.n2);
  EXPECT_GT(periodic, 10);
}

}  // namespace
}  // namespace stickslip
