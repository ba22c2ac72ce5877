// The smallest disturbance that tips steady sliding into oscillation, along a
// branch: for every unstable pure-slip row of a continuation result, the
// orbit's distance from (xbar, 0) in x, in x' and in energy
// (SmallestDisturbance in basin.hpp), as extra columns of branch.tsv.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "stickslip/continuation/continuation.hpp"
#include "stickslip/io/branch_report.hpp"

namespace stickslip {

// Columns dist_x, dist_xdot, dist_energy: one value per point of r, nan on
// rows that are not unstable pure-slip orbits (or where the orbit's run
// fails), 0 where such an orbit has amplitude 0 (its Hopf point). base is the model with the
// continued parameter r.param set per row. `cancelled` (if set) is polled per
// row and by the flow; once it is true the remaining rows are nan.
std::vector<ExtraColumn> DisturbanceColumns(const Params& base, const ContinuationResult& r,
                                            const FlowOptions& flow,
                                            const std::function<bool()>& cancelled = {});

}  // namespace stickslip
