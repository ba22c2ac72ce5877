// Adding-sliding on a forced branch with Filippov friction (coulomb,
// mu_s = mu_k: the slip leaving a stick phase starts tangent to x' = v, as in
// Kowalczyk & Piiroinen, Physica D 237, 2008). Along a stick phase the stick
// force f(t) = x_a + v (t - t_a) + 2 beta v - A cos(Omega t) has an interior
// maximum; where it touches mu_s a stick phase splits around a short slip
// (di Bernardo, Kowalczyk & Nordmark, Physica D 170, 2002, section 3, case
// 4). Reference: the closed-form coulomb pieces in long double
// (forced_reference.hpp), the orbit a fixed point of x -> x(T) from a stuck
// start, and Omega bisected on its stick count.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "forced_reference.hpp"
#include "forced_trace.hpp"
#include "stickslip/continuation/orbit_branch.hpp"

namespace stickslip {
namespace {

namespace ref = forced_reference;
using ref::Real;

// The m = 1 orbit through (x, v) at t = 0 (stuck there): the secant method on
// x -> x(T) from x_guess. Whether it closed to 1e-15, and its stick count.
bool StuckOrbit(const ref::Setup& s, Real x_guess, int* sticks) {
  const Real T = 2 * std::acos(Real(-1)) / s.w;
  auto run = [&](Real x0, int* n) {
    ref::PieceSim<ref::CoulombPiece> sim(s);
    sim.dt = 5e-3L;
    Real t = 0, x = x0, y = s.v;
    sim.Run(t, x, y, T);
    if (n) *n = sim.sticks;
    return x;
  };
  Real a = x_guess, b = x_guess + 1e-6L, fa = run(a, nullptr) - a;
  for (int i = 0; i < 30 && std::abs(b - a) > 1e-18L; ++i) {
    const Real fb = run(b, nullptr) - b, c = b - fb * (b - a) / (fb - fa);
    a = b, fa = fb, b = c;
  }
  return std::abs(run(b, sticks) - b) < 1e-15L;
}

// The stick count of that orbit at Omega = w.
int SticksOfOrbit(const ForcedBeltParams& p, Real w, Real x_guess) {
  const ref::Setup s{reference::Law(p.base), Real(p.base.beta), Real(p.base.v), Real(p.force), w};
  int sticks = 0;
  EXPECT_TRUE(StuckOrbit(s, x_guess, &sticks)) << "no orbit at Omega = " << double(w);
  return sticks;
}

// Coulomb mu_s = mu_k = 0.3, beta 0.05, v 0.1, A 0.4: near Omega = 0.41025
// the two stick phases of the m = 1 orbit merge (2 -> 1 with Omega up).
TEST(ForcedAddingSliding, FilippovCoulombStickPhasesMergeWhereTheStickForceTouchesMuS) {
  const ForcedBeltParams p = ref::Coulomb(0.3, 0.3, 0.05, 0.1, 0.4, 1);
  OrbitBranchOptions o(ForcedBelt::FlowDefaults());
  o.palc.ds_max = o.palc.ds = 0.005;
  const OrbitBranch b = testing_util::TraceOmega(p, 0.38, 0.44, o);
  const OrbitRow* ad = nullptr;
  for (const OrbitRow& r : b.special)
    if (std::abs(r.p - 0.41025) < 1e-3) ad = &r;
  ASSERT_NE(ad, nullptr) << Name(b.status) << " " << b.message;
  EXPECT_EQ(ad->label, SpecialKind::kAdding) << ad->description;
  ASSERT_DOUBLE_EQ(ad->start.z[1], 0.1);  // stuck at the section: the reference's start
  Real lo = 0.4101L, hi = 0.4104L;
  ASSERT_EQ(SticksOfOrbit(p, lo, ad->start.z[0]), 2);
  ASSERT_EQ(SticksOfOrbit(p, hi, ad->start.z[0]), 1);
  for (int i = 0; i < 50 && hi - lo > 1e-15L; ++i) {
    const Real mid = (lo + hi) / 2;
    (SticksOfOrbit(p, mid, ad->start.z[0]) == 2 ? lo : hi) = mid;
  }
  std::printf("[ measured ] AD at Omega = %.15g, reference %.15Lg, error %.1e\n", ad->p, lo,
              double(ad->p - lo));
  EXPECT_NEAR(ad->p, double(lo), 1e-10);
}

// With mu_s > mu_k (coulomb 0.4, 0.25, beta 0.05, v 0.1, A 0.6) the stick
// force's interior minimum reaches -mu_s near Omega = 0.3581105: the slip that
// splits the stick phase starts with x'' = mu_k - mu_s != 0, so it is not
// short and no m = 1 orbit exists beyond. Once ~100 GR labels flooded
// 0.35808 .. 0.35811 there: the parameter difference of the corrector
// straddled the jump (dP/dOmega ~ 9e3) and points with residual 1e-5 were
// accepted as stalled. One event, one label, at the edge of the 1-stick orbits
// (the secant on the closed-form pieces finds none beyond it).
TEST(ForcedAddingSliding, StickSplitWithAJumpIsOneLabelAtTheEdge) {
  const ForcedBeltParams p = ref::Coulomb(0.4, 0.25, 0.05, 0.1, 0.6, 1);
  OrbitBranchOptions o(ForcedBelt::FlowDefaults());
  o.palc.ds_max = 0.02 * 0.02;
  o.palc.ds = std::min(o.palc.ds, o.palc.ds_max);
  const OrbitBranch b = testing_util::TraceOmega(p, 0.35, 0.37, o);
  std::vector<OrbitRow> near;
  for (const OrbitRow& r : b.special)
    if (std::abs(r.p - 0.35811) < 1e-4) near.push_back(r);
  ASSERT_EQ(near.size(), 1u) << near.size() << " labels; " << b.message;
  EXPECT_EQ(near[0].label, SpecialKind::kAdding) << near[0].description;
  EXPECT_EQ(b.status, BranchStatus::kSequenceEnded) << b.message;  // its natural end
  for (const OrbitRow& r : b.rows) EXPECT_LE(r.p, near[0].p);      // nothing beyond the edge
  ASSERT_DOUBLE_EQ(near[0].start.z[1], 0.1);
  auto orbit = [&](Real w) {  // a 1-stick orbit near the edge's state
    const ref::Setup s{reference::Law(p.base), Real(0.05), Real(0.1), Real(0.6), w};
    int sticks = 0;
    return StuckOrbit(s, near[0].start.z[0], &sticks) && sticks == 1;
  };
  Real lo = 0.35811L, hi = 0.358111L;
  ASSERT_TRUE(orbit(lo));
  ASSERT_FALSE(orbit(hi));
  for (int i = 0; i < 50 && hi - lo > 1e-15L; ++i) {
    const Real mid = (lo + hi) / 2;
    (orbit(mid) ? lo : hi) = mid;
  }
  std::printf("[ measured ] edge at Omega = %.15g, reference %.15Lg, error %.1e\n", near[0].p, lo,
              double(near[0].p - lo));
  EXPECT_NEAR(near[0].p, double(lo), 1e-10);
}

// A floor run restarted in v (coulomb 0.4, 0.3, beta 0.1, A 0.5, Omega
// 0.5425): past the jump at v = 0.17025 Palc lands on the 1-stick orbits at
// v = 0.185 and once went down them (the far tangent oriented by the near
// one) to their edge at v = 0.1730304 (an AD-type split), ending there
// step-too-small. The sweep now goes on toward `to`: it reaches v = 0.5, and
// a stable row near v = 0.3 is an orbit of the closed-form pieces.
TEST(ForcedAddingSliding, FloorRunInVGoesOnTowardItsEndAfterAJump) {
  ForcedBeltParams p = ref::Coulomb(0.4, 0.3, 0.1, 0, 0.5, 0.542525324500101);
  OrbitBranchOptions o(ForcedBelt::FlowDefaults());
  o.palc.ds_max = o.palc.ds = 0.01;
  const OrbitBranch b = testing_util::Trace(p, Parameter::kV, 0, 0.5, o);
  EXPECT_EQ(b.status, BranchStatus::kReachedEnd) << b.message;
  ASSERT_FALSE(b.rows.empty());
  EXPECT_EQ(b.rows.back().p, 0.5);
  for (size_t i = 1; i < b.rows.size(); ++i)  // the restart once wrote its start twice
    EXPECT_NE(b.rows[i].p, b.rows[i - 1].p) << "row " << i << " repeats the row before";
  const OrbitRow* row = nullptr;
  for (const OrbitRow& r : b.rows)
    if (r.p >= 0.3 && r.stable && !row) row = &r;
  ASSERT_NE(row, nullptr);
  p.base.v = row->p;
  const ref::Setup s{reference::Law(p.base), Real(0.1), Real(row->p), Real(0.5), Real(p.omega)};
  ref::PieceSim<ref::CoulombPiece> sim(s);
  const Real T = 2 * std::acos(Real(-1)) / p.omega;
  Real t = 0, x = row->start.z[0], y = row->start.z[1];
  sim.Run(t, x, y, 40 * T);
  std::printf("[ measured ] v = %.6g: closed-form pieces return to (%.3e, %.3e) of the row\n",
              row->p, double(x - row->start.z[0]), double(y - row->start.z[1]));
  EXPECT_NEAR(double(x), row->start.z[0], 1e-9);
  EXPECT_NEAR(double(y), row->start.z[1], 1e-9);
}

// With no jump allowed, the turn back after Palc's landing across the jump is
// not taken: the run is cut short and says so (it once ended "reached-end",
// with no message, at v = 0.185).
TEST(ForcedAddingSliding, FloorRunInVOutOfJumpsSaysSo) {
  const ForcedBeltParams p = ref::Coulomb(0.4, 0.3, 0.1, 0, 0.5, 0.542525324500101);
  OrbitBranchOptions o(ForcedBelt::FlowDefaults());
  o.palc.ds_max = o.palc.ds = 0.01;
  o.max_jumps = 0;
  const OrbitBranch b = testing_util::Trace(p, Parameter::kV, 0, 0.5, o);
  EXPECT_EQ(b.status, BranchStatus::kStepTooSmall) << b.message;
  EXPECT_NE(b.message.find("turned back after a jump, max_jumps = 0"), std::string::npos)
      << b.message;
  EXPECT_EQ(b.jumps, 0);
  std::printf("[ measured ] %zu rows to v = %.6g: %s\n", b.rows.size(), b.rows.back().p,
              b.message.c_str());
  ASSERT_FALSE(b.rows.empty());
  EXPECT_LT(b.rows.back().p, 0.5);
}

}  // namespace
}  // namespace stickslip
