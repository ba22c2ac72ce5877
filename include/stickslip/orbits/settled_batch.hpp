// Stick-slip orbits of any autonomous system (system.hpp) at many parameter
// points, in columns (system_batch.hpp's SystemColumn and SystemBatch): at
// every row the orbit a run from `start` settles on (SettleOnStickSlip,
// settle.hpp: a transient, the least recurring stick exit, Newton on that
// stick-exit section). A system with a clock takes StroboscopicOrbits
// instead. Each worker thread copies the base system once and hands it each
// row's parameters; a row equals SettleOnStickSlip on that row's system bit
// for bit, whatever the thread count. No exception per point: a row that has
// no orbit keeps its status.
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "stickslip/orbits/settle.hpp"
#include "stickslip/orbits/system_batch.hpp"

namespace stickslip {

struct SettledBatchOptions {
  /// The run's transient, longest recurrence and Newton's flow
  /// (settle.cancelled is not used: see `cancelled`).
  SettleOptions settle;
  /// The start of every row (dimension() entries); empty: start_of(the
  /// row's system), else the origin.
  Eigen::VectorXd start;
  /// Called on the worker threads, one row's system each (Python passes
  /// NearSteadySliding: steady sliding with its first component moved by
  /// 0.01, so that a chain of like blocks does not start in step). A start
  /// of another size or not finite makes the row kIntegratorFailed.
  std::function<Eigen::VectorXd(const System&)> start_of;
  /// Worker threads, capped by the hardware threads; 0: all of them.
  int threads = 0;
  /// Polled on the calling thread only, as SystemBatchOptions::cancelled.
  std::function<bool()> cancelled;
  /// Called on the calling thread with the rows done so far.
  std::function<void(std::size_t done)> progress;
  /// Empty if valid, else one line naming the offending value.
  std::string ValidationError() const;
};

/// The rows' statuses: kOk; kNoReturn where the run has fewer than two stick
/// exits (steady sliding, a pure-slip motion, or a stuck mass); kAperiodic
/// where no stick exit recurs within max_returns (chaos, a longer period, or
/// not settled); the flow's failure (kIntegratorFailed, kContactOpen,
/// kCancelled); or Newton's. SystemBatch::m is the section's returns (stick
/// exits of `contact` per period) and contact the contact whose exit is the
/// section; start is that exit. Throws InvalidArgument, before any work, as
/// StroboscopicOrbits does, and for a system with a clock.
SystemBatch SettledOrbits(const System& base, const std::vector<SystemColumn>& columns,
                          const SettledBatchOptions& options);

}  // namespace stickslip
