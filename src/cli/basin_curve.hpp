// ss_basin --param NAME --from A --to B --n N: the exact basin stability
// (basin_stability.hpp) at N points of one parameter, in the box given by
// --x_min --x_max --xdot_min --xdot_max; basin_stability.tsv, .gp and .png.
#pragma once

#include <string>

#include "cli/about.hpp"
#include "cli/study.hpp"
#include "stickslip/basin/basin.hpp"

namespace stickslip::cli {

// --param, --from, --to, --n for the app's options_description.
void AddBasinCurveOptions(po::options_description& d);

// Validates those options (UsageError naming the option), computes the curve,
// writes the set into --out, prints one line per point; returns the exit code
// (0 done, 1 partial, interrupted, over max_time or figure failed). opts:
// the basin options as parsed (box, solver).
int RunBasinStabilityCurve(const std::string& prog, const Arguments& args, const Params& base,
                           const BasinOptions& opts, double max_time, const Metadata& meta);

}  // namespace stickslip::cli
