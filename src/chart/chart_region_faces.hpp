// The regions of a stability chart as polygons: the faces of the rectangle cut
// by the traced curves (chart_faces.hpp), each classified at one interior
// point by ClassifyPoint (chart_regions.hpp), neighbours of one region merged.
#pragma once

#include <string>
#include <vector>

#include "stickslip/chart/chart.hpp"

namespace stickslip {

// The faces of options.plane cut by every curve (HB, GR, LP), classified.
// Between two curves the region cannot change (the curves are where the
// tests of ClassifyPoint change sign), so one point decides a face.
// failure (optional): set to the first face whose stick-slip test failed
// numerically, where and why (the face is then shaded as without stick-slip).
std::vector<RegionFace> ClassifyFaces(const Params& base, const ChartOptions& options,
                                      const std::vector<Curve>& curves,
                                      std::string* failure = nullptr);

// The cells of grid whose region differs from the one drawn at their centre
// (the last face in drawing order whose outline contains it): a check of the
// polygons against a raster.
int GridDisagreements(const std::vector<RegionFace>& faces, const RegionGrid& grid);

}  // namespace stickslip
