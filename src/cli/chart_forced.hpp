// ss_chart for the harmonically forced oscillator: the
// chart in two of omega, force, v, beta (--param, --param2) with the LP, PD,
// NS and GR curves, their codimension-two points and the response grid
// (stickslip/chart/forced_chart.hpp); curves.tsv, codim2.tsv, response.tsv
// and forced_chart.png through the one output path (cli/app.hpp).
#pragma once

#include <string>

#include "cli/study.hpp"

namespace stickslip::cli {

// True when ss_chart is asked for the forced oscillator: --force given, or an
// axis (--param, --param2) that is omega or force.
bool ForcedChartRequested(const Arguments& args);
// The whole forced chart run; returns the exit code.
int RunForcedChart(const Arguments& args, const std::string& prog, const std::string& command);

}  // namespace stickslip::cli
