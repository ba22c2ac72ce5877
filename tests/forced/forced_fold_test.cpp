// Folds (LP) of forced stick-slip branches against an independent reference
// (issue 20: "located to 1e-10"). The reference shares nothing with the
// continuation: a 1-stick orbit leaves its stick phase at a phase theta where
// x + 2 beta v - A cos(theta) = mu_s, so theta alone fixes the exit state
// (x_e, v) (design.md section 5). For each theta, Omega(theta) closes the orbit:
// the next stick exit comes one forcing period later, found by the secant
// method on long-double RKF78 runs (forced_reference.hpp, tolerance 1e-18).
// The branch is the graph Omega(theta); its folds are the extrema of that
// scalar function, found by Brent's method (Boost.Math brent_find_minima).
#include <gtest/gtest.h>

#include <boost/math/tools/minima.hpp>
#include <cmath>
#include <cstdio>

#include "forced_reference.hpp"
#include "forced_trace.hpp"
#include "stickslip/continuation/orbit_branch.hpp"

namespace stickslip {
namespace {

namespace ref = forced_reference;
using ref::Real;

const Real kPi = std::acos(Real(-1));

// The time from the stick exit at phase theta to the next stick exit, minus
// one forcing period (0 on a 1-stick orbit of m = 1). NaN if the run has
// no single stick phase in between.
Real ExitGap(const ForcedBeltParams& p, Real w, Real theta) {
  const ref::Setup s{reference::Law(p.base), Real(p.base.beta), Real(p.base.v), Real(p.force), w};
  ref::PieceSim<ref::OdeintPiece> sim(s);
  sim.dt = 1e-2L;
  const Real T = 2 * kPi / w, t0 = theta / w;
  Real t = t0, x = s.law.mu_s - 2 * s.beta * s.v + s.a * std::cos(theta), y = s.v;
  sim.Run(t, x, y, t0 + Real(1.1) * T, +1);  // slip below the belt: the force is +mu_s
  int sticks = 0;
  for (const ref::Event& e : sim.events) {
    if (e.kind == 0) ++sticks;
    if (e.kind == 1) return sticks == 1 ? e.t - t0 - T : Real(NAN);
  }
  return NAN;
}

// Omega(theta): the root of ExitGap in Omega by the secant method from w0.
Real OmegaAt(const ForcedBeltParams& p, Real theta, Real w0) {
  Real a = w0, b = w0 * (1 + Real(1e-6)), fa = ExitGap(p, a, theta);
  for (int i = 0; i < 30; ++i) {
    const Real fb = ExitGap(p, b, theta);
    if (fb == 0 || std::abs(b - a) < 1e-17L * b) return b;
    const Real c = b - fb * (b - a) / (fb - fa);
    a = b, fa = fb, b = c;
  }
  return b;
}

// The exit phase (mod 2 pi) of the orbit of row r (the reference's run from
// its stroboscopic point).
Real ExitPhase(const ForcedBeltParams& p, const OrbitRow& r) {
  const ref::Setup s{reference::Law(p.base), Real(p.base.beta), Real(p.base.v), Real(p.force),
                     Real(r.p)};
  ref::PieceSim<ref::OdeintPiece> sim(s);
  sim.dt = 1e-2L;
  Real t = 0, x = r.start.z[0], y = r.start.z[1];
  sim.Run(t, x, y, 2 * kPi / Real(r.p));
  for (const ref::Event& e : sim.events)
    if (e.kind == 1) return std::fmod(e.t * Real(r.p), 2 * kPi);
  return NAN;
}

// The extremum of Omega(theta) within +-half_width of the LP row's exit
// phase: a minimum if sign = +1, a maximum if sign = -1.
Real ReferenceFold(const ForcedBeltParams& p, const OrbitRow& lp, Real half_width, int sign) {
  const Real theta0 = ExitPhase(p, lp);
  Real w = lp.p;  // the last root: the next secant's start
  auto f = [&](Real theta) {
    w = OmegaAt(p, theta, w);
    return sign * w;
  };
  const auto best =
      boost::math::tools::brent_find_minima(f, theta0 - half_width, theta0 + half_width, 28);
  EXPECT_GT(best.first, theta0 - 0.95L * half_width) << "the extremum is at the bracket's end";
  EXPECT_LT(best.first, theta0 + 0.95L * half_width) << "the extremum is at the bracket's end";
  return sign * best.second;
}

struct Fold {
  double near;  // where the scene's notes put it
  int sign;     // +1: Omega has a minimum there along the branch, -1: a maximum
};

void CheckFolds(const ForcedBeltParams& p, double from, double to, const std::vector<Fold>& folds) {
  OrbitBranchOptions o(
      ForcedBelt::FlowDefaults());  // as ss_continue: max_step 0.02 of the range, rtol 1e-12
  o.palc.ds_max = 0.02 * std::abs(to - from);
  o.palc.ds = std::min(o.palc.ds, o.palc.ds_max);
  const OrbitBranch b = testing_util::TraceOmega(p, from, to, o);
  for (const Fold& f : folds) {
    const OrbitRow* lp = nullptr;
    for (const OrbitRow& r : b.special)
      if (r.label == SpecialKind::kFold && std::abs(r.p - f.near) < 1e-4) lp = &r;
    ASSERT_NE(lp, nullptr) << "no LP near " << f.near << ": " << b.message;
    ASSERT_EQ(lp->sticks, 1);  // the reference parametrises 1-stick orbits
    ASSERT_EQ(lp->crossings, 0);
    const Real w = ReferenceFold(p, *lp, 0.02L, f.sign);
    std::printf("[ measured ] LP at Omega = %.15g, reference extremum %.15Lg, error %.1e\n", lp->p,
                w, double(lp->p - w));
    EXPECT_NEAR(lp->p, double(w), 1e-10);
  }
}

// The forced Stribeck scene (studies/stribeck_forced.ini): the m = 1 branch
// from Omega = 0.8 down turns at a minimum 0.62374 and a maximum 0.63020.
TEST(ForcedFold, StribeckSceneFoldsAreTheExtremaOfTheExitPhaseFamily) {
  const ForcedBeltParams p = [] {
    ForcedBeltParams q = ref::Belt(LawKind::kStribeck, 0.05, 0.25, 0.3, 0.8);
    q.base.v_s = 0.2;
    return q;
  }();
  CheckFolds(p, 0.8, 0.5, {{0.62374, +1}, {0.63020, -1}});
}

// The forced seed belt (studies/seed_forced.ini) at A = 0.18: a minimum at
// 0.71747 and a maximum at 0.72817 of the 1-stick branch.
TEST(ForcedFold, SeedBeltFoldsAreTheExtremaOfTheExitPhaseFamily) {
  ForcedBeltParams p = ref::Belt(LawKind::kCubic, 0.05, 0.25, 0.18, 1);
  p.base.mu_m = 0.25, p.base.v_m = 0.5;
  CheckFolds(p, 1, 0.3, {{0.71747, +1}, {0.72817, -1}});
}

}  // namespace
}  // namespace stickslip
