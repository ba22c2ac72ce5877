// ss_continue for a built-in system other than the belt (system_choice.hpp;
// docs/systems.md): steady sliding along --param with its HB and LP points,
// the stick-slip attractor a run settles on at --start_at, and its branch
// traced to --to and back to --from on the one branch driver, written as
// branch.tsv, special_points.tsv and bifurcation.gp through the one output
// path.
#pragma once

#include <string>

#include "cli/study.hpp"

namespace stickslip::cli {

// ss_continue's options for such a run: --start_at, --transient, --disturbance.
po::options_description SystemRunOptions();
// The run; returns the exit code. Throws UsageError on bad input.
int RunSystem(const Arguments& args, const std::string& prog, const std::string& command);

}  // namespace stickslip::cli
