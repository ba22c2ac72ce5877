// Stroboscopic shooting for periodic orbits of the forced oscillator.
#include <cmath>

#include "numerics/tolerances.hpp"
#include "stickslip/errors.hpp"
#include "stickslip/forced/orbit.hpp"

namespace stickslip {

const char* ForcedOrbitStatusName(ForcedOrbitStatus s) { return Name(s); }

void Multipliers(const Mat2& M, std::complex<double> out[2]) {
  // lambda^2 - tr lambda + det = 0.
  const double tr = M.trace(), det = M.determinant();
  const std::complex<double> disc = std::sqrt(std::complex<double>(tr * tr / 4 - det));
  out[0] = tr / 2 + disc;
  out[1] = tr / 2 - disc;
  if (std::abs(out[1]) > std::abs(out[0])) std::swap(out[0], out[1]);
}

namespace {

// The orbit's data from the run over one period of the orbit from its start.
void Describe(const ForcedRun& run, ForcedOrbit& o) {
  o.monodromy = run.jacobian;
  Multipliers(o.monodromy, o.multipliers);
  o.stable = std::abs(o.multipliers[0]) < 1;
  o.sticks = run.sticks;
  o.crossings = run.crossings;
  o.extrema = run.extrema;
  o.steps = run.steps;
}

}  // namespace

ForcedOrbit ShootStroboscopic(const ForcedModel& model, double x0, double xdot0, int m,
                              const ForcedOrbitOptions& options) {
  if (m < 1) throw InvalidArgument("m = " + std::to_string(m) + " must be >= 1");
  if (!(options.tol > 0) || options.max_newton < 1)
    throw InvalidArgument("orbit options: tol must be > 0 and max_newton >= 1");
  const ForcedFlow flow(model, options.flow);
  ForcedOrbit o;
  o.m = m;
  o.period = m * model.period();
  ForcedRequest rq;
  rq.t_end = o.period;
  rq.variational = true;
  ForcedPoint z = ForcedStart(model, 0, x0, xdot0);
  for (o.iterations = 1; o.iterations <= options.max_newton; ++o.iterations) {
    const ForcedRun run = flow.Run(z, rq);
    if (run.status != ForcedStatus::kReached) {
      o.status = ForcedOrbitStatus::kFlowFailed;
      o.message = run.message;
      return o;
    }
    const Vec2 r(run.end.x - z.x, run.end.xdot - z.xdot);
    const Mat2 A = run.jacobian - Mat2::Identity();
    if (std::abs(A.determinant()) <= Tolerances::kSingularShooting * (1 + A.cwiseAbs().maxCoeff())) {
      o.status = ForcedOrbitStatus::kSingular;
      o.message = "DP^m - I is singular (a multiplier at 1)";
      return o;
    }
    Vec2 dz = -A.partialPivLu().solve(r);
    const double size = 1 + std::max(std::abs(z.x), std::abs(z.xdot));
    const double norm = dz.cwiseAbs().maxCoeff();
    const double cap = Tolerances::kForcedNewtonCap * size;
    if (norm > cap) dz *= cap / norm;  // a long step is cut (damped Newton)
    o.update = dz.cwiseAbs().maxCoeff();
    if (o.update <= options.tol * size) {
      o.start = z;
      Describe(run, o);
      o.status = ForcedOrbitStatus::kConverged;
      return o;
    }
    // A stroboscopic point in stick stays on x' = v: its x' row of DP^m is 0.
    if (run.end.mode == Mode::kStick)
      z = ForcedStart(model, 0, z.x + dz[0], model.v());
    else
      z = ForcedStart(model, 0, z.x + dz[0], z.xdot + dz[1]);
  }
  o.status = ForcedOrbitStatus::kNoConvergence;
  o.message = "no convergence in " + std::to_string(options.max_newton) + " Newton iterations";
  return o;
}

}  // namespace stickslip
