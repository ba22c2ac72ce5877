// Seeds of the forced chart's curves: the special points of one-parameter
// runs on lines across the rectangle, and of the period-doubled branches that
// start at their PD points (AUTO-07p's ISW = -1), up to ForcedChartOptions::max_m.
#pragma once

#include <string>
#include <vector>

#include "stickslip/chart/forced_chart.hpp"

namespace stickslip {

struct ForcedSeed {
  CurveKind kind = CurveKind::kFold;
  int m = 1;
  double x0 = 0, xdot0 = 0, p1 = 0, p2 = 0;
  int fixed = 3;  // the unknown held while the seed is corrected (the line's constant)
  std::string where;
};

/// The seeds of the line along p1 at p2 = c (along1) or along p2 at p1 = c:
/// the special points of the branches through the stable orbits at either
/// end, and of the doubled branches from their PD points while 2m <= max_m.
/// *runs counts the one-parameter runs made.
std::vector<ForcedSeed> SeedsOnLine(const ForcedParams& base, const ForcedChartOptions& o,
                                    bool along1, double c, int* runs);

/// True if s lies on a traced curve of its kind and m.
bool NearForcedCurve(const std::vector<ForcedCurve>& curves, const ForcedSeed& s, const Plane& pl);

}  // namespace stickslip
