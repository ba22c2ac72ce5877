// CurveStart points of a chart's curves: sign changes of a test function sampled
// along the rectangle's four edges and three interior lines per axis, refined
// by Brent's method, after the caller's seeds.
#pragma once

#include <Eigen/Dense>
#include <functional>
#include <vector>

#include "stickslip/chart/chart.hpp"

namespace stickslip {

struct CurveStart {
  Eigen::Vector2d x;
  int fixed;  // the coordinate its line holds
};

// Roots of f along each start line (f may fail: NaN).
std::vector<CurveStart> StartPoints(const Plane& pl, int samples,
                                    const std::function<double(double, double)>& f);

// The caller's seeds of one kind first (holding p2), then the scan's.
std::vector<CurveStart> WithSeeds(const ChartOptions& o, CurveKind kind,
                                  std::vector<CurveStart> scan);

}  // namespace stickslip
