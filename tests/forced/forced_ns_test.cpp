// A Neimark-Sacker point of the forced oscillator (issue 20, item 3: NS
// "located to 1e-10"): the small non-stop response of a Stribeck belt
// (mu_s 0.4, mu_k 0.25, v_s 0.2, beta 0.05, A 0.05, Omega 1.5) loses
// stability as v falls through the negative-damping region, its complex
// pair leaving the unit circle near the unforced Hopf point
// 2 beta + mu'(v) = 0 (v = 0.2 ln(7.5) = 0.40298). The reference: the
// periodic orbit by Newton on the independent long-double stroboscopic map
// (reference/forced_lyapunov.hpp, RKF78), and v where det(Phi) = |mu|^2 = 1
// bisected here.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "forced_reference.hpp"
#include "forced_trace.hpp"
#include "reference/forced_lyapunov.hpp"
#include "src/continuation/orbit_problem.hpp"
#include "stickslip/continuation/orbit_branch.hpp"

namespace stickslip {
namespace {

using reference::LReal;

ForcedBeltParams Scene(double v) { return forced_reference::StribeckBelt(v, 0.05, 1.5); }

// det of the reference map's Jacobian at its fixed point near (x, y).
LReal RefDet(const ForcedBeltParams& p, LReal x, LReal y, bool* ok) {
  const reference::ForcedRef m(p);
  for (int it = 0; it < 20; ++it) {
    const reference::RefPeriod r = reference::RefOnePeriod(m, x, y, false, 1e-17L);
    *ok = r.ok && r.sticks == 0;
    if (!*ok) return 0;
    // Newton on P(z) - z: (Phi - I) dz = -(P(z) - z).
    const LReal a = r.phi[0][0] - 1, b = r.phi[0][1], c = r.phi[1][0], d = r.phi[1][1] - 1;
    const LReal fx = r.x - x, fy = r.y - y, det = a * d - b * c;
    const LReal dx = -(d * fx - b * fy) / det, dy = -(-c * fx + a * fy) / det;
    x += dx, y += dy;
    if (std::abs(dx) + std::abs(dy) < 1e-17L)
      return r.phi[0][0] * r.phi[1][1] - r.phi[0][1] * r.phi[1][0];
  }
  *ok = false;
  return 0;
}

LReal RefDet(double v, LReal x, LReal y, bool* ok) { return RefDet(Scene(v), x, y, ok); }

// The root of det(Phi) - 1 in Omega between lo (stable) and hi (unstable),
// by bisection on the reference map, from the state (x, y) at phase 0.
double RefNsOmega(ForcedBeltParams p, double lo, double hi, double x, double y) {
  bool ok = false;
  p.omega = lo;
  EXPECT_LT(RefDet(p, x, y, &ok), 1) << "Omega = " << lo;
  p.omega = hi;
  EXPECT_GT(RefDet(p, x, y, &ok), 1) << "Omega = " << hi;
  for (int i = 0; i < 60 && std::abs(hi - lo) > 1e-15; ++i) {
    p.omega = 0.5 * (lo + hi);
    (RefDet(p, x, y, &ok) < 1 ? lo : hi) = p.omega;
    EXPECT_TRUE(ok) << "Omega = " << p.omega;
  }
  return lo;
}

TEST(ForcedNeimarkSacker, LocatedWhereTheReferenceMapsPairLeavesTheUnitCircle) {
  OrbitBranchOptions o(ForcedBelt::FlowDefaults());
  o.palc.ds_max = o.palc.ds = 0.01;
  const OrbitBranch b = testing_util::Trace(Scene(0.6), Parameter::kV, 0.6, 0.3, o);
  EXPECT_EQ(b.status, BranchStatus::kReachedEnd) << b.message;
  ASSERT_EQ(b.special.size(), 1u);
  const OrbitRow& ns = b.special[0];
  EXPECT_EQ(ns.label, SpecialKind::kTorus);
  EXPECT_EQ(ns.sticks, 0);
  EXPECT_NEAR(std::abs(ns.multipliers[0]), 1, 1e-9);
  EXPECT_GT(std::abs(ns.multipliers[0].imag()), 0.1);  // a complex pair, not +-1
  // Near the unforced Hopf point (the forcing shifts it by O(A^2)).
  EXPECT_NEAR(ns.p, 0.2 * std::log(7.5), 0.01);
  // The reference: det(Phi) - 1 changes sign at the NS; bisect in v.
  bool ok = false;
  double lo = ns.p + 0.002, hi = ns.p - 0.002;  // stable at lo, unstable at hi
  ASSERT_LT(RefDet(lo, ns.start.z[0], ns.start.z[1], &ok), 1);
  ASSERT_TRUE(ok);
  ASSERT_GT(RefDet(hi, ns.start.z[0], ns.start.z[1], &ok), 1);
  ASSERT_TRUE(ok);
  for (int i = 0; i < 60 && std::abs(hi - lo) > 1e-15; ++i) {
    const double mid = 0.5 * (lo + hi);
    (RefDet(mid, ns.start.z[0], ns.start.z[1], &ok) < 1 ? lo : hi) = mid;
    ASSERT_TRUE(ok) << "v = " << mid;
  }
  std::printf("[ measured ] NS at v = %.15g, reference %.15g, error %.2e; |mu| - 1 = %.2e\n", ns.p,
              lo, ns.p - lo, std::abs(ns.multipliers[0]) - 1);
  EXPECT_NEAR(ns.p, lo, 1e-10);
}

// The same scene at v = 0.41 (just above the Hopf point: steady sliding
// stable), continued in Omega at A = 0.02 (studies/forced_ns_stribeck.ini): the
// pure-slip response loses stability on both sides of the 1:1 resonance, where
// its amplitude makes the mean slope of mu steep enough. Both NS points
// against det(Phi) = 1 of the reference map bisected in Omega.
TEST(ForcedNeimarkSacker, InOmegaBothSidesOfTheResonance) {
  ForcedBeltParams p = Scene(0.41);
  p.force = 0.02;
  OrbitBranchOptions o(ForcedBelt::FlowDefaults());
  o.palc.ds_max = o.palc.ds = 0.01;
  const OrbitBranch b = testing_util::TraceOmega(p, 2, 0.6, o);
  EXPECT_EQ(b.status, BranchStatus::kReachedEnd) << b.message;
  ASSERT_EQ(b.special.size(), 2u);
  for (const OrbitRow& ns : b.special) {
    EXPECT_EQ(ns.label, SpecialKind::kTorus);
    EXPECT_EQ(ns.sticks, 0);
    EXPECT_NEAR(std::abs(ns.multipliers[0]), 1, 1e-9);
    EXPECT_GT(std::abs(ns.multipliers[0].imag()), 0.1);
    // Unstable towards Omega = 1, stable away from it.
    const double out = ns.p > 1 ? 0.002 : -0.002;
    p.omega = ns.p;
    const double ref = RefNsOmega(p, ns.p + out, ns.p - out, ns.start.z[0], ns.start.z[1]);
    std::printf("[ measured ] NS at Omega = %.15g, reference %.15g, error %.2e\n", ns.p, ref,
                ns.p - ref);
    EXPECT_NEAR(ns.p, ref, 1e-12);
  }
}

// The NS points of studies/forced_ns_seed.ini (the seed's cubic law at
// v = 0.42, A = 0.05, in Omega): the 1:1 tongue's two sides, where the locked
// pure-slip orbit is stable towards Omega = 1.
TEST(ForcedNeimarkSacker, SeedBeltTongueInOmega) {
  ForcedBeltParams p = forced_reference::SeedBelt(0.42, 0.05, 1);
  OrbitBranchOptions o(ForcedBelt::FlowDefaults());
  o.palc.ds_max = o.palc.ds = 0.01;
  const OrbitBranch b = testing_util::TraceOmega(p, 1.3, 0.6, o);
  int checked = 0;
  for (const OrbitRow& ns : b.special) {
    if (ns.label != SpecialKind::kTorus) continue;
    EXPECT_EQ(ns.sticks, 0);
    EXPECT_GT(std::abs(ns.multipliers[0].imag()), 0.1);
    const double in = ns.p > 1 ? -0.002 : 0.002;
    p.omega = ns.p;
    const double ref = RefNsOmega(p, ns.p + in, ns.p - in, ns.start.z[0], ns.start.z[1]);
    std::printf("[ measured ] seed belt NS at Omega = %.15g, reference %.15g, error %.2e\n", ns.p,
                ref, ns.p - ref);
    EXPECT_NEAR(ns.p, ref, 1e-12);
    ++checked;
  }
  EXPECT_EQ(checked, 2) << b.message;
}

// Beside R2 (issue 35, planted bugs): on the pure-slip response at v 0.41,
// A 0.113 the pair goes from complex near -1 to real (-1.0267, -0.9739)
// through a PD and back. Two PD points and no NS; an NS point would have to
// be a complex pair on the unit circle (the rule: TorusPairIsComplex...).
TEST(ForcedNeimarkSacker, NoneBesideR2WhereThePairIsReal) {
  ForcedBeltParams p = Scene(0.41);
  p.force = 0.113;
  const OrbitBranch b =
      testing_util::TraceOmega(p, 2.4, 1.6, OrbitBranchOptions(ForcedBelt::FlowDefaults()));
  EXPECT_EQ(b.status, BranchStatus::kReachedEnd) << b.message;
  int pd = 0;
  for (const OrbitRow& s : b.special) {
    EXPECT_NE(s.label, SpecialKind::kTorus)
        << "Omega = " << s.p << ", mu " << s.multipliers[0] << ", " << s.multipliers[1];
    if (s.label == SpecialKind::kTorus) {
      OrbitRow o;
      o.multipliers = {s.multipliers[0], s.multipliers[1]};
      EXPECT_TRUE(orbit_detail::TorusPair(o, 1e-6));
    }
    pd += s.label == SpecialKind::kPeriodDoubling;
  }
  EXPECT_EQ(pd, 2);
}

// The rule itself: a real pair whose product is 1 (a neutral saddle) is no
// NS point; a complex pair on the unit circle is.
TEST(ForcedNeimarkSacker, TorusPairIsComplexOnTheUnitCircle) {
  OrbitRow r;
  r.multipliers = {-1.0294, 1 / -1.0294};  // product 1, real
  EXPECT_NEAR(orbit_detail::RowTest(r, 2), 0, 1e-15);
  EXPECT_FALSE(orbit_detail::TorusPair(r, 1e-6));
  r.multipliers = {-1.0294, -0.9714};
  EXPECT_FALSE(orbit_detail::TorusPair(r, 1e-6));
  r.multipliers = {std::polar(1.0, 2.0), std::polar(1.0, -2.0)};
  EXPECT_TRUE(orbit_detail::TorusPair(r, 1e-6));
  r.multipliers = {std::polar(1.01, 2.0), std::polar(1.01, -2.0)};
  EXPECT_FALSE(orbit_detail::TorusPair(r, 1e-6));
}

}  // namespace
}  // namespace stickslip
