// Periodic orbits of any system (system.hpp) at many parameter points, in
// columns: a base system, columns of values for some of its parameters by
// index (System::ParameterIndex: the index is the lens; row i is the base
// with every column's value i), and at every row the orbit the one shooting
// (shooting.hpp) finds on the stroboscopic section of the system's clock:
//  1. from `start` at t = 0, `transient` clock periods of the flow (onto an
//     attractor);
//  2. the section points of max_m more periods; m is the least with
//     |z_m - z_0| <= recurrence (1 + |z_0|) (max norm on the tangent block);
//     if none recurs, m is the one that comes closest;
//  3. Newton on P^m from z_0 (Shooting::Find): the exact orbit, its Floquet
//     multipliers, sticks and extremes. Where no m recurred, only a stable
//     orbit is taken (a slowly attracting one); else the row is kAperiodic
//     (chaotic, quasi-periodic, or a period above max_m). transient = 0
//     skips 1-2: Newton on P^max_m from `start`.
// The belt's stick-slip orbits have their own fast path (orbit_batch.hpp).
//
// Each worker thread prepares one Shooting and one copy of the base system
// and hands it each row's parameters, so a row equals a fresh Shooting's bit
// for bit, whatever the thread count. No exception per point: a row that has
// no orbit keeps its status. Rows are taken in blocks from a shared counter by
// at most `threads` workers of the bounded pool (parallel/pool.hpp).
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "stickslip/orbits/shooting.hpp"

namespace stickslip {

/// One column: a parameter by its System index and its value at every row.
struct SystemColumn {
  int parameter = 0;
  std::vector<double> values;
};

struct SystemBatchOptions {
  /// Upper bounds of transient and max_m.
  static constexpr int kMaxTransient = 1000000, kMaxMultiple = 64;
  ShootingOptions shooting;
  /// The start at t = 0 (dimension() entries, the clock's phase last); empty:
  /// the origin.
  Eigen::VectorXd start;
  int transient = 20;        ///< clock periods integrated before the search
  int max_m = 4;             ///< periods tried (transient = 0: Newton on P^max_m)
  double recurrence = 1e-3;  ///< step 2's tolerance, relative (0 < r < 1)
  /// Worker threads, capped by the hardware threads; 0: all of them.
  int threads = 0;
  /// Polled on the calling thread only: before any work, then before every
  /// row and at every step with one worker, or every 20 ms with more. Once it
  /// returns true the workers stop within one integration step; the row being
  /// computed and every row not reached are kCancelled. Empty: never.
  std::function<bool()> cancelled;
  /// Called on the calling thread with the rows done so far (every 20 ms with
  /// more than one worker, every block of rows with one). Empty: never.
  std::function<void(std::size_t done)> progress;
  /// Empty if valid, else one line naming the offending value.
  std::string ValidationError() const;
};

/// The result columns, one entry per row. A row whose status is not kOk
/// holds zeros in every number column and stable = 0 (never nan).
struct SystemBatch {
  int tangent = 0;  ///< tangent components per row of start, lo and hi
  std::vector<OrbitStatus> status;
  /// Section crossings per period: clock periods (StroboscopicOrbits) or
  /// stick exits of `contact` (SettledOrbits, settled_batch.hpp).
  std::vector<std::int32_t> m;
  /// The contact whose stick exit is the section; -1 on a stroboscopic one.
  std::vector<std::int32_t> contact;
  std::vector<std::int32_t> sticks;  ///< stick phases per period of the orbit
  std::vector<double> period;        ///< m periods of the clock
  /// Row-major, `tangent` per row: the orbit's point on the section (phase
  /// 0), and the extremes of each tangent component over one period.
  std::vector<double> start, lo, hi;
  std::vector<double> multiplier;    ///< the largest |Floquet multiplier|
  std::vector<std::uint8_t> stable;  ///< 1 where every |multiplier| < 1
  int threads = 0;                   ///< worker threads that ran
  bool cancelled = false;            ///< the cancel hook fired
  /// Non-empty if no worker thread could start, or a worker met an exception;
  /// the rows it did not finish stay kCancelled.
  std::string error;
  std::size_t rows() const { return status.size(); }
  std::size_t found() const;  ///< rows with status kOk
};

/// Throws InvalidArgument, before any work, naming the column (and row and
/// value) if: the options are invalid; base is invalid or has not one clock;
/// the start has another size; there is no column; a column's index is not
/// one of base's parameters or is given twice; the columns differ in length;
/// or a row's system is invalid (System::ValidationError). Zero rows: an
/// empty result.
SystemBatch StroboscopicOrbits(const System& base, const std::vector<SystemColumn>& columns,
                               const SystemBatchOptions& options);

}  // namespace stickslip
