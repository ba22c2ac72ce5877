// Codimension-two points of the forced chart (issue 21 item 3), refined on
// the curves (src/chart/forced_codim2.cpp), against independent computations:
//  - R2 (both multipliers -1) on the Stribeck belt at v = 0.41 near Omega = 2
//    (docs/studies.md): located once on the PD curve (det DP = 1 along
//    det(DP + I) = 0) and once on the NS curve (tr DP = -2 along det DP = 1),
//    two different defining systems that must give one point; and at it the
//    long-double reference map (reference/forced_lyapunov.hpp, RKF78 with its
//    own variational equations) has the orbit as a fixed point with
//    tr Phi = -2 and det Phi = 1.
//  - R1 (both +1) at the tip of the 1:1 tongue of studies/forced_ns_seed.ini:
//    the reference map there has tr Phi = 2 and det Phi = 1.
// The chord's interpolation (the code before) put the two R2 points 3.3e-4
// apart in Omega, and the R1 points 5.5e-6 off in Omega (|tr - 2| ~ 1e-5).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "forced_reference.hpp"
#include "forced_run.hpp"
#include "reference/forced_lyapunov.hpp"
#include "stickslip/chart/forced_chart.hpp"
#include "stickslip/forced/branch.hpp"

namespace stickslip {
namespace {

using reference::LReal;

ForcedParams Stribeck041() { return forced_reference::StribeckBelt(0.41, 0, 1); }

// studies/forced_ns_seed.ini
ForcedParams SeedBelt042() { return forced_reference::SeedBelt(0.42, 0, 1); }

ForcedChartResult Chart(const ForcedParams& base, double w0, double w1, double a0, double a1) {
  ForcedChartOptions o;
  o.plane.from1 = w0, o.plane.to1 = w1, o.plane.from2 = a0, o.plane.to2 = a1;
  o.n1 = o.n2 = 0;
  return ForcedChart(base, o);
}

// The reference map over one period from phase 0 at the codim-2 point's orbit
// (carried from its section phase to phase 0 by the library's flow: a start
// only; the reference's own fixed-point residual is asserted).
struct RefCheck {
  LReal residual, trace, det;
  int sticks;
};
RefCheck Reference(const ForcedParams& base, const ForcedCodim2& c) {
  ForcedParams p = base;
  p.omega = c.p1, p.force = c.p2;
  const ForcedModel model(p);
  FlowOptions f = ForcedModel::FlowDefaults();
  f.rtol = f.atol = 1e-14;
  const FlowPoint r =
      (testing_util::RunForced(model, ForcedStart(model, c.phase / model.omega(), c.x0, c.xdot0),
                               model.period(), {}, f)
           .end);
  const reference::ForcedRef m(p);
  const reference::RefPeriod q = reference::RefOnePeriod(m, r.z[0], r.z[1], false, 1e-18L);
  EXPECT_TRUE(q.ok);
  return {std::max(std::abs(q.x - r.z[0]), std::abs(q.y - r.z[1])), q.phi[0][0] + q.phi[1][1],
          q.phi[0][0] * q.phi[1][1] - q.phi[0][1] * q.phi[1][0], q.sticks};
}

TEST(ForcedCodim2, R2OnPdAndNsCurvesIsOnePointWithBothMultipliersAtMinusOne) {
  const ForcedParams base = Stribeck041();
  const ForcedChartResult r = Chart(base, 0.6, 2.4, 0.002, 0.16);
  std::vector<const ForcedCodim2*> pd, ns;
  for (const ForcedCodim2& c : r.codim2)
    if (c.label == Codim2Label::kR2) {
      EXPECT_EQ(c.method, ForcedCodim2Method::kRefined);
      (c.on == CurveKind::kPeriodDoubling ? pd : ns).push_back(&c);
    }
  ASSERT_EQ(pd.size(), 2u);
  ASSERT_EQ(ns.size(), 2u);
  for (const ForcedCodim2* a : pd) {
    double best = INFINITY;
    for (const ForcedCodim2* b : ns)
      best = std::min(best, std::max(std::abs(a->p1 - b->p1), std::abs(a->p2 - b->p2)));
    std::printf("R2 at Omega %.12f A %.12f: the NS curve's R2 %.2e away\n", a->p1, a->p2, best);
    EXPECT_LT(best, 1e-11);
    const RefCheck ref = Reference(base, *a);
    std::printf("  reference: fixed-point residual %.2Le, tr + 2 = %.2Le, det - 1 = %.2Le\n",
                ref.residual, ref.trace + 2, ref.det - 1);
    EXPECT_EQ(ref.sticks, 0);
    EXPECT_LT(ref.residual, 1e-10L);
    EXPECT_LT(std::abs(ref.trace + 2), 1e-12L);
    EXPECT_LT(std::abs(ref.det - 1), 1e-12L);
  }
}

TEST(ForcedCodim2, R1AtTheTongueTipHasBothMultipliersAtPlusOne) {
  const ForcedParams base = SeedBelt042();
  const ForcedChartResult r = Chart(base, 0.6, 1.6, 0.002, 0.1);  // the study's [chart]
  int n = 0;
  for (const ForcedCodim2& c : r.codim2) {
    if (c.label != Codim2Label::kR1) continue;
    ++n;
    EXPECT_EQ(c.method, ForcedCodim2Method::kRefined);
    const RefCheck ref = Reference(base, c);
    std::printf(
        "R1 at Omega %.12f A %.12f: reference residual %.2Le, tr - 2 = %.2Le, det - 1 = "
        "%.2Le\n",
        c.p1, c.p2, ref.residual, ref.trace - 2, ref.det - 1);
    EXPECT_EQ(ref.sticks, 0);
    EXPECT_LT(ref.residual, 1e-10L);
    EXPECT_LT(std::abs(ref.trace - 2), 1e-12L);
    EXPECT_LT(std::abs(ref.det - 1), 1e-12L);
  }
  EXPECT_EQ(n, 2);
}

// The GR curve of the pure-slip orbits on studies/forced_ns_seed.ini (the
// grazing margin v - max x' on the slip field without switching): it crosses
// the rectangle (it stopped after 2-3 points while the margin past the
// grazing was minus the stick time, a square root), and at points across it
// a one-parameter run in Omega at the point's A (ContinueForced through the
// point's orbit, its own bisection of the stick structure's change) locates
// its GR at the curve's Omega.
TEST(ForcedCodim2, PureSlipGrazingCurveMatchesOneParameterRuns) {
  const ForcedParams base = SeedBelt042();
  const ForcedChartResult r = Chart(base, 0.6, 1.6, 0.002, 0.1);
  const ForcedCurve* gr = nullptr;
  for (const ForcedCurve& c : r.curves)
    if (c.kind == CurveKind::kGrazing && c.m == 1) gr = &c;
  ASSERT_NE(gr, nullptr);
  EXPECT_GT(gr->points.size(), 100u);
  EXPECT_EQ(gr->ends.first.kind, CurveEndKind::kBorder);
  EXPECT_EQ(gr->ends.last.kind, CurveEndKind::kBorder);
  int checked = 0;
  for (size_t i = 10; i < gr->points.size(); i += gr->points.size() / 6) {
    const ForcedCurvePoint& p = gr->points[i];
    ForcedParams q = base;
    q.omega = p.p1, q.force = p.p2;
    const ForcedModel model(q);
    const FlowPoint z =
        (testing_util::RunForced(model, ForcedStart(model, p.phase / model.omega(), p.x0, p.xdot0),
                                 model.period())
             .end);
    OrbitBranchOptions o(ForcedModel::FlowDefaults());
    o.palc.ds = o.palc.ds_max = 2e-4;
    double best = NAN;
    for (const double side : {1.0, -1.0}) {
      const OrbitBranch b = ContinueForced(q, Parameter::kOmega, p.p1 + side * 2e-3,
                                           p.p1 - side * 2e-3, z.z[0], z.z[1], 1, o);
      for (const OrbitRow& row : b.special)
        if (row.label == SpecialKind::kGrazing &&
            !(std::abs(best - p.p1) <= std::abs(row.p - p.p1)))
          best = row.p;
      if (!std::isnan(best)) break;
    }
    std::printf("GR curve point Omega %.12f A %.6f: the run's GR %.2e away\n", p.p1, p.p2,
                best - p.p1);
    EXPECT_LT(std::abs(best - p.p1), 1e-10) << "A = " << p.p2;
    ++checked;
  }
  EXPECT_GE(checked, 5);
}

}  // namespace
}  // namespace stickslip
