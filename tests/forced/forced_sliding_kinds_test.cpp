// Sliding bifurcations of forced branches, each kind against a reference
// computed another way (issue 20, item 3): long-double closed-form coulomb
// pieces (forced_reference.hpp) iterated to the orbit, and the parameter
// where the orbit meets the stick band bracketed by bisection here.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "forced_reference.hpp"
#include "forced_trace.hpp"
#include "stickslip/continuation/orbit_branch.hpp"

namespace stickslip {
namespace {

namespace ref = forced_reference;
using ref::Real;

OrbitBranch Trace(ForcedBeltParams p, double from, double to, double ds_max) {
  OrbitBranchOptions o(ForcedBelt::FlowDefaults());
  o.palc.ds_max = o.palc.ds = ds_max;
  return testing_util::TraceOmega(p, from, to, o);
}

ref::Setup SetupOf(const ForcedBeltParams& p, Real w) {
  return ref::Setup{reference::Law(p.base), Real(p.base.beta), Real(p.base.v), Real(p.force), w};
}

// The closed-form pieces from (x0, x0') at t = 0 over `periods` forcing
// periods; the events of the last one.
std::vector<ref::Event> LastPeriod(const ForcedBeltParams& p, Real w, Real x0, Real y0,
                                   int periods) {
  ref::PieceSim<ref::CoulombPiece> sim(SetupOf(p, w));
  sim.dt = 5e-3L;
  const Real T = 2 * std::acos(Real(-1)) / w;
  Real t = 0, x = x0, y = y0;
  sim.Run(t, x, y, (periods - 1) * T);
  sim.events.clear();
  sim.Run(t, x, y, periods * T);
  return sim.events;
}

// The belt scene of issue 20 (coulomb mu_s 0.4, mu_k 0.25, v 0.2, beta 0,
// A 0.3): near Omega = 1.19620 the crossing of the 1-stick orbit reaches the
// band's edge |x + 2 beta v - A cos(Omega t)| = mu_s and turns into a stick
// phase that merges with the next one (mu_s > mu_k holds it): crossing-
// sliding, which the branch once labelled SW, 9e-6 short of the edge.
TEST(ForcedSlidingKinds, BeltCrossingReachingTheBandIsCrossingSliding) {
  const ForcedBeltParams p = ref::Coulomb(0.4, 0.25, 0, 0.2, 0.3, 1);
  const OrbitBranch b = Trace(p, 1.15, 1.25, 0.005);
  const OrbitRow* point = nullptr;
  for (const OrbitRow& r : b.special)
    if (std::abs(r.p - 1.1962) < 1e-3) point = &r;
  ASSERT_NE(point, nullptr) << Name(b.status) << " " << b.message;
  EXPECT_EQ(point->label, SpecialKind::kCrossing) << point->description;
  // The reference: the stable orbit (multiplier -0.24) by 40 periods of the
  // closed-form pieces from the located point's state; g = |force at the
  // crossing| - mu_s, bisected in Omega (no crossing: past the edge).
  auto g = [&](Real w) {
    const std::vector<ref::Event> ev = LastPeriod(p, w, point->start.z[0], point->start.z[1], 40);
    const ref::Setup s = SetupOf(p, w);
    for (const ref::Event& e : ev)
      if (e.kind == 2) return std::abs(s.StickForce(e.t, e.x)) - Real(0.4);
    return Real(-1);
  };
  Real lo = 1.1961, hi = 1.1963;
  ASSERT_GT(g(lo), 0);
  ASSERT_LT(g(hi), 0);
  for (int i = 0; i < 60 && hi - lo > 1e-15L; ++i) {
    const Real mid = (lo + hi) / 2;
    (g(mid) > 0 ? lo : hi) = mid;
  }
  std::printf("[ measured ] CR at Omega = %.15g, reference %.15Lg, error %.2e\n", point->p, lo,
              double(point->p - lo));
  EXPECT_NEAR(point->p, double(lo), 1e-10);
}

// A damped belt (coulomb mu_s 0.4, mu_k 0.25, v 0.3, beta 0.05, A 0.3): the
// pure slip grazes x' = v where Omega |P| = v (closed form, bisected here),
// and near Omega = 0.7317 the stick entry of the 1-stick orbit reaches the
// band's edge and turns into a crossing: crossing-sliding from the stick side,
// which the branch once labelled SW at its last row, 2.4e-5 short.
TEST(ForcedSlidingKinds, StickEntryReachingTheBandIsCrossingSliding) {
  const ForcedBeltParams p = ref::Coulomb(0.4, 0.25, 0.05, 0.3, 0.3, 1);
  // Two runs: the one from 0.3 ends where its 1-stick orbits end, at Omega
  // 0.6436414 (no m = 1 orbit just beyond; it once went on through points
  // with residual 3e-6); the one from 0.7 is on the orbits of the CR.
  const OrbitBranch b = Trace(p, 0.3, 1.5, 0.02 * 1.2), b2 = Trace(p, 0.7, 1.5, 0.02 * 1.2);
  const OrbitRow *gr = nullptr, *cr = nullptr;
  for (const OrbitRow& r : b.special)
    if (std::abs(r.p - 0.6194) < 1e-3) gr = &r;
  for (const OrbitRow& r : b2.special)
    if (std::abs(r.p - 0.7317) < 1e-3) cr = &r;
  ASSERT_TRUE(gr && cr) << Name(b.status) << " " << b.message;
  EXPECT_EQ(gr->label, SpecialKind::kGrazing) << gr->description;
  EXPECT_EQ(cr->label, SpecialKind::kCrossing) << cr->description;
  // Omega |P| = v, |P| = A / |1 - Omega^2 + 2 i beta Omega|.
  auto slip = [](Real w) {
    const Real re = 1 - w * w, im = 2 * Real(0.05) * w;
    return w * Real(0.3) / std::sqrt(re * re + im * im) - Real(0.3);
  };
  const Real w_gr = ref::Bisect([&](Real w) { return slip(w) > 0; }, Real(0.5), Real(0.7));
  // Crossing-sliding: the 1-stick orbit of the closed-form pieces (stuck at
  // t = 0: a fixed point of x -> x(T), by the secant method) has no crossing
  // before the edge; beyond it there is no such orbit, or it crosses.
  auto crosses = [&](Real w) {
    const Real T = 2 * std::acos(Real(-1)) / w;
    auto X = [&](Real x0, std::vector<ref::Event>* ev) {
      ref::PieceSim<ref::CoulombPiece> sim(SetupOf(p, w));
      sim.dt = 5e-3L;
      Real t = 0, x = x0, y = 0.3L;
      sim.Run(t, x, y, T);
      if (ev) *ev = sim.events;
      return x;
    };
    Real a = cr->start.z[0], b = cr->start.z[0] + 1e-6L, fa = X(a, nullptr) - a;
    for (int i = 0; i < 30 && std::abs(b - a) > 1e-18L; ++i) {
      const Real fb = X(b, nullptr) - b, c = b - fb * (b - a) / (fb - fa);
      a = b, fa = fb, b = c;
    }
    std::vector<ref::Event> ev;
    if (std::abs(X(b, &ev) - b) > 1e-15L) return true;  // no such orbit: past the edge
    for (const ref::Event& e : ev)
      if (e.kind == 2) return true;
    return false;
  };
  ASSERT_FALSE(crosses(0.7316L));
  ASSERT_TRUE(crosses(0.7318L));
  const Real w_cr = ref::Bisect(crosses, Real(0.7316), Real(0.7318));
  std::printf(
      "[ measured ] GR at %.15g, closed form %.15Lg (%.1e); CR at %.15g, pieces %.15Lg "
      "(%.1e)\n",
      gr->p, w_gr, double(gr->p - w_gr), cr->p, w_cr, double(cr->p - w_cr));
  EXPECT_NEAR(gr->p, double(w_gr), 1e-10);
  EXPECT_NEAR(cr->p, double(w_cr), 1e-10);
}

}  // namespace
}  // namespace stickslip

namespace stickslip {
namespace {

// A floor run restarted in v (issue 20: v = 0 is Den Hartog's floor, v > 0 a
// belt): from v = 0 upward the branch goes on (at v = 0 the orbit is
// symmetric, x_min = -x_max, by x -> -x, t -> t + T/2); the search across a
// jump of the map once stepped below v = 0 and threw "v = -0.085 must be >= 0".
TEST(ForcedSlidingKinds, FloorRunContinuesInVFromZeroWithinTheDomain) {
  ForcedBeltParams p = ref::Coulomb(0.4, 0.3, 0.1, 0, 0.5, 0.542525324500101);
  OrbitBranchOptions o(ForcedBelt::FlowDefaults());
  o.palc.ds_max = o.palc.ds = 0.01;
  OrbitBranch b;
  ASSERT_NO_THROW(b = testing_util::Trace(p, Parameter::kV, 0, 0.5, o));
  ASSERT_FALSE(b.rows.empty()) << b.message;
  EXPECT_EQ(b.rows.front().p, 0);
  EXPECT_NEAR(RowExtrema(b.rows.front()).x_min, -RowExtrema(b.rows.front()).x_max, 1e-10);
  double v_max = 0;
  for (const OrbitRow& r : b.rows) {
    EXPECT_GE(r.p, 0);
    v_max = std::max(v_max, r.p);
  }
  EXPECT_GT(v_max, 0.17);  // past the first jump (GR near v = 0.173)
  // A stable row near v = 0.05: 40 periods of the closed-form pieces from
  // its stroboscopic point come back to it.
  for (const OrbitRow& r : b.rows) {
    if (r.p < 0.05 || !r.stable) continue;
    p.base.v = r.p;
    ref::PieceSim<ref::CoulombPiece> sim(SetupOf(p, p.omega));
    const Real T = 2 * std::acos(Real(-1)) / p.omega;
    Real t = 0, x = r.start.z[0], y = r.start.z[1];
    sim.Run(t, x, y, 40 * T);
    std::printf("[ measured ] v = %.6g: closed-form pieces return to (%.3e, %.3e) of the row\n",
                r.p, double(x - r.start.z[0]), double(y - r.start.z[1]));
    EXPECT_NEAR(double(x), r.start.z[0], 1e-9);
    EXPECT_NEAR(double(y), r.start.z[1], 1e-9);
    break;
  }
}

}  // namespace
}  // namespace stickslip
