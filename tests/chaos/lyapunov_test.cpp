// The largest Lyapunov exponent of the forced flow (issue 21 item 2): on
// periodic windows against ln|mu_max| / T from the orbit's own Floquet
// multipliers (stroboscopic shooting and the exit-phase map: independent
// Newton solves), converging as the run grows; on a chaotic parameter
// against the long-double Odeint reference (reference/forced_lyapunov.hpp)
// within the estimates' own errors.
#include "stickslip/chaos/lyapunov.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "forced_reference.hpp"
#include "reference/forced_lyapunov.hpp"
#include "stickslip/errors.hpp"
#include "stickslip/forced/orbit.hpp"

namespace stickslip {
namespace {

ForcedParams Params(LawKind law, double beta, double v, double force, double omega) {
  return forced_reference::Belt(law, beta, v, force, omega);
}

// ln|mu_max| / T of the stroboscopic fixed point shot from the run's last point.
double FloquetExponent(const ForcedModel& m, const StroboscopicRun& r) {
  ForcedOrbitOptions o;
  const ForcedOrbit orbit = ShootStroboscopic(m, r.end.x, r.end.xdot, 1, o);
  EXPECT_EQ(orbit.status, ForcedOrbitStatus::kConverged) << orbit.message;
  EXPECT_TRUE(orbit.stable);
  return std::log(std::abs(orbit.multipliers[0])) / orbit.period;
}

TEST(Lyapunov, StickSlipWindowMatchesExitMapMultiplier) {
  // One stick per period (forced_bench's belt): one multiplier 0 (stick
  // collapses x'), the other the exit map's derivative.
  const ForcedModel m(Params(LawKind::kCoulomb, 0.05, 0.2, 0.3, 0.8));
  const StroboscopicRun r = IterateStroboscopic(m, ForcedStart(m, 0, 0, 0.2), LyapunovOptions());
  ASSERT_EQ(r.status, LyapunovStatus::kDone) << r.message;
  ForcedOrbitOptions o;
  const ForcedExitOrbit exit = ExitPhaseOrbit(m, 1.9, Mode::kSlipBelow, 1, 1, o);
  ASSERT_EQ(exit.status, ForcedOrbitStatus::kConverged) << exit.message;
  const double from_exit_map = std::log(std::abs(exit.multiplier)) / m.period();
  EXPECT_NEAR(r.lyapunov, from_exit_map, 1e-3);
  EXPECT_NEAR(r.lyapunov, FloquetExponent(m, r), 1e-3);
  for (const SectionPoint& q : r.points) EXPECT_EQ(q.sticks, 1);
}

// Convergence with the kept periods K on a non-stop (pure-slip) Stribeck orbit:
// printed, and at the defaults within 1e-3, shrinking with K.
void ConvergenceOnNonStopOrbit(double omega) {
  const ForcedModel m(Params(LawKind::kStribeck, 0.02, 0.2, 1.0, omega));
  double floquet = 0, last_err = 1;
  std::printf("omega %.3f: K, lambda, |lambda - floquet|\n", omega);
  for (int keep : {25, 50, 100, 200, 400, 800}) {
    LyapunovOptions o;
    o.keep = keep;
    const StroboscopicRun r = IterateStroboscopic(m, ForcedStart(m, 0, 0, 0.2), o);
    ASSERT_EQ(r.status, LyapunovStatus::kDone) << r.message;
    for (const SectionPoint& q : r.points) ASSERT_EQ(q.sticks, 0);
    if (keep == 25) floquet = FloquetExponent(m, r);
    const double err = std::abs(r.lyapunov - floquet);
    std::printf("  %4d  %.8f  %.2e\n", keep, r.lyapunov, err);
    if (keep == 200) {
      EXPECT_LT(err, 1e-3);  // the defaults
    }
    if (keep >= 200) {
      EXPECT_LE(err, last_err * 1.01 + 1e-12);
    }
    last_err = err;
  }
}

TEST(Lyapunov, NonStopRealMultipliersMatchFloquet) { ConvergenceOnNonStopOrbit(2.05); }
TEST(Lyapunov, NonStopComplexMultipliersMatchFloquet) { ConvergenceOnNonStopOrbit(1.5); }

TEST(Lyapunov, LinearPureSlipIsMinusBeta) {
  // Coulomb pure slip is linear: both multipliers have modulus exp(-beta T).
  const ForcedModel m(Params(LawKind::kCoulomb, 0.05, 0.2, 0.3, 0.4));
  const StroboscopicRun r = IterateStroboscopic(m, ForcedStart(m, 0, 0, 0.2), LyapunovOptions());
  ASSERT_EQ(r.status, LyapunovStatus::kDone) << r.message;
  EXPECT_NEAR(r.lyapunov, -0.05, 1e-3);
}

TEST(Lyapunov, ChaoticTaylorAgreesWithOdeintReference) {
  // Stribeck, beta 0.01, v 0.1, A 0.5, Omega 0.35: positive exponent, about 1.8 sticks per period.
  const ForcedParams p = Params(LawKind::kStribeck, 0.01, 0.1, 0.5, 0.35);
  const ForcedModel m(p);
  LyapunovOptions o;
  o.transient = 200, o.keep = 1000;
  const StroboscopicRun r = IterateStroboscopic(m, ForcedStart(m, 0, 0, 0.1), o);
  ASSERT_EQ(r.status, LyapunovStatus::kDone) << r.message;
  const reference::RefLyapunov ref =
      reference::RefLargestExponent(p, 0, 0.1L, o.transient, o.align, o.keep, o.batches, 1e-14L);
  ASSERT_TRUE(ref.ok);
  const double err = std::hypot(r.lyapunov_err, static_cast<double>(ref.err));
  std::printf("chaotic: taylor %.5f +- %.1e, reference %.5f +- %.1e\n", r.lyapunov, r.lyapunov_err,
              static_cast<double>(ref.lambda), static_cast<double>(ref.err));
  EXPECT_GT(r.lyapunov, 3 * r.lyapunov_err);  // chaotic
  EXPECT_NEAR(r.lyapunov, static_cast<double>(ref.lambda), 3 * err);
}

TEST(Lyapunov, InvalidOptionsThrow) {
  const ForcedModel m(Params(LawKind::kCoulomb, 0.05, 0.2, 0.3, 0.8));
  LyapunovOptions o;
  o.keep = 0;
  EXPECT_THROW(IterateStroboscopic(m, ForcedStart(m, 0, 0, 0.2), o), InvalidArgument);
}

}  // namespace
}  // namespace stickslip
