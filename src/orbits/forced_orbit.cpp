// The forced oscillator's orbits on the one shooting (orbits/shooting.hpp):
// its stroboscopic map and its exit-phase map are the time and stick-exit
// sections of ForcedBelt (x, x', theta).
#include "stickslip/orbits/forced_orbit.hpp"

#include <cmath>
#include <memory>

#include "stickslip/errors.hpp"

namespace stickslip {

void Multipliers(const Mat2& M, std::complex<double> out[2]) {
  // lambda^2 - tr lambda + det = 0.
  const double tr = M.trace(), det = M.determinant();
  const std::complex<double> disc = std::sqrt(std::complex<double>(tr * tr / 4 - det));
  out[0] = tr / 2 + disc;
  out[1] = tr / 2 - disc;
  if (std::abs(out[1]) > std::abs(out[0])) std::swap(out[0], out[1]);
}

int PeriodMultiple(const ForcedBelt& model, const PeriodicOrbit& o) {
  return static_cast<int>(std::lround(o.period / model.period()));
}

namespace {

// One shooting per thread for the options last used (a forced orbit is shot
// per scan point: the flow and its buffers are kept, the model assigned).
// An exit-phase search sets its own return time, so that is not compared.
// Options equal to the cached ones were validated when it was made; its
// return time is validated as it is set.
Shooting& CachedShooting(const ForcedBelt& model, const ShootingOptions& o) {
  thread_local std::unique_ptr<Shooting> cached;
  if (cached) {
    const ShootingOptions& c = cached->options();
    if (c.flow == o.flow && c.max_newton == o.max_newton && c.tol == o.tol &&
        c.max_steps == o.max_steps && c.extrema == o.extrema && c.switching == o.switching) {
      cached->set_system(model);
      cached->set_max_return_time(o.max_return_time);
      return *cached;
    }
  }
  cached = std::make_unique<Shooting>(model, o);  // throws InvalidArgument for bad options
  return *cached;
}

}  // namespace

PeriodicOrbit ShootStroboscopic(const ForcedBelt& model, double x0, double xdot0, int m,
                                const ShootingOptions& options) {
  if (m < 1) throw InvalidArgument("m = " + std::to_string(m) + " must be >= 1");
  Shooting& shooting = CachedShooting(model, options);
  PoincareSection section;
  section.kind = SectionKind::kTime;
  section.time = m * model.period();
  return shooting.Find({0, Eigen::Vector3d(x0, xdot0, 0), ModeSet()}, section);
}

// The exit-phase map (docs/theory.md, "One shooting"): stick collapses the
// state to one number, the phase at which it ends, so the return from one
// exit to the next is a circle map t_e -> t'; on the one shooting it is the
// stick-exit section of (x, x', theta), closing after `sticks` exits and m
// turns of theta.
PeriodicOrbit ExitPhaseOrbit(const ForcedBelt& model, double t_guess, Mode exit_mode, int sticks,
                             int m, const ShootingOptions& options) {
  if (m < 1 || sticks < 1) throw InvalidArgument("m and sticks must be >= 1");
  if (exit_mode == Mode::kStick) throw InvalidArgument("exit_mode must be a slip mode");
  Shooting& shooting = CachedShooting(model, options);
  const double T = model.period();
  shooting.set_max_return_time((m + 2) * T);  // well past the expected return
  FlowPoint start{t_guess, Eigen::Vector3d(0, model.v(), model.omega() * t_guess),
                  ModeSet(exit_mode)};
  // On the band's edge x_e = +-mu_s - 2 beta v + A cos(Omega t_e).
  const double sign = exit_mode == Mode::kSlipBelow ? 1 : -1;
  model.ProjectOnExit(ModeSet(Mode::kStick), 0, sign * model.static_limit(), start.z);
  PeriodicOrbit p = shooting.Find(start, PoincareSection::StickExit(0, sticks, m));
  if (p.status == OrbitStatus::kNoReturn)
    p.message = "fewer stick exits than asked for within m + 2 periods";
  if (!p.ok()) return p;
  // The exit time in [0, T) (theta is its clock: t = theta / Omega).
  const double t = p.start.z[2] / model.omega();
  p.start.t = t - std::floor(t / T) * T;
  p.start.z[2] = model.omega() * p.start.t;
  return p;
}

}  // namespace stickslip
