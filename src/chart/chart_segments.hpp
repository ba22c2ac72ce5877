// Private to src/: the segments of a chart arrangement (chart_faces.hpp) in
// the unit square: the rectangle's edges and the polylines, clipped.
#pragma once

#include <array>
#include <vector>

#include "stickslip/chart/chart_faces.hpp"

namespace stickslip {

using Segment = std::array<Point2, 2>;

// The rectangle's four edges, then the polylines scaled to the unit square and
// clipped to it. A polyline end within kEndSnap of the border, of another
// polyline or of its own other end (a closed curve) is joined to the nearest
// such point by one more segment: traced curves end on the border or at a
// codimension-two point to the continuation's accuracy, not exactly on the
// chords of the curve they meet.
std::vector<Segment> UnitSegments(const Plane& plane,
                                  const std::vector<std::vector<Point2>>& polylines);

}  // namespace stickslip
