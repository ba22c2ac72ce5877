// Stick-slip orbits of the forced oscillator as fixed points of the exit-phase
// map (docs/theory.md, "One shooting"): stick collapses the state to one number, the
// phase at which it ends, so the return from one exit to the next is a circle
// map t_e -> t'. On the one shooting it is the stick-exit section of
// (x, x', theta), closing after `sticks` exits and m turns of theta.
#include <cmath>

#include "forced_shooting.hpp"
#include "stickslip/errors.hpp"
#include "stickslip/forced/orbit.hpp"

namespace stickslip {

ForcedExitOrbit ExitPhaseOrbit(const ForcedModel& model, double t_guess, Mode exit_mode, int sticks,
                               int m, const ForcedOrbitOptions& options) {
  if (m < 1 || sticks < 1) throw InvalidArgument("m and sticks must be >= 1");
  if (exit_mode == Mode::kStick) throw InvalidArgument("exit_mode must be a slip mode");
  Shooting& shooting = forced_detail::CachedShooting(model, options);
  const double T = model.period();
  shooting.set_max_return_time((m + 2) * T);  // well past the expected return
  FlowPoint start{t_guess, Eigen::Vector3d(0, model.v(), model.omega() * t_guess),
                  ModeSet(exit_mode)};
  // On the band's edge x_e = +-mu_s - 2 beta v + A cos(Omega t_e).
  const double sign = exit_mode == Mode::kSlipBelow ? 1 : -1;
  model.ProjectOnExit(ModeSet(Mode::kStick), 0, sign * model.static_limit(), start.z);
  const PeriodicOrbit p = shooting.Find(start, PoincareSection::StickExit(0, sticks, m));
  ForcedExitOrbit o;
  o.m = m, o.sticks = sticks, o.exit_mode = exit_mode;
  o.status = forced_detail::FromOrbitStatus(p.status);
  o.message = p.status == OrbitStatus::kNoReturn
                  ? "fewer stick exits than asked for within m + 2 periods"
                  : p.message;
  o.iterations = p.iterations;
  o.update = p.update;
  if (!p.ok()) return o;
  const double t = p.start.z[2] / model.omega();
  o.t_exit = t - std::floor(t / T) * T;
  o.x_exit = p.start.z[0];
  // DP's eigenvalues are this, 0 (the stick's collapse) and 0 (the flow).
  o.multiplier = p.multipliers[0].real();
  o.stable = p.stable;
  o.crossings = p.crossings;
  o.extrema = forced_detail::ExtremaOf(p);
  return o;
}

}  // namespace stickslip
