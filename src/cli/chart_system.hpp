// ss_chart for a built-in system other than the belt (system_choice.hpp;
// docs/systems.md, "Charts"): HB of steady sliding and LP, PD and NS of
// periodic orbits in two of the system's parameters (ChartSystem), written
// as curves.tsv, codim2.tsv and chart.gp through the one output path.
#pragma once

#include <string>

#include "cli/study.hpp"

namespace stickslip::cli {

// The run; returns the exit code. Throws UsageError on bad input.
int RunSystemChart(const Arguments& args, const std::string& prog, const std::string& command);

}  // namespace stickslip::cli
