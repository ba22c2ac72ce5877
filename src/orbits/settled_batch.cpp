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
  out.m[i] = r.section.returns;
  out.contact[i] = r.section.contact;
  out.period[i] = r.orbit.period;
  batch_detail::StoreOrbit(r.orbit, i, out);
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
  if (err.empty() && options.start.size() && options.start.size() != base.dimension())
    err = "the start has " + std::to_string(options.start.size()) + " components, the system " +
          std::to_string(base.dimension());
  return batch_detail::RunColumns(
      base, columns, err, kSettledBlockRows, kSettledThreadRows, options.threads, options.cancelled,
      options.progress,
      [&](batch_detail::RowQueue& q, SystemBatch& out) { Work(base, columns, options, q, out); });
}

}  // namespace stickslip
