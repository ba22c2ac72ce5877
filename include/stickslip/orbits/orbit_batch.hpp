// Stick-slip orbits of the belt model at many parameter points, in columns:
// a base parameter set, columns of values for some of its parameters (row i
// is the base with every column's value i), and one stick-slip orbit per row
// (OrbitFinder::StickSlip(true): the return map of Omega is constant, seed
// case 1, so one slip integration from the exit point decides; a slip phase
// whose first return misses Omega is kMissed, the orbit of a sweep that makes
// more than one revolution before it sticks is not sought).
//
// Each worker thread prepares one OrbitFinder and hands it each row's model
// (set_model), so a row equals a fresh finder's StickSlip(true) bit for bit,
// whatever the thread count. No exception per point: a row that has no orbit
// keeps its status. Rows are taken in blocks of 64 from a shared counter by at
// most `threads` workers of the bounded pool (parallel/pool.hpp), one per 256
// rows at most; one worker runs on the calling thread.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "stickslip/orbits/orbit.hpp"
#include "stickslip/systems/belt/parameter_axis.hpp"

namespace stickslip {

/// One column: a parameter of the base's law and its value at every row.
struct ParameterColumn {
  ParameterAxis parameter;
  std::vector<double> values;
};

struct OrbitBatchOptions {
  /// Integration settings; orbit.floquet asks for the multiplier column
  /// (variational equations, about 1.5 x the time of a row).
  OrbitOptions orbit;
  /// Worker threads, capped by the hardware threads; 0: all of them.
  int threads = 0;
  /// Polled on the calling thread only (so it needs no locking): once before
  /// any work; with one worker (threads = 1, or at most 256 rows) the rows run
  /// on the calling thread, which polls it before every row and at every
  /// integration step; with more, every 20 ms while the workers run. Once it
  /// returns true the workers stop within one integration step; the row being
  /// integrated and every row not reached are kCancelled. Empty: never.
  std::function<bool()> cancelled;
  /// Empty if valid, else one line naming the offending value.
  std::string ValidationError() const;
};

/// The result columns, one entry per row. A row whose status is not kOk
/// holds zeros in every number column and stable = 0 (never nan): its status
/// says why (kMissed: the first return stays below the belt speed, no
/// stick-slip orbit here; kNoReturn, kIntegratorFailed; kCancelled).
struct OrbitBatch {
  std::vector<OrbitStatus> status;
  std::vector<double> period;   ///< slip time + t_stick
  std::vector<double> t_stick;  ///< stick time (x0 - x_a) / v, seed eq. (3.6)
  std::vector<double> x_min, x_max, xdot_min, xdot_max;  ///< extremes over one period
  /// The nontrivial Floquet multiplier (with floquet; else 0: the stick-slip
  /// orbit is superstable).
  std::vector<double> multiplier;
  std::vector<std::uint8_t> stable;  ///< 1 where the orbit is stable
  int threads = 0;                   ///< worker threads that ran
  bool cancelled = false;            ///< the cancel hook fired
  /// Non-empty if no worker thread could start, or a worker met an exception;
  /// the rows it did not finish stay kCancelled.
  std::string error;
  std::size_t rows() const { return status.size(); }
  /// Rows with status kOk.
  std::size_t found() const;
};

/// Throws InvalidArgument, before any work, naming the column (and row and
/// value) if: the options are invalid; there is no column; two columns name the
/// same parameter; a column's parameter does not apply to base's law;
/// the columns differ in length; or a row's parameter set is invalid
/// (ValidationError(Params), as Model checks it). Zero rows: an empty result.
OrbitBatch StickSlipOrbits(const Params& base, const std::vector<ParameterColumn>& columns,
                           const OrbitBatchOptions& options);

}  // namespace stickslip
