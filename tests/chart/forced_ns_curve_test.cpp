// The forced chart's Neimark-Sacker curves (issue 21 item 3: "curve points
// against one-parameter runs") on studies/forced_ns_seed.ini: the seed belt
// at v = 0.42, below its (supercritical) Hopf point, forced. The 1:1 locking
// tongue of the pure-slip response is bounded by an NS curve. A curve point's
// NS is located again by ContinueForced in Omega at that point's force (its
// own start, branch and bisection of |mu| - 1: independent of the tracer).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "forced_reference.hpp"
#include "forced_run.hpp"
#include "forced_trace.hpp"
#include "stickslip/chart/forced_chart.hpp"
#include "stickslip/forced/branch.hpp"

namespace stickslip {

namespace {

ForcedParams Scene(double a, double w) { return forced_reference::SeedBelt(0.42, a, w); }

// The study's chart: Omega 0.6..1.6, A 0.002..0.1.
ForcedChartOptions NsChartOptions() {
  ForcedChartOptions o;
  o.plane.from1 = 0.6, o.plane.to1 = 1.6, o.plane.from2 = 0.002, o.plane.to2 = 0.1;
  return o;
}

// The NS row of the run in Omega at force a nearest p.p1, from the curve
// point's orbit carried to phase 0, over Omega +- 2e-3 both ways. p NaN if none.
OrbitRow LocateNsRow(const ForcedCurvePoint& p, double a) {
  const ForcedModel model(Scene(a, p.p1));
  // (the phase lies in [0, 2 pi): one period reaches phase 0)
  const FlowPoint z =
      (testing_util::RunForced(model, ForcedStart(model, p.phase / model.omega(), p.x0, p.xdot0),
                               model.period())
           .end);
  OrbitBranchOptions o(ForcedModel::FlowDefaults());
  o.palc.ds = o.palc.ds_max = 2e-4;
  OrbitRow best;
  best.p = NAN;
  for (const double side : {1.0, -1.0}) {
    const OrbitBranch b = ContinueForced(Scene(a, p.p1), Parameter::kOmega, p.p1 + side * 2e-3,
                                         p.p1 - side * 2e-3, z.z[0], z.z[1], 1, o);
    for (const OrbitRow& r : b.special)
      if (r.label == SpecialKind::kTorus && !(std::abs(best.p - p.p1) <= std::abs(r.p - p.p1)))
        best = r;
    if (!std::isnan(best.p)) return best;
  }
  return best;
}

double LocateNs(const ForcedCurvePoint& p) { return LocateNsRow(p, p.p2).p; }

// The study's NS curve, traced from the NS of the run in Omega at A = 0.05 on
// the tongue's right side (once for all tests).
const ForcedCurve& StudyCurve() {
  static const ForcedCurve curve = [] {
    const ForcedParams p = Scene(0.05, 1.3);
    OrbitBranchOptions bo(ForcedModel::FlowDefaults());
    bo.palc.ds = bo.palc.ds_max = 0.01;
    const OrbitBranch run = testing_util::TraceOmega(p, 1.3, 1.05, bo);
    EXPECT_FALSE(run.special.empty()) << run.message;
    if (run.special.empty() || run.special[0].label != SpecialKind::kTorus) return ForcedCurve();
    const OrbitRow& s = run.special[0];
    std::string why;
    return TraceForcedCurve(Scene(0.05, s.p), NsChartOptions(), CurveKind::kTorus, 1, s.start.z[0],
                            s.start.z[1], s.p, 0.05, &why);
  }();
  return curve;
}

TEST(ForcedNsCurve, PointsMatchOneParameterRunsInOmega) {
  const ForcedCurve& c = StudyCurve();
  EXPECT_GT(c.points.size(), 50u) << c.ends.Text();
  int checked = 0;
  for (const ForcedCurvePoint& q : c.points) {
    if (q.flag || q.p2 < 0.01) continue;  // real multipliers near the tongue's tip
    // Every 12th point (both sides of the tongue, A from 0.01 to 0.1).
    if ((&q - c.points.data()) % 12 != 0) continue;
    const double w = LocateNs(q);
    std::printf("[ measured ] NS curve point Omega %.12f at force %.6f: run %.12f (%.1e)\n", q.p1,
                q.p2, w, std::abs(q.p1 - w));
    // Both solve det(DP) = 1: the curve's corrector to 1e-10 (ForcedCurveCorrector
    // at rtol 1e-11), the run's bisection of |mu| - 1 to its own tolerance; the
    // test function's slope in Omega is O(1). Measured <= 6.4e-13.
    EXPECT_NEAR(q.p1, w, 1e-9) << "force " << q.p2;
    ++checked;
  }
  EXPECT_GE(checked, 6);
}

}  // namespace
}  // namespace stickslip
