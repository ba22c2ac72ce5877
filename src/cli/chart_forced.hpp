// ss_chart for the harmonically forced oscillator (ForcedBelt): the chart in
// two of its parameters (--param, --param2; default the (omega, force) map)
// with the LP, PD, NS and GR curves, their codimension-two points and a 40 x 40
// response grid, run as every system's chart (chart_system.hpp).
#pragma once

#include <string>

#include "cli/chart_system.hpp"

namespace stickslip::cli {

// True when ss_chart is asked for the forced oscillator: --force given, or an
// axis (--param, --param2) that is omega or force.
bool ForcedChartRequested(const Arguments& args);
// The forced oscillator's chart. Throws UsageError on bad input.
ChartJob ForcedChartJob(const Arguments& args, const std::string& prog, const std::string& command);

}  // namespace stickslip::cli
