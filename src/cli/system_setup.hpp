// ss_continue --system's inputs (run_system.hpp), validated once at entry:
// the system at --from, the range, --start_at, a restart's point and the
// branch and settling options. UsageError naming the option otherwise.
#pragma once

#include <memory>
#include <optional>

#include "cli/clock_start.hpp"
#include "cli/study.hpp"
#include "cli/system_choice.hpp"
#include "cli/system_restart.hpp"
#include "stickslip/continuation/orbit_branch.hpp"
#include "stickslip/orbits/settle.hpp"

namespace stickslip::cli {

struct SystemSetup {
  std::unique_ptr<System> system;  // at --from
  SystemChoice choice = SystemChoice::kChain;
  Params law;  // the contacts' law, as given
  std::optional<SystemPoint> restart;
  bool doubled = false;  // --switch: the period-doubled branch from a PD point
  int param = 0;
  double from = 0, to = 0, start_at = 0, max_step = 0.01, disturbance = 0.01;
  double max_amplitude = OrbitBranchOptions().max_amplitude;
  FlowOptions flow;
  SettleOptions settle;
  StartChoice start;  // a clock's --all, --m, --point (without --restart)
};

// The run's setup from the arguments (a restart's point read).
SystemSetup ConfigureSystemRun(const Arguments& args);

}  // namespace stickslip::cli
