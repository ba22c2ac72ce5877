// Where a branch of a system with no clock starts when a start list is asked
// for (ss_continue --all, --point N without --restart; docs/systems.md): the
// orbits FindAutonomousOrbits (orbit_search.hpp) finds at the start point,
// from steady sliding moved along each of its modes, numbered by period.
// --all starts one branch on each, --point N on orbit N.
#pragma once

#include <iosfwd>
#include <string>
#include <vector>

#include "cli/clock_start.hpp"
#include "cli/run_control.hpp"
#include "stickslip/continuation/orbit_branch.hpp"
#include "stickslip/orbits/settle.hpp"

namespace stickslip::cli {

struct AutonomousStart {
  SettledOrbit orbit;       // its section point and section (StickExit(contact, returns))
  std::vector<int> sticks;  // stick phases per period, per contact
  bool stable = false;
  double mult_max = 0;  // the largest |multiplier|
};

// The scan's orbits at `at`'s parameters within opts.max_amplitude (the
// first component's maximum), by period.
std::vector<AutonomousStart> AutonomousStartOrbits(const System& at, const OrbitBranchOptions& opts,
                                                   RunControl& run);

// The start list printed on os and the orbits the choice selects (--all:
// each; --point N: orbit N, else UsageError naming --point and the list's
// size).
std::vector<SettledOrbit> ChosenAutonomousStarts(const System& at, const OrbitBranchOptions& opts,
                                                 const StartChoice& choice,
                                                 const std::string& where, std::ostream& os,
                                                 RunControl& run);

// "start orbits at v = 0.3 (--point N continues orbit N):" and a line each.
void PrintAutonomousStarts(std::ostream& os, const std::vector<AutonomousStart>& list,
                           const std::string& where);

}  // namespace stickslip::cli
