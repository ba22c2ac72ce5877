// Iterates of a Poincare map and the largest Lyapunov exponent
// (chaos/lyapunov.hpp; docs/theory.md "Lyapunov exponents").
#include "stickslip/chaos/lyapunov.hpp"

#include <cfloat>
#include <cmath>
#include <cstring>

#include "numerics/numbers.hpp"
#include "numerics/tolerances.hpp"
#include "stickslip/equilibria/steady_sliding.hpp"
#include "stickslip/errors.hpp"
#include "stickslip/flow/switching.hpp"

namespace stickslip {

std::string LyapunovOptions::ValidationError() const {
  const std::string e = flow.ValidationError();
  if (!e.empty()) return e;
  const std::string most = std::to_string(kMaxPeriods) + "]";
  if (transient < 0 || transient > kMaxPeriods)
    return "transient = " + std::to_string(transient) + " must lie in [0, " + most;
  if (keep < 1 || keep > kMaxPeriods)
    return "keep = " + std::to_string(keep) + " must lie in [1, " + most;
  if (align < 0 || align > transient)
    return "align = " + std::to_string(align) + " must lie in [0, transient]";
  if (batches < 1 || batches > keep)
    return "batches = " + std::to_string(batches) + " must lie in [1, keep]";
  if (!(max_return_time > 0) || !std::isfinite(max_return_time))
    return "max_return_time = " + Num(max_return_time) + " must be finite and > 0";
  return "";
}

namespace {

// Accumulates ln|J_k M|_F per kept return into batch sums.
class TangentProduct {
 public:
  TangentProduct(int n, int keep, int batches)
      : keep_(keep), sums_(batches, 0.0), times_(batches, 0.0) {
    m_ = Eigen::MatrixXd::Identity(n, n) / std::sqrt(static_cast<double>(n));
  }
  // One return's Jacobian over time dt; `record` adds its growth to the kept
  // sum. False (nothing changed) if J M is not finite (a grazing return).
  bool Apply(const Eigen::MatrixXd& J, double dt, bool record) {
    next_.noalias() = J * m_;
    double norm = next_.norm();
    if (!std::isfinite(norm)) return false;
    double growth = std::log(norm);
    if (!(norm > 0)) {  // collapsed onto zero: count a factor DBL_EPSILON, reseed with J
      ++collapses_;
      growth = std::log(DBL_EPSILON);
      next_ = J;
      norm = next_.norm();
      if (!(norm > 0)) next_.setIdentity(), norm = next_.norm();
    }
    m_ = next_ / norm;
    if (!record) return true;
    const size_t b = static_cast<size_t>(recorded_) * sums_.size() / keep_;
    sums_[b] += growth;
    times_[b] += dt;
    ++recorded_;
    return true;
  }
  // The exponent per unit time and the standard error of the batch means; a
  // fixed return time `period` > 0 counts returns x period (the stroboscopic map).
  void Result(double period, double* lambda, double* err) const {
    const int b = static_cast<int>(sums_.size());
    double total = 0, time = 0;
    for (int i = 0; i < b; ++i) total += sums_[i], time += times_[i];
    *lambda = total / (period > 0 ? recorded_ * period : time);
    *err = 0;
    if (b < 2) return;
    double var = 0;
    for (int i = 0; i < b; ++i) {
      const int n = (i + 1) * keep_ / b - i * keep_ / b;  // returns in batch i
      const double d = sums_[i] / (period > 0 ? n * period : times_[i]) - *lambda;
      var += d * d;
    }
    *err = std::sqrt(var / (b - 1) / b);
  }
  int collapses() const { return collapses_; }

 private:
  int keep_;
  std::vector<double> sums_, times_;
  Eigen::MatrixXd m_, next_;
  int recorded_ = 0, collapses_ = 0;
};

// The first component with |z_i| above a (or not finite), else -1.
int Diverged(ConstState z, double a) {  // a view: no copy of head(nt) per return
  for (int i = 0; i < z.size(); ++i)
    if (!(std::abs(z[i]) <= a)) return i;
  return -1;
}

// A start with a contact already open (its normal force <= 0) is outside
// the model: the run ends at once as kContactOpen.
bool OpenAtStart(const System& s, const FlowPoint& start, SectionRun* run) {
  for (int i = 0; i < s.contacts(); ++i) {
    const std::optional<ContactVelocity> n = s.NormalForce(i);
    if (!n || n->At(start.z.data()) > 0) continue;
    run->status = LyapunovStatus::kContactOpen;
    run->message = "contact " + std::to_string(i) + " is open at the start (normal force " +
                   Num(n->At(start.z.data())) + ")";
    run->end = start;
    return true;
  }
  return false;
}

// The kept point at z after the return r (its switches recorded).
SectionPoint Point(const System& s, const FlowPoint& z, const FlowRun& r,
                   const std::vector<FlowSwitch>& switches, double dt) {
  const int nt = s.tangent_dimension();
  SectionPoint p;
  p.z = z.z.head(nt);
  p.mode = z.mode;
  p.sticks = r.sticks, p.exits = r.exits;
  p.dt = dt;
  if (s.clocks() > 0)
    for (const FlowSwitch& ev : switches)
      if (ev.kind == SwitchKind::kStickOut) {
        const double phase = std::fmod(ev.z[nt], 2 * M_PI);
        p.first_exit_phase = static_cast<float>(phase < 0 ? phase + 2 * M_PI : phase);
        break;
      }
  return p;
}

// The map's Jacobian on the tangent block over one return: Phi on a time
// section; (I - f g^T / (g . f)) Phi at the arrival on a surface (shooting.hpp).
void ReturnJacobian(const System& s, const PoincareSection& p, const FlowRun& r, Eigen::VectorXd& f,
                    Eigen::VectorXd& g, Eigen::MatrixXd* J) {
  if (p.kind == SectionKind::kTime) {
    *J = r.jacobian;
    return;
  }
  const int n = s.dimension();
  f.resize(n);
  s.Field(r.end.mode, r.end.z, f);
  g.resize(n);
  SurfaceGradient(p.surface.g, g);
  *J = r.jacobian - f * (g.transpose() * r.jacobian) / g.dot(f);
}

void Check(const System& s, const FlowPoint& start, const PoincareSection& p,
           const LyapunovOptions& o) {
  const std::string e = o.ValidationError();
  if (!e.empty()) throw InvalidArgument(e);
  if (start.z.size() != s.dimension())
    throw InvalidArgument("the start has " + std::to_string(start.z.size()) +
                          " components, the system " + std::to_string(s.dimension()));
  if (p.kind == SectionKind::kStickExit)
    throw InvalidArgument("a map is iterated on a time or surface section, not a stick exit");
  if (p.kind == SectionKind::kTime && !(p.time > 0 && std::isfinite(p.time)))
    throw InvalidArgument("the section's time = " + Num(p.time) + " must be finite and > 0");
  if (p.kind == SectionKind::kSurface && s.clocks() > 0)
    throw InvalidArgument("a system with a clock is iterated on its stroboscopic section");
}

// Return k passed max_amplitude in component `big`. The ends of an
// iteration are out of line and cold: the loop runs every return (the hot
// code's footprint, docs/benchmarks.md, "Where the fetch cliff is").
[[gnu::noinline, gnu::cold]] void DivergedIn(const System& s, int big, int k, double max_amplitude,
                                             SectionRun* run) {
  run->status = LyapunovStatus::kDiverged;
  run->message =
      "|" + s.StateName(big) + "| passed " + Num(max_amplitude) + " in return " + std::to_string(k);
}

// The end of return k that is not a return: the run's status and message.
void EndStatus(const System& s, const FlowRun& r, bool timed, int k, double rest_tol,
               SectionRun* run) {
  const std::string where =
      std::string(timed ? " (period " : " (return ") + std::to_string(k) + ")";
  if (!timed && r.status == FlowStatus::kTimeLimit) {
    // At rest: settled there if the rest point is stable; a start placed on
    // an unstable one stays there too, but attracts nothing (no return).
    const bool at_rest = FieldVanishes(s, r.end.mode, r.end.z, rest_tol);
    const SteadyState eq = at_rest ? SteadySliding(s, r.end.mode) : SteadyState();
    run->status = eq.stable() ? LyapunovStatus::kRest : LyapunovStatus::kNoReturn;
    run->message = (eq.stable() ? "at rest at t = "
                    : at_rest ? "on an unstable rest point (largest real part " + Num(eq.max_real) +
                                    ") by t = "
                              : "no return by t = ") +
                   Num(r.end.t) + where;
    if (eq.stable()) run->lyapunov = eq.max_real;
    return;
  }
  run->status = r.status == FlowStatus::kCancelled     ? LyapunovStatus::kCancelled
                : r.status == FlowStatus::kContactOpen ? LyapunovStatus::kContactOpen
                                                       : LyapunovStatus::kFlowFailed;
  run->message = r.message + where;
}

// The end of return k that is not a return, and a drift past max_amplitude
// with no return (a stuck drift).
[[gnu::noinline, gnu::cold]] void EndWithout(const System& s, const FlowRun& r, bool timed, int k,
                                             double rest_tol, double max_amplitude,
                                             SectionRun* run) {
  EndStatus(s, r, timed, k, rest_tol, run);
  const int far = Diverged(r.end.z.head(s.tangent_dimension()), max_amplitude);
  const bool lost =
      run->status == LyapunovStatus::kNoReturn || run->status == LyapunovStatus::kFlowFailed;
  if (!lost || far < 0) return;
  run->status = LyapunovStatus::kDiverged;
  run->message = "|" + s.StateName(far) + "| = " + Num(r.end.z[far]) + " passed " +
                 Num(max_amplitude) + " before return " + std::to_string(k) +
                 ", t = " + Num(r.end.t);
}

}  // namespace

bool FieldVanishes(const System& s, const ModeSet& m, ConstState z, double tol) {
  Eigen::VectorXd f(s.dimension());
  s.Field(m, z, f);
  const int nt = s.tangent_dimension();
  return f.head(nt).lpNorm<Eigen::Infinity>() <= tol * (1 + z.head(nt).lpNorm<Eigen::Infinity>());
}

Section MaximaSection(const System& s) {
  const int d = s.DerivativeOf(0);
  Section x;
  x.direction = -1;
  if (d >= 0) {
    x.g.terms[0] = {d, 1.0};
    x.g.size = 1;
    return x;
  }
  x.g = s.Contact(0);  // h(z) = w.z - speed
  const SteadyState rest = SteadySliding(s);
  if (rest.found) x.g.speed += x.g.At(rest.z.data());  // h(z) - h(rest) = 0
  return x;
}

SectionRun IterateSection(const System& s, const FlowPoint& start, const PoincareSection& section,
                          const LyapunovOptions& o, const std::function<bool()>& cancelled,
                          double max_amplitude) {
  Check(s, start, section, o);
  // A flow of its own: `cancelled` may run another tool on this thread.
  Flow flow(s, o.flow);
  const bool timed = section.kind == SectionKind::kTime;
  const int n = s.dimension(), nt = s.tangent_dimension();
  const Eigen::VectorXd clocks = start.z.tail(n - nt);
  const double rest_tol = Tolerances::From(o.flow.rtol, o.flow.atol).SectionCycle();
  SectionRun run;
  if (OpenAtStart(s, start, &run)) return run;
  run.points.reserve(o.keep);
  TangentProduct tangent(nt, o.keep, o.batches);
  std::vector<FlowSwitch> switches;
  FlowRequest rq;
  rq.max_steps = o.flow.max_steps;
  if (!timed) rq.sections.push_back(section.surface);
  FlowRun r;
  Eigen::MatrixXd J;
  Eigen::VectorXd f, g;
  FlowPoint z = start;
  if (timed) z.t = 0;  // each period starts again at t = 0, phase as at the start
  const int total = o.transient + o.keep;
  for (int k = 0; k < total; ++k) {
    if (cancelled && cancelled()) {
      run.status = LyapunovStatus::kCancelled;
      run.message = "cancelled after " + std::to_string(k) + " returns";
      break;
    }
    const bool kept = k >= o.transient;
    rq.t_max = z.t + (timed ? section.time : o.max_return_time);
    rq.variational = o.exponent && k >= o.transient - o.align;
    switches.clear();
    rq.switches = kept ? &switches : nullptr;
    flow.Run(z, rq, &r);
    run.steps += r.steps;
    if (r.status != (timed ? FlowStatus::kTimeLimit : FlowStatus::kSection)) {
      EndWithout(s, r, timed, k, rest_tol, max_amplitude, &run);
      if (run.status == LyapunovStatus::kRest) z = r.end;
      break;
    }
    const int big = Diverged(r.end.z.head(nt), max_amplitude);
    if (big >= 0) {  // end: the last state within bounds
      DivergedIn(s, big, k, max_amplitude, &run);
      break;
    }
    const double dt = r.end.t - z.t;
    // z = r.end (both of the system's size), clocks back to the start's phase
    // on a time section: libc's copies, not an inlined vector loop each.
    z.t = timed ? 0.0 : r.end.t;
    z.mode = r.end.mode;
    std::memcpy(z.z.data(), r.end.z.data(), sizeof(double) * (timed ? nt : n));
    if (timed) {
      std::memcpy(z.z.data() + nt, clocks.data(), sizeof(double) * (n - nt));
      OntoStickSurfaces(s, z.mode, z.z);
    }
    if (rq.variational) {
      ReturnJacobian(s, section, r, f, g, &J);
      if (!tangent.Apply(J, dt, kept)) {
        run.status = LyapunovStatus::kFlowFailed;
        run.message = "the map's Jacobian is not finite at return " + std::to_string(k) +
                      ", t = " + Num(r.end.t) + " (the orbit grazes the section)";
        break;
      }
    }
    if (kept) run.points.push_back(Point(s, z, r, switches, dt));
  }
  run.end = z;
  run.collapses = tangent.collapses();
  if (run.status == LyapunovStatus::kDone && o.exponent)
    tangent.Result(timed ? section.time : 0, &run.lyapunov, &run.lyapunov_err);
  return run;
}

SectionRun IterateStroboscopic(const System& s, const FlowPoint& start, const LyapunovOptions& o,
                               const std::function<bool()>& cancelled, double max_amplitude) {
  return IterateSection(s, start, PoincareSection::Stroboscopic(s, start.z, 1), o, cancelled,
                        max_amplitude);
}

}  // namespace stickslip
