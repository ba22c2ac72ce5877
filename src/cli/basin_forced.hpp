// ss_basin for the harmonically forced oscillator:
// --force A --omega W classifies a grid of starts (x, x') at forcing phase 0
// by the attractor they reach (basin/attractors.hpp), written as
// basins_forced.tsv, attractors.tsv and the basin figure.
#pragma once

#include <boost/program_options.hpp>
#include <string>

#include "cli/study.hpp"

namespace stickslip::cli {

// --transient --keep --max_period (the forced path's own options).
po::options_description ForcedBasinOptionGroup();
// UsageError naming the first of --x_min --x_max --xdot_min --xdot_max given
// beyond +-1e6 (BasinOptions / AttractorOptions::kMaxCorner), for both paths.
void CheckBoxCorners(const Arguments& args);
// The whole forced run; returns the exit code.
int RunForcedBasin(const Arguments& args, const std::string& prog, const std::string& command);

}  // namespace stickslip::cli
