// A labelled point of an earlier ss_continue run, read back from its output
// directory (branch.tsv, special_points.tsv and their '# key: value' lines), so
// a new run can start there: AUTO-07p's IRS (restart label).
#pragma once

#include <limits>
#include <string>

#include "stickslip/errors.hpp"
#include "stickslip/systems/belt/belt_flow.hpp"
#include "stickslip/systems/belt/parameter_axis.hpp"
#include "stickslip/systems/belt/params.hpp"

namespace stickslip {

/// The point, with everything a new run needs to start from it.
struct LabelledPoint {
  // m's upper bound a forced point is read with (a sanity bound on the file).
  static constexpr int kMaxM = 1000;
  // The largest branch.tsv or special_points.tsv read (64 MiB); larger is refused.
  static constexpr long long kMaxFileBytes = 64LL << 20;

  std::string label;  // "HB1", "GR1", ..., or the point number as given ("17")
  int pt = 0;         // its row in branch.tsv (1-based)
  std::string type;   // GR, HB, LP, or the row's kind: stick-slip, pure-slip, equilibrium
  // The parameter that run continued (a forced run's: the law's, force or omega).
  ParameterAxis param = Parameter::kV;
  double p = 0;               // its value at the point
  Params params;              // every parameter at the point (the continued one = p)
  FlowOptions flow;           // that run's integrator and tolerances
  Vec2 state = Vec2::Zero();  // x_start, xdot_start (BranchPoint / SpecialPoint)
  double period = 0;          // nan for steady sliding
  // A forced run's point (ss_continue --force): its forcing, and state is the
  // stroboscopic point (x0, xdot0) at theta = 0 of its m-periodic orbit.
  bool forced = false;
  double force = 0, omega = 1;
  int m = 1;
  // That run's range of param (its --from and --to), nan where not recorded.
  double run_from = std::numeric_limits<double>::quiet_NaN();
  double run_to = std::numeric_limits<double>::quiet_NaN();

  /// The continued parameter's name as the run's files print it ("v", "omega").
  std::string ParamName() const { return param.name(); }
};

/// Why a restart cannot be read: the run directory (a file missing, corrupt,
/// not an ss_continue run) or the point (no such label or number in that run).
class RestartError : public InvalidArgument {
 public:
  enum class Part { kRun, kPoint };
  RestartError(Part part, const std::string& what) : InvalidArgument(what), part_(part) {}
  Part part() const { return part_; }

 private:
  Part part_;
};

/// The tool name of files the Python module writes (Branch.save): read as
/// ss_continue's.
inline constexpr const char* kPythonTool = "stickslip.continue_branch";

/// Reads `point` (a label such as "HB1" or "PD1", or a point number "17" of branch.tsv)
/// from the run in `dir`. Throws RestartError naming the file or the point.
LabelledPoint ReadLabelledPoint(const std::string& dir, const std::string& point);

}  // namespace stickslip
