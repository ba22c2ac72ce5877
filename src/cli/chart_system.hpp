// ss_chart for any system but the belt (system_choice.hpp; docs/systems.md,
// "Charts"): HB of steady sliding and LP, PD, NS and GR of periodic orbits in
// two of the system's parameters (ChartSystem), and optionally the response
// grid (Responses), written as curves.tsv, codim2.tsv, response.tsv and
// chart.gp through the one output path. The forced oscillator's run
// (chart_forced.hpp) is one such chart with its own defaults.
#pragma once

#include <memory>
#include <string>

#include "cli/about.hpp"
#include "cli/study.hpp"
#include "stickslip/chart/response_grid.hpp"
#include "stickslip/chart/system_chart.hpp"

namespace stickslip::cli {

// --grid's largest side.
inline constexpr long kMaxChartGrid = 400;

// A chart to run, with its options validated.
struct ChartJob {
  std::unique_ptr<System> system;
  SystemChartOptions chart;
  ResponseOptions grid;  ///< n1 = 0: no grid
  std::string model;     ///< the system and its parameters, the axes "[axis]"
  std::string title;     ///< the figure's, in gnuplot's enhanced text
  Metadata meta;         ///< every file's header, before the range and status
};

// --max_amplitude (default `fallback`), finite and > 0; UsageError naming it otherwise.
double MaxAmplitudeFromArguments(const Arguments& args, double fallback);
// --max_step (default `fallback`) in [1 / kMaxCurvePoints, kMaxStepLimit];
// UsageError naming it otherwise.
double MaxStepFromArguments(const Arguments& args, double fallback);

// --system's chart (--param, --param2, --from .. --to2 required). Throws
// UsageError on bad input.
ChartJob SystemChartJob(const Arguments& args, const std::string& prog, const std::string& command);

// Runs the job (its cancel hooks then refer to this run: the job is spent);
// returns the exit code.
int RunChart(const Arguments& args, const std::string& prog, ChartJob job);

}  // namespace stickslip::cli
