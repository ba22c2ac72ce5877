// The smallest disturbance that tips steady sliding into oscillation, along a
// branch: for every unstable pure-slip row of a continuation result, the
// orbit's distance from (xbar, 0) in x, in x' and in energy
// (SmallestDisturbance in basin.hpp); ss_continue writes them as branch.tsv's
// dist_x, dist_xdot and dist_energy.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "stickslip/basin/basin.hpp"
#include "stickslip/continuation/continuation.hpp"

namespace stickslip {

// One disturbance per point of r, nan on rows that are not unstable pure-slip
// orbits (or where the orbit's run
// fails), 0 where such an orbit has amplitude 0 (its Hopf point). base is the model with the
// continued parameter r.param set per row. `cancelled` (if set) is polled per
// row and by the flow; once it is true the remaining rows are nan.
std::vector<Disturbance> BranchDisturbances(const Params& base, const ContinuationResult& r,
                                            const FlowOptions& flow,
                                            const std::function<bool()>& cancelled = {});

}  // namespace stickslip
