// Stick-slip orbits of the forced oscillator as fixed points of the exit-phase
// map (issue 20, item 3), against the coulomb closed form: the return time of
// the closed-form simulation and its central difference in the exit time.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "forced_reference.hpp"
#include "forced_run.hpp"
#include "forced_trace.hpp"
#include "stickslip/continuation/orbit_branch.hpp"
#include "stickslip/orbits/forced_orbit.hpp"

namespace stickslip {
namespace {

namespace ref = forced_reference;
using ref::Real;

// The closed-form simulation from the exit at t_e into mode sigma (+1 below):
// the time of its `sticks`-th next exit.
Real ClosedFormReturn(const ForcedBeltParams& p, Real t_e, int sigma, int sticks) {
  const ref::Setup s{reference::Law(p.base), p.base.beta, p.base.v, p.force, p.omega};
  ref::PieceSim<ref::CoulombPiece> sim(s);
  Real t = t_e, x = sigma * s.law.mu_s - 2 * s.beta * s.v + s.a * std::cos(s.w * t_e), y = s.v;
  const Real T = 2 * std::acos(Real(-1)) / s.w;
  sim.Run(t, x, y, t_e + (sticks + 3) * T, sigma);
  int exits = 0;
  for (const auto& e : sim.events)
    if (e.kind == 1 && ++exits == sticks) return e.t;
  return -1;
}

// An exit time and side after a transient of 60 forcing periods.
void GuessExit(const ForcedBelt& m, double* t, Mode* mode) {
  for (const FlowSwitch& e : testing_util::RunSwitches(m, ForcedStart(m, 0, 0, 0), 60 * m.period()))
    if (e.kind == SwitchKind::kStickOut) *t = e.t, *mode = e.after[0];
}

void Check(const ForcedBeltParams& p, int sticks, int m) {
  const ForcedBelt model(p);
  double t_guess = -1;
  Mode mode = Mode::kSlipBelow;
  GuessExit(model, &t_guess, &mode);
  ASSERT_GT(t_guess, 0) << "no stick exit in the transient";
  ShootingOptions o(ForcedBelt::FlowDefaults());
  o.flow.rtol = o.flow.atol = 1e-14;
  const PeriodicOrbit orbit = ExitPhaseOrbit(model, t_guess, mode, sticks, m, o);
  ASSERT_TRUE(orbit.ok()) << orbit.message;
  const int sigma = mode == Mode::kSlipBelow ? 1 : -1;
  const Real T = model.period();
  const Real back = ClosedFormReturn(p, orbit.start.t, sigma, sticks);
  EXPECT_NEAR(static_cast<double>(back - orbit.start.t - m * T), 0, 1e-11);
  const Real d = 1e-6L;
  const Real fd = (ClosedFormReturn(p, orbit.start.t + d, sigma, sticks) -
                   ClosedFormReturn(p, orbit.start.t - d, sigma, sticks)) /
                  (2 * d);
  EXPECT_NEAR(orbit.multipliers[0].real(), static_cast<double>(fd), 1e-7);
  // The same orbit by stroboscopic shooting: the same nontrivial multiplier.
  // Its state at the next theta = 0 starts the shooting.
  const FlowRun to_zero = testing_util::RunForced(
      model, ForcedStart(model, orbit.start.t, orbit.start.z[0], model.v(), mode),
      std::ceil(orbit.start.t / model.period()) * model.period(), {}, o.flow);
  const PeriodicOrbit strobe = ShootStroboscopic(model, to_zero.end.z[0], to_zero.end.z[1], m, o);
  ASSERT_TRUE(strobe.ok()) << strobe.message;
  EXPECT_NEAR(strobe.multipliers[0].real(), orbit.multipliers[0].real(), 1e-9);
  EXPECT_EQ(strobe.sticks, sticks);
  EXPECT_EQ(strobe.crossings, orbit.crossings);
  EXPECT_NEAR(OrbitExtrema(strobe).x_max, OrbitExtrema(orbit).x_max, 1e-11);
  std::printf(
      "[ measured ] %d sticks in %d periods: t_e = %.15g, multiplier %.12g, "
      "closed form: return error %.2e, multiplier %.12g\n",
      sticks, m, orbit.start.t, orbit.multipliers[0].real(),
      static_cast<double>(back - orbit.start.t - m * T), static_cast<double>(fd));
}

TEST(ForcedExitMap, BeltStickSlipOrbitMatchesCoulombClosedForm) {
  ForcedBeltParams p;
  p.base.law = LawKind::kCoulomb;
  p.base.mu_s = 0.4, p.base.mu_k = 0.25, p.base.beta = 0.05, p.base.v = 0.2;
  p.force = 0.3, p.omega = 0.8;
  Check(p, 1, 1);
}

TEST(ForcedExitMap, FloorTwoStopOrbitMatchesCoulombClosedForm) {
  ForcedBeltParams p;
  p.base.law = LawKind::kCoulomb;
  p.base.mu_s = 0.4, p.base.mu_k = 0.3, p.base.beta = 0.05, p.base.v = 0;
  p.force = 0.7, p.omega = 0.6;
  Check(p, 2, 1);
}

// Flip-unstable stick-slip orbits (issue 35, planted bugs): the m = 1 orbit of
// studies/stribeck_forced.ini between its PD (Omega 0.6182) and 0.605 has a
// multiplier from -1.02 to -1.98; the exit map must call it unstable (|mu| > 1,
// not mu < 1). Started from the branch's rows (the transient finds the
// doubled attractors there); its multiplier against the stroboscopic one.
TEST(ForcedExitMap, FlipUnstableStickSlipOrbitsAreUnstable) {
  const ForcedBeltParams p = forced_reference::StribeckBelt(0.25, 0.3, 0.62);
  const OrbitBranch b =
      testing_util::TraceOmega(p, 0.62, 0.605, OrbitBranchOptions(ForcedBelt::FlowDefaults()));
  ASSERT_EQ(b.status, BranchStatus::kReachedEnd) << b.message;
  int checked = 0;
  double lowest = 0;
  for (const OrbitRow& r : b.rows) {
    if (r.p > 0.618 || r.label != SpecialKind::kNone) continue;
    ForcedBeltParams q = p;
    q.omega = r.p;
    const ForcedBelt model(q);
    double t = -1;
    Mode mode = Mode::kSlipBelow;
    for (const FlowSwitch& e : testing_util::RunSwitches(
             model, ForcedStart(model, 0, r.start.z[0], r.start.z[1]), model.period()))
      if (e.kind == SwitchKind::kStickOut) t = e.t, mode = e.after[0];
    ASSERT_GT(t, 0) << "Omega = " << r.p;
    const PeriodicOrbit o =
        ExitPhaseOrbit(model, t, mode, 1, 1, ShootingOptions(ForcedBelt::FlowDefaults()));
    ASSERT_TRUE(o.ok()) << o.message;
    EXPECT_NEAR(o.multipliers[0].real(), r.multipliers[0].real(), 1e-8) << "Omega = " << r.p;
    EXPECT_LT(o.multipliers[0].real(), -1) << "Omega = " << r.p;
    EXPECT_FALSE(o.stable) << "Omega = " << r.p << ", multiplier " << o.multipliers[0].real();
    lowest = std::min(lowest, o.multipliers[0].real());
    ++checked;
  }
  std::printf("[ measured ] %d orbits, multipliers down to %.4f\n", checked, lowest);
  EXPECT_GE(checked, 3);
  EXPECT_LT(lowest, -1.9);
}

}  // namespace
}  // namespace stickslip
