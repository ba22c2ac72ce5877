// The stroboscopic map's iterates and the largest Lyapunov exponent
// (chaos/lyapunov.hpp; docs/theory.md "Lyapunov exponents").
#include "stickslip/chaos/lyapunov.hpp"

#include <cfloat>
#include <cmath>

#include "numerics/numbers.hpp"
#include "stickslip/errors.hpp"

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
  return "";
}

namespace {

// Accumulates ln|J_k M|_F per kept period into batch sums.
class TangentProduct {
 public:
  explicit TangentProduct(int keep, int batches) : keep_(keep), sums_(batches, 0.0) {}
  // One period's Jacobian; `record` adds its growth to the kept sum.
  void Apply(const Mat2& J, bool record) {
    Mat2 next = J * m_;
    double norm = next.norm();
    double growth = std::log(norm);
    if (!(norm > 0)) {  // collapsed onto zero: count a factor DBL_EPSILON, reseed with J
      ++collapses_;
      growth = std::log(DBL_EPSILON);
      next = J;
      norm = next.norm();
      if (!(norm > 0)) next = Mat2::Identity(), norm = next.norm();
    }
    m_ = next / norm;
    if (!record) return;
    sums_[static_cast<size_t>(recorded_) * sums_.size() / keep_] += growth;
    ++recorded_;
  }
  // The exponent per unit time and the standard error of the batch means.
  void Result(double period, double* lambda, double* err) const {
    const int b = static_cast<int>(sums_.size());
    double total = 0;
    for (double s : sums_) total += s;
    *lambda = total / (recorded_ * period);
    *err = 0;
    if (b < 2) return;
    double var = 0;
    for (int i = 0; i < b; ++i) {
      const int n = (i + 1) * keep_ / b - i * keep_ / b;  // periods in batch i
      const double d = sums_[i] / (n * period) - *lambda;
      var += d * d;
    }
    *err = std::sqrt(var / (b - 1) / b);
  }
  int collapses() const { return collapses_; }

 private:
  int keep_;
  std::vector<double> sums_;
  Mat2 m_ = Mat2::Identity() / std::sqrt(2.0);
  int recorded_ = 0, collapses_ = 0;
};

}  // namespace

StroboscopicRun IterateStroboscopic(const ForcedModel& model, const FlowPoint& start,
                                    const LyapunovOptions& options,
                                    const std::function<bool()>& cancelled, double max_amplitude) {
  const std::string e = options.ValidationError();
  if (!e.empty()) throw InvalidArgument(e);
  // A flow of its own: `cancelled` may run another forced tool on this thread.
  Flow flow(model, options.flow);
  const double T = model.period(), w = model.omega();
  StroboscopicRun run;
  run.points.reserve(options.keep);
  TangentProduct tangent(options.keep, options.batches);
  std::vector<FlowSwitch> switches;
  FlowRequest rq;
  rq.max_steps = options.flow.max_steps;
  FlowRun r;
  // Each period starts again at phase 0 (t = theta = 0: the field is T-periodic).
  FlowPoint z = ForcedStart(model, 0, start.z[0], start.z[1], start.mode[0]);
  const int total = options.transient + options.keep;
  for (int k = 0; k < total; ++k) {
    if (cancelled && cancelled()) {
      run.status = LyapunovStatus::kCancelled;
      run.message = "cancelled after " + std::to_string(k) + " periods";
      break;
    }
    const bool kept = k >= options.transient;
    rq.t_max = T;
    rq.variational = options.exponent && k >= options.transient - options.align;
    switches.clear();
    rq.switches = kept ? &switches : nullptr;
    flow.Run(z, rq, &r);
    run.steps += r.steps;
    if (!Reached(r)) {
      run.status = LyapunovStatus::kFlowFailed;
      run.message = r.message + " (period " + std::to_string(k) + ")";
      break;
    }
    if (!(std::abs(r.end.z[0]) <= max_amplitude && std::abs(r.end.z[1]) <= max_amplitude)) {
      run.status = LyapunovStatus::kDiverged;  // end: the last state within bounds
      run.message = "|x| or |x'| passed " + Num(max_amplitude) + " in period " + std::to_string(k);
      break;
    }
    z = ForcedStart(model, 0, r.end.z[0], r.end.z[1], r.end.mode[0]);
    if (rq.variational) tangent.Apply(r.jacobian, kept);
    if (!kept) continue;
    SectionPoint p;
    p.x = z.z[0], p.xdot = r.end.z[1], p.mode = z.mode[0];
    p.sticks = r.sticks, p.exits = r.exits;
    for (const FlowSwitch& ev : switches)
      if (ev.kind == SwitchKind::kStickOut) {
        p.first_exit_phase = static_cast<float>(std::fmod(w * ev.t, 2 * M_PI));
        break;
      }
    run.points.push_back(p);
  }
  run.end = z;
  run.collapses = tangent.collapses();
  if (run.status == LyapunovStatus::kDone && options.exponent)
    tangent.Result(T, &run.lyapunov, &run.lyapunov_err);
  return run;
}

}  // namespace stickslip
