// The regions of a stability chart, point by point (chart.hpp, RegionGrid).
#pragma once

#include <string>

#include "stickslip/chart/chart.hpp"

namespace stickslip {

// The region at p: steady sliding stable where 2 beta + mu'(v) > 0; a
// stick-slip orbit where the first return of the slip phase from the exit
// point reaches the belt speed (the grazing gap is > 0). With stable steady sliding
// and no stick-slip orbit, and only if pure_slip_check, the section map is
// iterated from the exit trajectory's first maximum of x: a sequence that
// settles on a pure-slip orbit (instead of decaying to the equilibrium) means
// a stable pure-slip orbit beside stable steady sliding (bistable).
// failure (optional): set if the stick-slip test failed numerically (the cell
// is then shaded as if no stick-slip orbit were there).
Region ClassifyPoint(OrbitFinder& finder, const Params& p, bool pure_slip_check,
                     std::string* failure = nullptr);

// The grid of options.region_n1 x options.region_n2 cell centres. A stable
// pure-slip orbit beside stable steady sliding needs a fold of pure-slip
// orbits: an LP curve, or a GR point of persistence type where steady sliding
// is stable; the pure-slip check runs only if `curves` has one.
RegionGrid ClassifyGrid(const Params& base, const ChartOptions& options,
                        const std::vector<Curve>& curves);

}  // namespace stickslip
