// Batched settled stick-slip orbits of an autonomous system (settled_batch.hpp).
#include "stickslip/orbits/settled_batch.hpp"

#include <cmath>
#include <memory>

#include "batch_rows.hpp"
#include "stickslip/errors.hpp"
#include "system_columns.hpp"

namespace stickslip {

namespace {

// A row is a whole settling run (about a thousand steps): small blocks
// balance the workers.
constexpr std::size_t kSettledBlockRows = 4;
constexpr std::size_t kSettledThreadRows = 8;

OrbitStatus StatusOf(const SettledOrbit& r) {
  if (r.found) return OrbitStatus::kOk;
  switch (r.run) {
    case FlowStatus::kTimeLimit:
      break;
    case FlowStatus::kCancelled:
      return OrbitStatus::kCancelled;
    case FlowStatus::kContactOpen:
      return OrbitStatus::kContactOpen;
    default:
      return OrbitStatus::kIntegratorFailed;
  }
  if (r.recurred) return r.orbit.status;  // Newton's
  return r.stick_exits < 2 ? OrbitStatus::kNoReturn : OrbitStatus::kAperiodic;
}

void Store(const SettledOrbit& r, std::size_t i, SystemBatch& out) {
  out.status[i] = StatusOf(r);
  if (!r.found) return;
  const PeriodicOrbit& o = r.orbit;
  const int nt = out.tangent;
  out.m[i] = r.section.returns;
  out.contact[i] = r.section.contact;
  out.sticks[i] = o.sticks;
  out.period[i] = o.period;
  for (int c = 0; c < nt; ++c) {
    out.start[i * nt + c] = o.start.z[c];
    out.lo[i * nt + c] = o.lo.size() > c ? o.lo[c] : 0.0;
    out.hi[i * nt + c] = o.hi.size() > c ? o.hi[c] : 0.0;
  }
  out.multiplier[i] = o.multipliers.empty() ? 0.0 : std::abs(o.multipliers.front());
  out.stable[i] = o.stable ? 1 : 0;
}

void Work(const System& base, const std::vector<SystemColumn>& columns,
          const SettledBatchOptions& options, batch_detail::RowQueue& queue, SystemBatch& out) {
  const std::unique_ptr<System> system = base.Clone();
  SettleOptions settle = options.settle;
  settle.cancelled = [&queue] { return queue.Cancelled(); };
  for (std::size_t begin, end; queue.Take(&begin, &end);) {
    for (std::size_t i = begin; i < end && !queue.Cancelled(); ++i) {
      batch_detail::SetRow(columns, i, *system);
      const Eigen::VectorXd start = options.start.size() ? options.start
                                    : options.start_of   ? options.start_of(*system)
                                                       : Eigen::VectorXd::Zero(system->dimension());
      if (start.size() != system->dimension() || !start.allFinite()) {  // start_of's
        out.status[i] = OrbitStatus::kIntegratorFailed;
        continue;
      }
      Store(SettleOnStickSlip(*system, start, settle), i, out);
    }
    queue.Done(end - begin);
  }
}

}  // namespace

std::string SettledBatchOptions::ValidationError() const {
  std::string err = settle.ValidationError();
  if (err.empty() && !start.allFinite()) err = "the start has a component that is not finite";
  if (err.empty() && threads < 0) err = "threads = " + std::to_string(threads) + " must be >= 0";
  return err;
}

SystemBatch SettledOrbits(const System& base, const std::vector<SystemColumn>& columns,
                          const SettledBatchOptions& options) {
  std::string err = options.ValidationError();
  if (err.empty()) err = base.ValidationError();
  if (err.empty() && base.clocks() != 0)
    err = "a system with a clock settles on its stroboscopic section: StroboscopicOrbits";
  SettledBatchOptions o = options;
  if (err.empty() && o.start.size() && o.start.size() != base.dimension())
    err = "the start has " + std::to_string(o.start.size()) + " components, the system " +
          std::to_string(base.dimension());
  if (err.empty()) err = batch_detail::ColumnError(base, columns);
  const std::size_t rows = columns.empty() ? 0 : columns[0].values.size();
  if (err.empty()) err = batch_detail::RowError(base, columns, rows);
  if (!err.empty()) throw InvalidArgument(err);
  SystemBatch out = batch_detail::Sized(rows, base.tangent_dimension());
  if (rows == 0) return out;
  if (o.cancelled && o.cancelled()) {
    out.cancelled = true;
    return out;
  }
  batch_detail::RowQueue queue(rows, kSettledBlockRows);
  const batch_detail::RowsRun run =
      batch_detail::RunRows(queue, o.threads, kSettledThreadRows, o.cancelled, o.progress,
                            [&](batch_detail::RowQueue& q) { Work(base, columns, o, q, out); });
  out.threads = run.threads;
  out.error = run.error;
  out.cancelled = run.cancelled;
  return out;
}

}  // namespace stickslip
