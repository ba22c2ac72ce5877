// ss_basin on a Poincare section, through the one classifier
// (basin/attractors.hpp): the harmonically forced oscillator (--force A
// --omega W: starts (x, x') at forcing phase 0, written as basins_forced.*)
// and every --system (starts on a 2-D slice through steady sliding, returns
// to the first velocity's zero falling, written as basins.*), each with
// attractors.tsv and the basin figure.
#pragma once

#include <boost/program_options.hpp>
#include <string>

#include "cli/study.hpp"

namespace stickslip::cli {

// --transient --keep --max_period --threads --slice (the section path's own options).
po::options_description SectionBasinOptionGroup();
// UsageError naming the first of --x_min --x_max --xdot_min --xdot_max given
// beyond +-1e6 (BasinOptions / AttractorOptions::kMaxCorner), for both paths.
void CheckBoxCorners(const Arguments& args);
// The whole run; returns the exit code.
int RunSectionBasin(const Arguments& args, const std::string& prog, const std::string& command);

}  // namespace stickslip::cli
