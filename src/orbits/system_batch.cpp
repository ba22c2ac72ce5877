#include "stickslip/orbits/system_batch.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>

#include "batch_rows.hpp"
#include "numerics/max_abs.hpp"
#include "numerics/numbers.hpp"
#include "numerics/tolerances.hpp"
#include "stickslip/errors.hpp"
#include "system_columns.hpp"

namespace stickslip {

namespace {

using batch_detail::SetRow;

// A row costs a transient and a Newton solve (about 0.1 ms): small blocks
// balance the workers, and a thread pays for its start within a block.
constexpr std::size_t kSystemBlockRows = 16;
constexpr std::size_t kSystemThreadRows = 32;
// Newton iterations from a run that did not recur (system_batch.hpp, step 3).
constexpr int kUnsettledNewton = 8;

OrbitStatus FromFlow(FlowStatus s) {
  return s == FlowStatus::kCancelled ? OrbitStatus::kCancelled : OrbitStatus::kIntegratorFailed;
}

// One worker's tools: the row's system, its shooting (prepared at the first
// row), a plain flow request for the transient and its last section points.
struct Worker {
  Worker(const System& b, const std::vector<SystemColumn>& c, const SystemBatchOptions& o,
         batch_detail::RowQueue& q)
      : base(b), columns(c), options(o), queue(q), ring(o.max_m + 1) {}
  const System& base;
  const std::vector<SystemColumn>& columns;
  const SystemBatchOptions& options;
  batch_detail::RowQueue& queue;
  std::unique_ptr<System> system = base.Clone();
  std::optional<Shooting> shooting;
  std::optional<Flow> settle;  // the transient's flow, at kSettleTolerance
  FlowRequest request;
  FlowRun run;
  std::vector<Eigen::VectorXd> ring;  // section point k at k % (max_m + 1)

  // A fixed point of P^m that is one of P^d, d | m (a slowly attracting
  // orbit whose run came closest after m periods): shot again with d.
  void LeastPeriod(double T, int* m, PoincareSection* section, PeriodicOrbit* o) {
    const int nt = system->tangent_dimension();
    const FlowPoint z = o->start;
    const double tol = Tolerances::kLeastPeriod * (1 + MaxAbs(z.z.head(nt)));
    for (int d = 1; d < *m; ++d) {
      if (*m % d != 0) continue;
      request.t_max = z.t + d * T;
      shooting->flow().Run(z, request, &run);
      if (run.status != FlowStatus::kTimeLimit ||
          !(MaxAbs(run.end.z.head(nt) - z.z.head(nt)) <= tol))
        continue;
      section->time = d * T;
      section->turns = d;
      PeriodicOrbit least = shooting->Find(z, *section);
      if (least.ok()) {
        *m = d;
        *o = std::move(least);
      }
      return;
    }
  }

  // Step 3: Newton on P^m from z (max_newton: fewer from a run that did
  // not recur, where a slowly attracting orbit is near); *m becomes the
  // orbit's least period.
  PeriodicOrbit Shoot(const FlowPoint& z, double T, int max_newton, int* m) {
    PoincareSection section;
    section.time = *m * T;
    section.turns = *m;
    shooting->set_max_newton(max_newton);
    PeriodicOrbit o = shooting->Find(z, section);
    if (o.ok() && *m > 1) LeastPeriod(T, m, &section, &o);
    return o;
  }

  void Store(const PeriodicOrbit& o, int m, double T, std::size_t i, SystemBatch& out) const {
    out.status[i] = o.status;
    if (!o.ok()) return;
    out.m[i] = m;
    out.period[i] = m * T;
    batch_detail::StoreOrbit(o, i, out);
  }

  // Steps 1-3 of system_batch.hpp, period by period: the first section point
  // that recurs within max_m periods is shot; before `transient` periods
  // only a stable orbit is taken (an attractor reached early), after them any.
  void Settled(FlowPoint z, double T, std::size_t i, SystemBatch& out) {
    const int nt = system->tangent_dimension(), rows = options.max_m + 1;
    const int newton = options.shooting.max_newton;
    FlowPoint anchor;  // the point after `transient` periods
    double closest = std::numeric_limits<double>::infinity();
    int closest_m = options.max_m;
    ring[0] = z.z.head(nt);
    for (int k = 1; k <= options.transient + options.max_m; ++k) {
      request.t_max = k * T;
      settle->Run(z, request, &run);
      if (run.status != FlowStatus::kTimeLimit) {
        out.status[i] = FromFlow(run.status);
        return;
      }
      z = run.end;
      const Eigen::VectorXd& now = ring[k % rows] = z.z.head(nt);
      const double tol = options.recurrence * (1 + MaxAbs(now));
      int m = 0;
      for (int d = 1; d <= std::min(options.max_m, k) && m == 0; ++d)
        if (MaxAbs(now - ring[(k - d) % rows]) <= tol) m = d;
      if (k == options.transient) anchor = z;
      if (k > options.transient) {
        const double d = MaxAbs(now - anchor.z.head(nt));
        if (d < closest) closest = d, closest_m = k - options.transient;
      }
      if (m == 0) continue;
      const PeriodicOrbit o = Shoot(z, T, newton, &m);
      if (k >= options.transient || (o.ok() && o.stable) || o.status == OrbitStatus::kCancelled) {
        Store(o, m, T, i, out);
        return;
      }
    }
    // No recurrence: the orbit Newton finds near the run is its attractor
    // only if it is stable (a slowly attracting one), else the run is aperiodic.
    const PeriodicOrbit o = Shoot(anchor, T, std::min(newton, kUnsettledNewton), &closest_m);
    Store(o, closest_m, T, i, out);
    if (o.status != OrbitStatus::kCancelled && !(o.ok() && o.stable)) {
      out.status[i] = OrbitStatus::kAperiodic;
      out.m[i] = 0;
      out.sticks[i] = 0;
      out.period[i] = out.multiplier[i] = 0;
      out.stable[i] = 0;
      for (int c = 0; c < nt; ++c)
        out.start[i * nt + c] = out.lo[i * nt + c] = out.hi[i * nt + c] = 0;
    }
  }

  void Row(std::size_t i, SystemBatch& out) {
    SetRow(columns, i, *system);
    if (shooting) {
      shooting->set_system(*system);
      settle->set_system(*system);
    } else {
      shooting.emplace(*system, options.shooting);
      shooting->flow().set_cancel([this] { return queue.Cancelled(); });
      request.max_steps = options.shooting.max_steps;
      // The transient only has to find the attractor to recurrence's 1e-3:
      // a lower Taylor order there (Newton then works at full accuracy).
      FlowOptions loose = options.shooting.flow;
      loose.rtol = std::max(loose.rtol, Tolerances::kSettle);
      loose.atol = std::max(loose.atol, Tolerances::kSettle);
      settle.emplace(*system, loose);
      settle->set_cancel([this] { return queue.Cancelled(); });
    }
    const FlowPoint z{0, options.start, ModeOf(*system, options.start)};
    const double T = PoincareSection::Stroboscopic(*system, z.z, 1).time;
    if (options.transient > 0) return Settled(z, T, i, out);
    int m = options.max_m;
    const PeriodicOrbit o = Shoot(z, T, options.shooting.max_newton, &m);
    Store(o, m, T, i, out);
  }

  void Work(SystemBatch& out) {
    for (std::size_t begin, end; queue.Take(&begin, &end);) {
      for (std::size_t i = begin; i < end && !queue.Cancelled(); ++i) Row(i, out);
      queue.Done(end - begin);
    }
  }
};

}  // namespace

std::string SystemBatchOptions::ValidationError() const {
  std::string err = shooting.ValidationError();
  if (!err.empty()) return err;
  if (transient < 0 || transient > kMaxTransient)
    return "transient = " + std::to_string(transient) + " must be in [0, " +
           std::to_string(kMaxTransient) + "]";
  if (max_m < 1 || max_m > kMaxMultiple)
    return "max_m = " + std::to_string(max_m) + " must be in [1, " + std::to_string(kMaxMultiple) +
           "]";
  if (!(recurrence > 0 && recurrence < 1))
    return "recurrence = " + Num(recurrence) + " must be in (0, 1)";
  if (!start.allFinite()) return "the start has a component that is not finite";
  if (threads < 0) return "threads = " + std::to_string(threads) + " must be >= 0";
  return "";
}

std::size_t SystemBatch::found() const {
  return static_cast<std::size_t>(std::count(status.begin(), status.end(), OrbitStatus::kOk));
}

SystemBatch StroboscopicOrbits(const System& base, const std::vector<SystemColumn>& columns,
                               const SystemBatchOptions& options) {
  std::string err = options.ValidationError();
  if (err.empty()) err = base.ValidationError();
  if (err.empty() && base.clocks() != 1)
    err = "a stroboscopic section needs a system with one clock, not " +
          std::to_string(base.clocks());
  SystemBatchOptions o = options;
  if (err.empty()) err = batch_detail::StartError(base, &o.start);
  return batch_detail::RunColumns(
      base, columns, err, kSystemBlockRows, kSystemThreadRows, o.threads, o.cancelled, o.progress,
      [&](batch_detail::RowQueue& q, SystemBatch& out) { Worker(base, columns, o, q).Work(out); });
}

}  // namespace stickslip
