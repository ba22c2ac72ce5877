// Branch switching at a period doubling (issue 20, item 3: "PD, with a switch
// onto the doubled branch"): the forced Stribeck scene of
// studies/stribeck_forced.ini, whose m = 1 stick-slip branch doubles near
// Omega = 0.618. The doubled branch must emanate from the PD point (its orbit
// tends to the m = 1 orbit run twice, its multiplier to +1 = (-1)^2) and,
// where it is stable, be the attractor of the independent long-double
// stroboscopic map (reference/forced_lyapunov.hpp, RKF78).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "forced_run.hpp"
#include "forced_trace.hpp"
#include "reference/forced_lyapunov.hpp"
#include "stickslip/errors.hpp"
#include "stickslip/orbits/forced_orbit.hpp"

namespace stickslip {
namespace {

ForcedBeltParams StribeckScene(double omega) {
  ForcedBeltParams p;
  p.base.law = LawKind::kStribeck;
  p.base.mu_s = 0.4, p.base.mu_k = 0.25, p.base.v_s = 0.2;
  p.base.beta = 0.05, p.base.v = 0.25;
  p.force = 0.3, p.omega = omega;
  return p;
}

// The doubled branch from the stroboscopic point (x0, x0') of the
// m-periodic orbit of p (at its PD) between lo and hi: ContinueDoubled on
// the stroboscopic section.
OrbitBranch Doubled(const ForcedBeltParams& p, double x0, double xdot0, double lo, double hi, int m,
                    const OrbitBranchOptions& o) {
  const ForcedBelt at(p);
  const FlowPoint pd = testing_util::StrobePoint(x0, xdot0);
  return ContinueDoubled(at, ParameterAxis(Parameter::kOmega).index(), pd,
                         PoincareSection::Stroboscopic(at, pd.z, m), lo, hi, o);
}

OrbitBranchOptions Options() {
  OrbitBranchOptions o(ForcedBelt::FlowDefaults());
  o.shooting.flow.rtol = o.shooting.flow.atol = 1e-13;
  o.palc.ds_max = 0.004;
  o.palc.ds = 0.004;
  return o;
}

// The m = 1 branch from Omega = 0.7 down to 0.6 and its first PD.
OrbitRow FirstPeriodDoubling() {
  const ForcedBeltParams p = StribeckScene(0.7);
  const ForcedBelt m(p);
  const FlowRun tr = testing_util::RunForced(m, ForcedStart(m, 0, 0, 0.25), 200 * m.period());
  const OrbitBranch b = testing_util::StrobeBranch(p, Parameter::kOmega, 0.7, 0.6, tr.end.z[0],
                                                   tr.end.z[1], 1, Options());
  for (const OrbitRow& r : b.special)
    if (r.label == SpecialKind::kPeriodDoubling) return r;
  ADD_FAILURE() << "no PD on the m = 1 branch: " << Name(b.status) << " " << b.message;
  return {};
}

TEST(ForcedSwitch, DoubledBranchEmanatesFromThePeriodDoubling) {
  const OrbitRow pd = FirstPeriodDoubling();
  ASSERT_EQ(pd.label, SpecialKind::kPeriodDoubling);
  const OrbitBranch d = Doubled(StribeckScene(pd.p), pd.start.z[0], pd.start.z[1], pd.p - 0.006,
                                pd.p + 0.006, 1, Options());
  ASSERT_GE(d.rows.size(), 4u) << Name(d.status) << " " << d.message;
  EXPECT_EQ(d.status, BranchStatus::kReachedEnd) << d.message;
  // Supercritical: the doubled branch opens toward lower Omega, stable there.
  const OrbitRow& first = d.rows.front();
  EXPECT_LT(first.p, pd.p);
  EXPECT_EQ(PeriodMultiple(d), 2);
  // Near the PD the 2-cycle's points are z +- a sqrt(|p - p_PD|) e: the
  // offset from the m = 1 orbit, squared over |p - p_PD|, tends to a constant,
  // and the multiplier of the doubled orbit tends to +1.
  double ratio[2] = {0, 0};
  for (int i = 0; i < 2; ++i) {
    const OrbitRow& r = d.rows[i];
    const double off2 =
        std::pow(r.start.z[0] - pd.start.z[0], 2) + std::pow(r.start.z[1] - pd.start.z[1], 2);
    ratio[i] = off2 / std::abs(r.p - pd.p);
    std::printf(
        "[ measured ] doubled row %d: Omega - Omega_PD = %.3e, |z - z_PD| = %.3e, "
        "mult %.9f\n",
        i, r.p - pd.p, std::sqrt(off2), r.multipliers[0].real());
  }
  EXPECT_NEAR(ratio[1] / ratio[0], 1, 0.2);
  // The flip normal form x -> -(1 + a) x + c x^3 (Kuznetsov, section 4.4):
  // the m orbit's multiplier is -(1 + a), the 2-cycle's (1 - 2a)^2 ~ 1 - 4a,
  // so (1 - mu_2m) / |1 + mu_m| -> 4 at the PD (mu_m by separate shooting).
  const OrbitRow& r0 = d.rows.front();
  ShootingOptions oo(ForcedBelt::FlowDefaults());
  oo.flow = Options().shooting.flow;
  const ForcedBelt m0(StribeckScene(r0.p));
  const PeriodicOrbit single = ShootStroboscopic(m0, pd.start.z[0], pd.start.z[1], 1, oo);
  ASSERT_TRUE(single.ok());
  const double flip = std::abs(1 + single.multipliers[0].real());
  const double ratio4 = (1 - r0.multipliers[0].real()) / flip;
  std::printf("[ measured ] (1 - mu_2) / |1 + mu_1| = %.6f at Omega - Omega_PD = %.3e\n", ratio4,
              r0.p - pd.p);
  EXPECT_NEAR(ratio4, 4, 0.1);
  EXPECT_LT(std::abs(r0.multipliers[0]), 1);      // stable where it opens
  EXPECT_GT(std::abs(single.multipliers[0]), 1);  // the m = 1 orbit is not
  for (const OrbitRow& r : d.special)
    std::printf("[ measured ] doubled branch: %s at Omega = %.15g\n", Name(r.label), r.p);
  // Away from the PD, the independent map's attractor is the doubled orbit:
  // from the library's 2m point, 400 reference periods later the map still
  // alternates between it and its image (the m = 1 orbit there is unstable).
  const OrbitRow& far = d.rows.back();
  EXPECT_NEAR(far.p, pd.p - 0.006, 1e-12);
  ASSERT_TRUE(far.stable);
  const ForcedBeltParams q = StribeckScene(far.p);
  const reference::ForcedRef m(q);
  reference::LReal x = far.start.z[0] + 1e-4, y = far.start.z[1];
  bool stuck = far.start.z[1] == q.base.v;
  for (int k = 0; k < 400; ++k) {
    const reference::RefPeriod per = reference::RefOnePeriod(m, x, y, stuck, 1e-16L);
    ASSERT_TRUE(per.ok);
    x = per.x, y = per.y, stuck = per.stuck;
  }
  const reference::RefPeriod half = reference::RefOnePeriod(m, x, y, stuck, 1e-16L);
  const double gap0 = std::hypot(double(x) - far.start.z[0], double(y) - far.start.z[1]);
  const double split = std::hypot(double(half.x - x), double(half.y - y));
  std::printf("[ measured ] Omega = %.12g: reference attractor vs doubled row %.2e, split %.3e\n",
              far.p, gap0, split);
  EXPECT_LT(gap0, 1e-8);
  EXPECT_GT(split, 1e-3);  // a genuine 2-cycle, not the m = 1 orbit
}

TEST(ForcedSwitch, RefusesAPointWithoutAFlip) {
  OrbitBranchOptions o = Options();
  const ForcedBeltParams p = StribeckScene(0.7);
  const ForcedBelt m(p);
  const FlowRun tr = testing_util::RunForced(m, ForcedStart(m, 0, 0, 0.25), 200 * m.period());
  ShootingOptions oo(ForcedBelt::FlowDefaults());
  oo.flow = o.shooting.flow;
  const PeriodicOrbit orbit = ShootStroboscopic(m, tr.end.z[0], tr.end.z[1], 1, oo);
  ASSERT_TRUE(orbit.ok());
  const OrbitBranch d = Doubled(p, orbit.start.z[0], orbit.start.z[1], 0.6, 0.8, 1, o);
  EXPECT_EQ(d.status, BranchStatus::kStartFailed);
  EXPECT_NE(d.message.find("not a period doubling"), std::string::npos) << d.message;
  EXPECT_TRUE(d.rows.empty());
  EXPECT_EQ(PeriodMultiple(d), 2);  // the section it would have had, also on failure
  // Bounds that do not bracket the PD's Omega (0.7) are refused by name.
  try {
    Doubled(p, 0, 0, 0.8, 0.9, 1, o);
    ADD_FAILURE() << "bounds 0.8, 0.9 accepted at Omega = 0.7";
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find("lo < 0.7 < hi"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace stickslip
