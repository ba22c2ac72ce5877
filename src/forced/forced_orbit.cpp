// The forced oscillator's orbits on the one shooting (orbits/shooting.hpp):
// its stroboscopic map and its exit-phase map are the time and stick-exit
// sections of ForcedModel (x, x', theta).
#include <cmath>
#include <memory>

#include "forced_shooting.hpp"
#include "stickslip/errors.hpp"
#include "stickslip/forced/orbit.hpp"

namespace stickslip {

void Multipliers(const Mat2& M, std::complex<double> out[2]) {
  // lambda^2 - tr lambda + det = 0.
  const double tr = M.trace(), det = M.determinant();
  const std::complex<double> disc = std::sqrt(std::complex<double>(tr * tr / 4 - det));
  out[0] = tr / 2 + disc;
  out[1] = tr / 2 - disc;
  if (std::abs(out[1]) > std::abs(out[0])) std::swap(out[0], out[1]);
}

namespace forced_detail {

// One shooting per thread for the options last used (a forced orbit is
// shot per scan point and per branch step: the flow and its buffers are
// kept, the model assigned).
Shooting& CachedShooting(const ForcedModel& model, const ForcedOrbitOptions& o) {
  const std::string err = o.flow.ValidationError();
  if (!err.empty()) throw InvalidArgument(err);
  if (!(o.tol > 0) || o.max_newton < 1)
    throw InvalidArgument("orbit options: tol must be > 0 and max_newton >= 1");
  ShootingOptions so;
  so.flow = o.flow;
  so.max_newton = o.max_newton;
  so.tol = o.tol;
  so.max_steps = o.flow.max_steps;
  thread_local std::unique_ptr<Shooting> cached;
  if (cached) {
    const ShootingOptions& c = cached->options();
    if (c.flow == so.flow && c.max_newton == so.max_newton && c.tol == so.tol &&
        c.max_steps == so.max_steps) {
      cached->set_system(model);
      return *cached;
    }
  }
  cached = std::make_unique<Shooting>(model, so);
  return *cached;
}

ForcedOrbitStatus FromOrbitStatus(OrbitStatus s) {
  switch (s) {
    case OrbitStatus::kOk:
      return ForcedOrbitStatus::kConverged;
    case OrbitStatus::kSingular:
      return ForcedOrbitStatus::kSingular;
    case OrbitStatus::kNotConverged:
    case OrbitStatus::kNoReturn:
      return ForcedOrbitStatus::kNoConvergence;
    default:
      return ForcedOrbitStatus::kFlowFailed;
  }
}

Extrema ExtremaOf(const PeriodicOrbit& o) {
  return o.lo.size() >= 2 ? Extrema{o.lo[0], o.hi[0], o.lo[1], o.hi[1]} : Extrema::Empty();
}

}  // namespace forced_detail

ForcedOrbit ShootStroboscopic(const ForcedModel& model, double x0, double xdot0, int m,
                              const ForcedOrbitOptions& options) {
  if (m < 1) throw InvalidArgument("m = " + std::to_string(m) + " must be >= 1");
  Shooting& shooting = forced_detail::CachedShooting(model, options);
  PoincareSection section;
  section.kind = SectionKind::kTime;
  section.time = m * model.period();
  const PeriodicOrbit p = shooting.Find({0, Eigen::Vector3d(x0, xdot0, 0), ModeSet()}, section);
  ForcedOrbit o;
  o.m = m;
  o.period = section.time;
  o.status = forced_detail::FromOrbitStatus(p.status);
  o.message = p.message;
  o.iterations = p.iterations;
  o.update = p.update;
  if (!p.ok()) return o;
  o.start = {p.start.t, p.start.z[0], p.start.z[1], p.start.mode[0]};
  o.monodromy = p.monodromy;
  o.multipliers[0] = p.multipliers[0];
  o.multipliers[1] = p.multipliers[1];
  o.stable = p.stable;
  o.sticks = p.sticks;
  o.crossings = p.crossings;
  o.extrema = forced_detail::ExtremaOf(p);
  o.steps = p.steps;
  return o;
}

}  // namespace stickslip
