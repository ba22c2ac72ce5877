// --restart DIR --point LABEL: start a run from a labelled point of an earlier
// ss_continue run (AUTO-07p's IRS). The point's parameters and solver options
// become the defaults; options given on the command line (or study) override.
#pragma once

#include <optional>
#include <string>

#include "cli/study.hpp"
#include "stickslip/chart/chart.hpp"
#include "stickslip/io/restart.hpp"

namespace stickslip::cli {

// The two options, for an app's own options_description; `systems`: the
// app restarts --system runs too (ss_continue).
void AddRestartOptions(po::options_description& d, bool systems = false);

// The point if --restart was given, else nothing. Throws UsageError naming
// --restart or --point and the value (missing or corrupt files, an unknown
// label, --point without --restart, physical inputs beside --restart).
std::optional<LabelledPoint> RestartFromArguments(const Arguments& args);

// ss_chart's seed at a restart's GR or HB point, on plane pl of model base.
// Throws UsageError naming --point if it is no GR or HB point or lies outside.
ChartOptions::Seed ChartSeed(const Arguments& args, const LabelledPoint& lp, const Plane& pl,
                             const Params& base);

// "DIR point HB1 (pt 200, v = 0.44)" for the metadata.
std::string DescribeRestart(const Arguments& args, const LabelledPoint& lp);

}  // namespace stickslip::cli
