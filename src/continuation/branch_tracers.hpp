// Internal to the continuation: the branch tracers, each of which follows one
// kind of solution and returns how it ended, and the switch at a grazing
// point, which the driver (continuation.cpp) calls between them.
#pragma once

#include <vector>

#include "continuation/branch_context.hpp"

namespace stickslip {

// Steady sliding on the grid from `from` to `to`, with its Hopf points
// located (recorded in the context and as special points) and their rows.
std::vector<BranchPoint> TraceEquilibrium(BranchContext& ctx);

// Stick-slip orbits are unique for given parameters (the return map on Omega
// is constant, seed case 1): natural steps in p with an adaptive size. Ends
// at the range end, at a grazing point, or stopped.
BranchEnd TraceStickSlip(BranchContext& ctx, const BranchStart& start);

// Pure-slip orbits by pseudo-arclength continuation of G(a, p) = 0. Ends at
// the range end, at a Hopf point, at a grazing point, or stopped.
BranchEnd TracePureSlip(BranchContext& ctx, const BranchStart& start);

// A pure-slip step from p sticks: a grazing point ahead in direction dp_sign,
// searched within kSearchSteps steps growing from `step`, located by Brent.
bool GrazingAhead(BranchContext& ctx, double p, double dp_sign, double step, double* p_gr);

// At a grazing point the stick phase has length zero: records GR (and LP if
// the branch turns back there) and the grazing row, and returns where the
// other kind of orbit continues (phase kNone: nowhere).
BranchStart SwitchAtGrazing(BranchContext& ctx, const BranchEnd& end);

}  // namespace stickslip
