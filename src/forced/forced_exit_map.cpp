// Stick-slip orbits of the forced oscillator as fixed points of the exit-phase
// map (design.md section 5): stick collapses the state to one number, the
// phase at which it ends, so the return from one exit to the next is a circle
// map t_e -> t'. Its derivative follows the exit time's dependence on the
// state: delta t = -grad h . delta z / (dh/dt) at the exit (h = stick force -+ mu_s).
#include <cmath>

#include "numerics/tolerances.hpp"
#include "stickslip/errors.hpp"
#include "stickslip/forced/orbit.hpp"

namespace stickslip {
namespace {

// The edge of the stick band the exit into `mode` leaves from, at time t.
double EdgeX(const ForcedModel& m, double t, Mode mode) {
  const double s = mode == Mode::kSlipBelow ? 1 : -1;
  return s * m.static_limit() - 2 * m.beta() * m.v() + m.force() * std::cos(m.omega() * t);
}

}  // namespace

ForcedExitOrbit ExitPhaseOrbit(const ForcedModel& model, double t_guess, Mode exit_mode, int sticks,
                               int m, const ForcedOrbitOptions& options) {
  if (m < 1 || sticks < 1) throw InvalidArgument("m and sticks must be >= 1");
  if (exit_mode == Mode::kStick) throw InvalidArgument("exit_mode must be a slip mode");
  const ForcedFlow flow(model, options.flow);
  const double T = model.period();
  ForcedExitOrbit o;
  o.m = m, o.sticks = sticks, o.exit_mode = exit_mode;
  double t = t_guess;
  for (o.iterations = 1; o.iterations <= options.max_newton; ++o.iterations) {
    const ForcedPoint start{t, EdgeX(model, t, exit_mode), model.v(), exit_mode};
    ForcedRequest rq;
    rq.t_end = t + (m + 2) * T;  // well past the expected return
    rq.variational = true;
    rq.stop_at_exit = sticks;
    const ForcedRun run = flow.Run(start, rq);
    if (run.status != ForcedStatus::kReached) {
      o.status = ForcedOrbitStatus::kFlowFailed;
      o.message = run.message;
      return o;
    }
    if (run.exits < sticks || run.end.mode != exit_mode) {
      o.status = ForcedOrbitStatus::kNoConvergence;
      o.message = run.exits < sticks ? "fewer stick exits than asked for within m + 2 periods"
                                     : "the return leaves the other edge of the stick band";
      return o;
    }
    // w: the start's motion with t_e (along the edge, minus the flow's own).
    const Vec2 f0 = model.Field(exit_mode, t, Vec2(start.x, start.xdot));
    const Vec2 w(-model.force() * model.omega() * std::sin(model.omega() * t) - f0[0], -f0[1]);
    // S_out leaves the x row alone: row 0 of the run's Jacobian is the stick's delta x.
    const double dtp = -(run.jacobian.row(0).dot(w)) / model.StickForceRate(run.end.t);
    const double g = run.end.t - t - m * T, dg = dtp - 1;
    if (!(std::abs(dg) > Tolerances::kExitMapFold)) {
      o.status = ForcedOrbitStatus::kSingular;
      o.message = "the exit map's derivative is 1 (a fold)";
      return o;
    }
    double dt = -g / dg;
    if (std::abs(dt) > T / 4) dt = std::copysign(T / 4, dt);
    o.update = std::abs(dt);
    if (o.update <= options.tol * (1 + std::abs(t))) {
      o.t_exit = t - std::floor(t / T) * T;
      o.x_exit = start.x;
      o.multiplier = dtp;
      o.stable = std::abs(dtp) < 1;
      o.crossings = run.crossings;
      o.extrema = run.extrema;
      o.status = ForcedOrbitStatus::kConverged;
      return o;
    }
    t += dt;
  }
  o.message = "no convergence in " + std::to_string(options.max_newton) + " Newton iterations";
  return o;
}

}  // namespace stickslip
