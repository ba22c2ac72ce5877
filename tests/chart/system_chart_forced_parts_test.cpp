// The one chart (ChartSystem, TraceOrbitCurve; system_chart.hpp) on the
// forced oscillator, against references computed another way:
//  - a GR curve (the arrival's margin |lambda| - mu_s at a crossing) of Den
//    Hartog's (1931) non-stop orbit against his closed-form stop condition;
//  - the R1 points where studies/forced_ns_seed.ini's NS curves end (the
//    pair turns real at +1), and the R2 points of the Stribeck belt at v =
//    0.41, each on a PD and an NS curve: refined on the curve, and at each
//    the long-double reference map (reference/forced_lyapunov.hpp, RKF78 with
//    its own variational equations) has the orbit as a fixed point with
//    tr Phi = 2 (-2) and det Phi = 1;
//  - the GR gap curve and the NS curves of forced_ns_seed.ini against
//    one-parameter runs in Omega, which locate GR and NS by their own
//    bisection.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "forced_reference.hpp"
#include "forced_run.hpp"
#include "reference/forced_lyapunov.hpp"
#include "stickslip/chart/system_chart.hpp"
#include "stickslip/orbits/forced_orbit.hpp"

namespace stickslip {
namespace {

using reference::LReal;

// Den Hartog (1931), v = 0, beta = 0, mu_s = mu_k = mu: the non-stop orbit
// stops where A = mu |1 - W^2| sqrt(U^2 + W^-4), U = sin(pi/W) / (W (1 +
// cos(pi/W))) (tests/chart/forced_chart_test.cpp derives it).
double DenHartogStopForce(double mu, double w) {
  const double U = std::sin(M_PI / w) / (w * (1 + std::cos(M_PI / w)));
  return mu * std::abs(1 - w * w) * std::sqrt(U * U + 1 / (w * w * w * w));
}

SystemChartOptions Options(const System& s, double from1, double to1, double from2, double to2) {
  SystemChartOptions o;
  o.plane.p1 = s.ParameterIndex("omega"), o.plane.p2 = s.ParameterIndex("force");
  o.plane.from1 = from1, o.plane.to1 = to1, o.plane.from2 = from2, o.plane.to2 = to2;
  o.branch = OrbitBranchOptions(ForcedBelt::FlowDefaults());
  return o;
}

TEST(SystemChartForcedParts, DenHartogGrazingCurveIsHisStopCondition) {
  const double mu = 0.3;
  for (const double w : {0.7, 1.5}) {  // one curve below and one above resonance
    // The non-stop orbit a little above the boundary, then the curve from it.
    const double a = DenHartogStopForce(mu, w) * 1.02;
    const ForcedBelt model(forced_reference::Coulomb(mu, mu, 0, 0, a, w));
    SystemChartOptions o = Options(model, w < 1 ? 0.6 : 1.2, w < 1 ? 0.9 : 2.0, 0.05, 1.5);
    o.branch.shooting.flow.rtol = o.branch.shooting.flow.atol = 1e-13;
    o.max_step = 0.02;
    const PeriodicOrbit orbit =
        ShootStroboscopic(model, a / (1 - w * w), 0.01, 1, o.branch.shooting);
    ASSERT_TRUE(orbit.ok()) << orbit.message;
    ASSERT_EQ(orbit.sticks, 0);
    const SystemCurve c =
        TraceOrbitCurve(model, o, CurveKind::kGrazing, orbit.start, w, a,
                        PoincareSection::Stroboscopic(model, orbit.start.z, 1), 1);
    EXPECT_FALSE(c.gap);  // the arrival's margin: the orbit crosses x' = v
    ASSERT_GT(c.points.size(), 10u) << c.ends.Text();
    EXPECT_EQ(c.ends.first.kind, CurveEndKind::kBorder) << c.ends.Text();
    EXPECT_EQ(c.ends.last.kind, CurveEndKind::kBorder) << c.ends.Text();
    double worst = 0;
    for (const SystemCurvePoint& p : c.points) {
      const double ref = DenHartogStopForce(mu, p.p1);
      EXPECT_NEAR(p.p2, ref, 1e-8 * std::max(1.0, ref)) << "Omega = " << p.p1;
      worst = std::max(worst, std::abs(p.p2 - ref));
    }
    std::printf(
        "[ measured ] GR curve Omega in [%g, %g]: %zu points, max |A - A_DenHartog| = "
        "%.2e, ends %s\n",
        c.points.front().p1, c.points.back().p1, c.points.size(), worst, c.ends.Text().c_str());
  }
}

// The reference map over one period from phase 0 at a codim-2 point's orbit
// (carried from its section phase to phase 0 by the library's flow: a start
// only; the reference's own fixed-point residual is asserted).
struct RefCheck {
  LReal residual, trace, det;
  int sticks;
};
RefCheck Reference(const ForcedBeltParams& base, const SystemCodim2& x) {
  ForcedBeltParams p = base;
  p.omega = x.p1, p.force = x.p2;
  const ForcedBelt model(p);
  FlowOptions f = ForcedBelt::FlowDefaults();
  f.rtol = f.atol = 1e-14;
  const FlowPoint& z = x.orbit.start;
  const FlowRun to0 =
      testing_util::RunForced(model, z, z.t + (2 * M_PI - z.z[2]) / model.omega(), {}, f);
  EXPECT_TRUE(to0.ok()) << to0.message;
  const reference::ForcedRef m(p);
  const reference::RefPeriod q =
      reference::RefOnePeriod(m, to0.end.z[0], to0.end.z[1], false, 1e-18L);
  EXPECT_TRUE(q.ok);
  return {std::max(std::abs(q.x - to0.end.z[0]), std::abs(q.y - to0.end.z[1])),
          q.phi[0][0] + q.phi[1][1], q.phi[0][0] * q.phi[1][1] - q.phi[0][1] * q.phi[1][0],
          q.sticks};
}

TEST(SystemChartForcedParts, R1WhereTheNsCurvesEndHasBothMultipliersAtPlusOne) {
  const ForcedBeltParams base = forced_reference::SeedBelt(0.42, 0.05, 1.3);
  const ForcedBelt s(base);
  const SystemChart c = ChartSystem(s, Options(s, 0.6, 1.6, 0.002, 0.1));  // the study's [chart]
  int n = 0;
  for (const SystemCodim2& x : c.codim2) {
    if (x.label != Codim2Label::kR1) continue;
    ++n;
    EXPECT_EQ(x.on, CurveKind::kTorus);
    ASSERT_EQ(x.method, Codim2Method::kRefined);
    const RefCheck ref = Reference(base, x);
    std::printf(
        "[ measured ] R1 at Omega %.12f A %.12f: reference residual %.2Le, tr - 2 = "
        "%.2Le, det - 1 = %.2Le\n",
        x.p1, x.p2, ref.residual, ref.trace - 2, ref.det - 1);
    EXPECT_EQ(ref.sticks, 0);
    EXPECT_LT(ref.residual, 1e-10L);
    EXPECT_LT(std::abs(ref.trace - 2), 1e-12L);
    EXPECT_LT(std::abs(ref.det - 1), 1e-12L);
  }
  EXPECT_EQ(n, 2);  // one where each NS curve of the 1:1 tongue ends
}

// R2 (both multipliers at -1) on the Stribeck belt at v = 0.41 near Omega = 2
// (docs/studies.md): located on the PD curve (the NS test's zero with two
// multipliers at -1) and on the NS curve (the PD test's zero), two different
// defining systems that must give one point, which the reference map has as
// a fixed point with tr Phi = -2 and det Phi = 1.
TEST(SystemChartForcedParts, R2OnPdAndNsCurvesIsOnePointWithBothMultipliersAtMinusOne) {
  const ForcedBeltParams base = forced_reference::StribeckBelt(0.41, 0.05, 1);
  const ForcedBelt s(base);
  const SystemChart c = ChartSystem(s, Options(s, 0.6, 2.4, 0.002, 0.16));
  std::vector<const SystemCodim2*> pd, ns;
  for (const SystemCodim2& x : c.codim2)
    if (x.label == Codim2Label::kR2) {
      EXPECT_EQ(x.method, Codim2Method::kRefined);
      (x.on == CurveKind::kPeriodDoubling ? pd : ns).push_back(&x);
    }
  // Both R2 on the NS curve; the PD curve of the 1:2 tongue ends at the
  // tongue's tip (branch-jump), so only the left one also on it.
  ASSERT_EQ(ns.size(), 2u);
  ASSERT_GE(pd.size(), 1u);
  for (const SystemCodim2* a : pd) {
    double best = INFINITY;
    for (const SystemCodim2* b : ns)
      best = std::min(best, std::max(std::abs(a->p1 - b->p1), std::abs(a->p2 - b->p2)));
    std::printf("[ measured ] R2 at Omega %.12f A %.12f on PD: the NS curve's R2 %.2e away\n",
                a->p1, a->p2, best);
    EXPECT_LT(best, 1e-10);
  }
  for (const std::vector<const SystemCodim2*>* on : {&pd, &ns})
    for (const SystemCodim2* a : *on) {
      const RefCheck ref = Reference(base, *a);
      std::printf(
          "[ measured ] R2 at Omega %.12f A %.12f on %s: reference residual %.2Le, "
          "tr + 2 = %.2Le, det - 1 = %.2Le\n",
          a->p1, a->p2, CurveLabel(a->on), ref.residual, ref.trace + 2, ref.det - 1);
      EXPECT_EQ(ref.sticks, 0);
      EXPECT_LT(ref.residual, 1e-10L);
      EXPECT_LT(std::abs(ref.trace + 2), 1e-12L);
      EXPECT_LT(std::abs(ref.det - 1), 1e-12L);
    }
}

// The Omega of the `label` point nearest p.p1 that a one-parameter run in
// Omega at p's force, through p's orbit over p.p1 +- 2e-3 (either way first),
// locates; NaN if none.
double RunPointNear(const ForcedBeltParams& base, const SystemCurvePoint& p,
                    const PoincareSection& section, SpecialKind label) {
  ForcedBeltParams q = base;
  q.force = p.p2;
  OrbitBranchOptions o(ForcedBelt::FlowDefaults());
  o.palc.ds = o.palc.ds_max = 2e-4;
  double best = NAN;
  for (const double side : {1.0, -1.0}) {
    q.omega = p.p1 + side * 2e-3;
    const OrbitBranch b = ContinueOrbits(ForcedBelt(q), ForcedBelt::kOmegaIndex, p.orbit.start,
                                         section, p.p1 - side * 2e-3, o);
    for (const OrbitRow& r : b.special)
      if (r.label == label && !(std::abs(best - p.p1) <= std::abs(r.p - p.p1))) best = r.p;
    if (!std::isnan(best)) break;
  }
  return best;
}

// The GR curve of the pure-slip orbits on studies/forced_ns_seed.ini (the gap
// margin, on the slip field without switching): it crosses the rectangle, and
// at points across it a one-parameter run in Omega through the point's orbit
// (the one branch driver, its own bisection of the switching sequence's
// change) locates its GR at the curve's Omega.
TEST(SystemChartForcedParts, GapGrazingCurveMatchesOneParameterRuns) {
  const ForcedBeltParams base = forced_reference::SeedBelt(0.42, 0.05, 1.3);
  const ForcedBelt s(base);
  const SystemChart c = ChartSystem(s, Options(s, 0.6, 1.6, 0.002, 0.1));
  const SystemCurve* gr = nullptr;
  for (const SystemCurve& cv : c.curves)
    if (cv.kind == CurveKind::kGrazing) gr = &cv;
  ASSERT_NE(gr, nullptr);
  EXPECT_TRUE(gr->gap);
  EXPECT_GT(gr->points.size(), 100u);
  EXPECT_EQ(gr->ends.first.kind, CurveEndKind::kBorder);
  EXPECT_EQ(gr->ends.last.kind, CurveEndKind::kBorder);
  int checked = 0;
  for (std::size_t i = 10; i < gr->points.size(); i += gr->points.size() / 6) {
    const SystemCurvePoint& p = gr->points[i];
    const double best = RunPointNear(base, p, gr->section, SpecialKind::kGrazing);
    std::printf("[ measured ] GR curve point Omega %.12f A %.6f: the run's GR %.2e away\n", p.p1,
                p.p2, best - p.p1);
    EXPECT_LT(std::abs(best - p.p1), 1e-10) << "A = " << p.p2;
    ++checked;
  }
  EXPECT_GE(checked, 5);
}

// The NS curves bounding the 1:1 tongue of studies/forced_ns_seed.ini: at
// every 12th point (A >= 0.01, both curves) a one-parameter run in Omega
// through the point's orbit (its own start, branch and bisection of the NS
// test, independent of the tracer) locates its NS at the point's Omega.
TEST(SystemChartForcedParts, NsCurvePointsMatchOneParameterRunsInOmega) {
  const ForcedBeltParams base = forced_reference::SeedBelt(0.42, 0.05, 1.3);
  const ForcedBelt s(base);
  const SystemChart c = ChartSystem(s, Options(s, 0.6, 1.6, 0.002, 0.1));
  int checked = 0;
  for (const SystemCurve& cv : c.curves) {
    if (cv.kind != CurveKind::kTorus) continue;
    EXPECT_GT(cv.points.size(), 50u) << cv.ends.Text();
    for (std::size_t i = 0; i < cv.points.size(); i += 12) {
      const SystemCurvePoint& p = cv.points[i];
      if (p.p2 < 0.01) continue;  // near the tongue's tip
      const double best = RunPointNear(base, p, cv.section, SpecialKind::kTorus);
      std::printf("[ measured ] NS curve point Omega %.12f at force %.6f: run %.12f (%.1e)\n", p.p1,
                  p.p2, best, std::abs(p.p1 - best));
      EXPECT_NEAR(p.p1, best, 1e-9) << "force " << p.p2;
      ++checked;
    }
  }
  EXPECT_GE(checked, 6);
}

}  // namespace
}  // namespace stickslip
