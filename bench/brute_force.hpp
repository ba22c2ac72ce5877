// Brute force, the way a user without continuation works: simulate the exact
// Filippov model (stickslip::BeltFlow, event-driven CVODE) from rest, x = x' = 0,
// cycle by cycle until successive cycles agree, and measure the last cycle.
// A cycle runs from one maximum of x (x' = 0 downwards, the section of
// StopRule::at_section) to the next: one per cycle for stick-slip and for
// pure-slip orbits about steady sliding.
#pragma once

#include <string>

#include "stickslip/systems/belt/belt_flow.hpp"

namespace bench {

struct BruteOptions {
  stickslip::FlowOptions flow;
  // Stop when period (relative) and x_max (absolute) of two successive cycles
  // differ by at most this.
  double converge_tol = 1e-9;
  int min_cycles = 3;    // cycles measured before the test may stop the run
  double t_cap = 20000;  // give up converging here and report the last cycle
};

struct BruteCycle {
  bool ok = false;
  std::string message;
  bool converged = false;  // false: stopped by t_cap
  double period = 0, x_max = 0, x_min = 0, xdot_max = 0, t_stick = 0;
  double t_end = 0;  // simulated time
  int cycles = 0;
  long steps = 0;  // BeltFlow::total_steps()
};

BruteCycle BruteForce(const stickslip::Params& p, const BruteOptions& o);

}  // namespace bench
