// Areas of plane regions bounded by closed curves, clipped to an axis-aligned
// box: the exact basin stability of ss_basin (basin_stability.hpp), where the
// basin boundary is an unstable periodic orbit.
#pragma once

#include <vector>

#include "stickslip/systems/belt/model.hpp"

namespace stickslip {

/// The closed box [x_lo, x_hi] x [y_lo, y_hi].
struct Box {
  double x_lo = 0, x_hi = 0, y_lo = 0, y_hi = 0;
  double Area() const { return (x_hi - x_lo) * (y_hi - y_lo); }
};

/// Area of a simple polygon (vertices in order, either orientation, not
/// repeated at the end) intersected with the box: Sutherland & Hodgman (1974)
/// clipping against the four edges, then the shoelace formula. Exact up to
/// rounding for a polygon; >= 0.
double ClippedPolygonArea(const std::vector<Vec2>& polygon, const Box& box);

/// Area inside a smooth simple closed curve, clipped to the box. The curve is
/// given by samples z[k] at times t[k] (increasing, t.back() one period after
/// t.front(), z.back() == z.front() up to rounding) with derivatives dz[k].
/// Between samples it is the cubic Hermite interpolant (error O(h^4)); each
/// piece is cut into m and 2m chords and the two polygon areas are combined by
/// Richardson extrapolation (the chord error is c / m^2 + O(m^-3)).
/// Throws InvalidArgument on fewer than 4 samples or mismatched sizes.
double ClippedCurveArea(const std::vector<double>& t, const std::vector<Vec2>& z,
                        const std::vector<Vec2>& dz, const Box& box, int m = 8);

}  // namespace stickslip
