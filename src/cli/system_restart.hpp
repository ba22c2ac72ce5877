// ss_continue --restart DIR --point LABEL where DIR is an earlier --system
// run (docs/systems.md, "Restarts"): the point's system, parameters and
// solver options become the defaults, and the run starts on its orbit.
#pragma once

#include <string>

#include "cli/about.hpp"
#include "cli/study.hpp"
#include "cli/system_choice.hpp"
#include "stickslip/io/system_restart.hpp"

namespace stickslip::cli {

// --restart and --point given, and DIR's file for the point is a system's.
bool SystemRestartRequested(const Arguments& args);

// The point; UsageError naming --restart or --point (a file missing,
// corrupt, too large or not regular; an unknown label, listing the labels;
// a point of steady sliding), or --system, --blocks where they contradict
// the run's.
SystemPoint SystemRestartFromArguments(const Arguments& args);

// "DIR point LP1 (pt 32, LP, mu_k = 0.52877)" for the metadata.
std::string DescribeSystemRestart(const Arguments& args, const SystemPoint& sp);

// The metadata a restart reads back (io/system_restart.cpp): system_name,
// blocks (a chain), law, law_parameters and parameters ("a=1,b=2"),
// integrator, max_steps, max_amplitude, and section_contact and
// section_returns where the run has a section.
void AddRestartMetadata(const System& s, SystemChoice choice, const Params& law,
                        const FlowOptions& flow, double max_amplitude,
                        const PoincareSection* section, Metadata& meta);

}  // namespace stickslip::cli
