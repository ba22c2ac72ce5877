// ss_simulate's shared range options and the forced oscillator's inputs
// (--force A --omega W); its trajectory is drawn by the one system path
// (simulate_system.hpp), its orbit list by ForcedOrbitsApp.
#pragma once

#include <boost/program_options.hpp>
#include <string>

#include "cli/study.hpp"
#include "stickslip/io/report.hpp"
#include "stickslip/systems/forced/flow.hpp"

namespace stickslip::cli {

// x0, xdot0, t_end, dt: validated once (UsageError naming the option).
struct SimulateRange {
  static constexpr long kMaxRows = 10000000;  // rows are held in memory until the atomic write
  double x0 = 0, xdot0 = 0, t_end = 100, dt = 0.01;
  long max_rows = kMaxRows;  // --max_rows: rows at switches and section points count too
};
SimulateRange SimulateRangeFromArguments(const Arguments& args, double default_xdot0);
void AddRangeMeta(TsvTable& table, const SimulateRange& r);

// The forced model and its flow options from --force, --omega, the model and
// solver options (validated: UsageError naming the option). `shown` is what
// the metadata prints.
struct ForcedInputs {
  ForcedBeltParams p;
  FlowOptions flow = ForcedBelt::FlowDefaults();
  FlowOptions shown;
};
ForcedInputs ForcedInputsFromArguments(const Arguments& args);

// --section strobe|exit|none, --orbits, --max_m.
void AddSimulateForcedOptions(po::options_description& d);
// ss_simulate --force --orbits: every periodic orbit at one parameter point
// (forced_orbits.cpp); returns the exit code.
int ForcedOrbitsApp(const Arguments& args, const std::string& prog, const std::string& command);

}  // namespace stickslip::cli
