// The orbit diagram of any system (issue 21 item 1, issue 32 item 3): for
// each value of one parameter, the section points of its Poincare map after a
// transient (a forced system's stroboscopic map, an autonomous system's
// returns to a surface), the stick counts and exit phases, and the largest
// Lyapunov exponent (chaos/lyapunov.hpp). Swept up and down, each value starting from
// the last state of the one before, so that hysteresis shows. The two
// directions (and, with chunks > 1, their pieces) are tasks of a pool of at
// most `threads` threads, capped by the hardware threads; no exception crosses
// a thread (a failure is the value's status).
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "stickslip/chaos/lyapunov.hpp"
#include "stickslip/names.hpp"
#include "stickslip/systems/belt/parameter_axis.hpp"
#include "stickslip/systems/forced/forced.hpp"

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
  /// A value whose state passes this is kDiverged; the next starts from rest.
  double max_amplitude = 50;
  /// An autonomous system's section (default MaximaSection); a forced
  /// system's is its stroboscopic map.
  std::optional<Section> surface;
  std::function<bool()> cancelled;                    ///< polled by the calling thread
  std::function<void(int done, int total)> progress;  ///< called on the calling thread
  /// Empty if valid, else one line naming the offending value.
  std::string ValidationError() const;
};

/// One parameter value of one sweep.
struct DiagramColumn {
  SweepDirection direction = SweepDirection::kUp;
  double value = 0;
  SectionRun run;         ///< kRest: settled on steady sliding, its one point in run.points
  bool computed = false;  ///< false: not reached (cancelled)
  bool settled() const {
    return run.status == LyapunovStatus::kDone || run.status == LyapunovStatus::kRest;
  }
};

struct OrbitDiagram {
  std::vector<DiagramColumn> columns;  ///< the up sweep, then the down sweep
  int failed = 0;                      ///< computed values neither kDone, kRest nor kContactOpen
  /// Computed values whose run lost contact (kContactOpen: the model ends
  /// there, an outcome, not a failure); they have no section points.
  int contact_lost = 0;
  int threads = 0;    ///< worker threads that ran
  std::string error;  ///< not empty: no worker thread could start (nothing computed)
  bool cancelled = false;
  double seconds = 0;  ///< wall time
  long steps = 0;
};

/// Parameter `parameter` of `base` (its index, System::ParameterIndex) swept
/// over from..to; each sweep starts from rest on the belt (every contact's
/// velocity on its surface, the rest 0). Throws InvalidArgument if the
/// options or the system at either end are not valid.
OrbitDiagram ComputeOrbitDiagram(const System& base, int parameter,
                                 const OrbitDiagramOptions& options);
/// The forced oscillator, options.axis swept (any of the law's, force, omega).
OrbitDiagram ComputeOrbitDiagram(const ForcedBeltParams& base, const OrbitDiagramOptions& options);

}  // namespace stickslip
