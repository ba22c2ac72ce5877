// A point of an earlier `ss_continue --system` run (chain, mode_coupling;
// docs/systems.md), read back from its branch.tsv or special_points.tsv (the
// '# key: value' lines and the point's row), so a new run starts on that
// orbit with no settling: AUTO-07p's IRS for the systems. The system itself
// is built by the caller from the names and numbers here (the library does
// not know the built-in systems by name).
#pragma once

#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "stickslip/io/restart.hpp"
#include "stickslip/orbits/shooting.hpp"

namespace stickslip {

/// The point, with everything a new run needs to start from it.
struct SystemPoint {
  std::string label;   ///< "LP1", "GR1", ..., or the point number as given ("17")
  int pt = 0;          ///< its row in branch.tsv (1-based)
  std::string type;    ///< LP, GR, PD, ... or the row's kind (stick-slip, pure-slip)
  int branch = 0;      ///< the row's branch number (0: steady sliding)
  std::string system;  ///< the system's name: "chain", "mode_coupling"
  int blocks = 0;      ///< a chain's blocks (0 for other systems)
  Params law;          ///< the contacts' law with its coefficients
  /// Every parameter of the system by name, in the system's order, at the
  /// point (the continued one is p).
  std::vector<std::pair<std::string, double>> parameters;
  std::string continued;  ///< the parameter that run continued
  double p = 0;           ///< its value at the point
  FlowOptions flow;       ///< that run's integrator and tolerances
  double max_amplitude = 0;
  /// The section the branch was traced on: a stick exit, or a clock's m
  /// turns (kind kTime, turns m; its time is the system's at the point).
  PoincareSection section;
  FlowPoint start;   ///< the orbit's point on it, with its mode (contacts in order)
  int contacts = 0;  ///< the mode's contacts (the items of mode_0)
  double period = 0;
  /// That run's range (its --from and --to).
  double run_from = std::numeric_limits<double>::quiet_NaN();
  double run_to = std::numeric_limits<double>::quiet_NaN();
  /// At an LP: the side of p on which that run's rows next to it lie (1
  /// above, -1 below; 0 unknown), the side of the fold's branch.
  int fold_side = 0;
  /// Whether the point is an orbit (steady sliding's rows are not).
  bool periodic() const { return branch > 0; }
};

/// Whether the file `point` would be read from in `dir` (special_points.tsv
/// for a label, branch.tsv for a number) was written by a system's run (it
/// has a '# system:' line). False where it cannot be read: ReadSystemPoint
/// and ReadLabelledPoint say why.
bool IsSystemRun(const std::string& dir, const std::string& point);

/// Reads `point` (a label such as "LP1", or a point number "17" of
/// branch.tsv) from the system's run in `dir`. A number takes the type of a
/// special point at the same row (special_points.tsv's pt), so an LP is a
/// fold either way. Throws RestartError naming
/// the file (missing, corrupt, too large, not a regular file, not a system's
/// run) or the point (no such label or number: the message lists the labels).
SystemPoint ReadSystemPoint(const std::string& dir, const std::string& point);

}  // namespace stickslip
