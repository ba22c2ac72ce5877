// The faces of a chart's planar arrangement: the rectangle cut by the traced
// curves (polylines), as polygons. Curves are split at their crossings; a
// curve end inside a face (a dangling end) does not split it. Each face gets
// one interior point far from its edges, is labelled there, and adjacent faces
// with equal labels are merged. Geometry only: labelling is the caller's
// (ClassifyFaces of chart_regions.hpp labels by region).
#pragma once

#include <array>
#include <functional>
#include <vector>

#include "stickslip/chart/plane.hpp"

namespace stickslip {

using Point2 = std::array<double, 2>;  // (p1, p2)

struct Face {
  std::vector<Point2> outer;               // counter-clockwise, not repeated at the end
  std::vector<std::vector<Point2>> holes;  // clockwise; curves closed inside the face
  double area = 0;                         // outer minus holes, in p1 * p2 units
  double outer_area = 0;                   // of the outer ring alone
  Point2 inside{};  // interior point, the farthest from the edges of a scanline sample
  int label = 0;
};

// The faces of the rectangle cut by the polylines (points outside it are
// clipped), labelled by label(inside) and merged where adjacent faces have
// equal labels. Sorted by outer_area, largest first: drawing them in this order
// paints a face inside a hole over the face around it. Points closer than
// 1e-9 of the rectangle's size are one vertex.
std::vector<Face> ArrangementFaces(const Plane& plane,
                                   const std::vector<std::vector<Point2>>& polylines,
                                   const std::function<int(const Point2&)>& label);

}  // namespace stickslip
