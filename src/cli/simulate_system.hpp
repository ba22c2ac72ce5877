// ss_simulate for a built-in system other than the belt (system_choice.hpp;
// docs/systems.md): one trajectory of the one flow from --state (default:
// steady sliding with the first component moved by 0.01), written as
// trajectory.tsv (t, every state component, the mode of every contact) and
// drawn as trajectory.png through the one output path.
#pragma once

#include <string>

#include "cli/study.hpp"

namespace stickslip::cli {

// ss_simulate's --state option.
void AddSimulateSystemOptions(po::options_description& d);
// The run; returns the exit code. Throws UsageError on bad input.
int SimulateSystemApp(const Arguments& args, const std::string& prog, const std::string& command);

}  // namespace stickslip::cli
