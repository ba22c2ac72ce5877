// The orbit diagram of the forced oscillator (issue 21 item 1): for each
// value of one parameter, the stroboscopic map's section points after a
// transient, the stick counts and exit phases, and the largest Lyapunov
// exponent (chaos/lyapunov.hpp). Swept up and down, each value starting from
// the last state of the one before, so that hysteresis shows. The two
// directions (and, with chunks > 1, their pieces) are tasks of a pool of at
// most `threads` threads, capped by the hardware threads; no exception crosses
// a thread (a failure is the value's status).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "stickslip/chaos/lyapunov.hpp"
#include "stickslip/forced/branch.hpp"
#include "stickslip/names.hpp"

namespace stickslip {

enum class SweepDirection { kUp, kDown };
template <>
struct EnumNames<SweepDirection> {
  static constexpr NamedValue<SweepDirection> kTable[] = {
      {SweepDirection::kUp, "up"},
      {SweepDirection::kDown, "down"},
  };
};

struct OrbitDiagramOptions {
  /// n's upper bound (1e6 parameter values).
  static constexpr int kMaxValues = 1000000;
  /// Upper bound of n x keep x directions, the section points held in memory.
  static constexpr double kMaxPoints = 1e7;
  ParameterAxis axis = Parameter::kOmega;
  double from = 0.5, to = 2.5;
  int n = 200;  ///< parameter values, from..to inclusive
  bool up = true, down = true;
  LyapunovOptions iterate;
  /// Pieces each sweep is cut into, run in parallel: 1 (the default) follows
  /// every value from the one before; k > 1 starts each piece from rest, so
  /// hysteresis shows only within a piece (a single direction then uses more
  /// than one core).
  int chunks = 1;
  /// Worker threads, capped by the hardware threads; 0: all of them.
  int threads = 0;
  /// A value whose |x| or |x'| passes this is kDiverged; the next starts from rest.
  double max_amplitude = 50;
  std::function<bool()> cancelled;                    ///< polled by the calling thread
  std::function<void(int done, int total)> progress;  ///< called on the calling thread
  /// Empty if valid, else one line naming the offending value.
  std::string ValidationError() const;
};

/// One parameter value of one sweep.
struct DiagramColumn {
  SweepDirection direction = SweepDirection::kUp;
  double value = 0;
  SectionRun run;
  bool computed = false;  ///< false: not reached (cancelled)
};

struct OrbitDiagram {
  std::vector<DiagramColumn> columns;  ///< the up sweep, then the down sweep
  int failed = 0;                      ///< computed values whose status is not kDone
  int threads = 0;                     ///< worker threads that ran
  std::string error;  ///< not empty: no worker thread could start (nothing computed)
  bool cancelled = false;
  double seconds = 0;  ///< wall time
  long steps = 0;
};

/// Throws InvalidArgument if the options or the model at either end are not valid.
OrbitDiagram ComputeOrbitDiagram(const ForcedParams& base, const OrbitDiagramOptions& options);

}  // namespace stickslip
