#include "chart/chart_region_faces.hpp"

#include <sstream>

#include "chart/chart_regions.hpp"
#include "chart/hopf_curve.hpp"
#include "stickslip/chart/chart_faces.hpp"

namespace stickslip {

std::vector<RegionFace> ClassifyFaces(const Params& base, const ChartOptions& o,
                                      const std::vector<Curve>& curves, std::string* failure) {
  const Plane& pl = o.plane;
  std::vector<std::vector<Point2>> lines;
  // The pure-slip check needs a fold of pure-slip orbits (as ClassifyGrid).
  bool check = false;
  for (const Curve& c : curves) {
    lines.emplace_back();
    for (const CurvePoint& p : c.points) {
      lines.back().push_back({p.p1, p.p2});
      check = check || c.kind == CurveKind::kFold ||
              (p.type == CurvePointType::kPersistence && HopfFunction(pl.At(base, p.p1, p.p2)) > 0);
    }
  }
  OrbitFinder finder(Model(base), o.orbit);
  const std::vector<Face> faces = ArrangementFaces(pl, lines, [&](const Point2& x) {
    std::string why;
    const Region region = ClassifyPoint(finder, pl.At(base, x[0], x[1]), check, &why);
    if (!why.empty() && failure && failure->empty()) {
      std::ostringstream os;
      os << "region of the face classified at " << pl.p1 << " = " << x[0] << ", " << pl.p2 << " = "
         << x[1] << ": stick-slip orbit: " << why;
      *failure = os.str();
    }
    return static_cast<int>(region);
  });
  std::vector<RegionFace> out;
  for (const Face& f : faces) out.push_back({f, static_cast<Region>(f.label)});
  return out;
}

int GridDisagreements(const std::vector<RegionFace>& faces, const RegionGrid& grid) {
  auto inside = [](const std::vector<Point2>& r, double x, double y) {
    bool in = false;
    for (size_t i = 0, j = r.size() - 1; i < r.size(); j = i++)
      if ((r[i][1] > y) != (r[j][1] > y) &&
          x < r[i][0] + (y - r[i][1]) * (r[j][0] - r[i][0]) / (r[j][1] - r[i][1]))
        in = !in;
    return in;
  };
  int n = 0;
  for (int i = 0; i < grid.n1; ++i)
    for (int j = 0; j < grid.n2; ++j) {
      const RegionFace* drawn = nullptr;
      for (const RegionFace& f : faces)
        if (inside(f.face.outer, grid.x1[i], grid.x2[j])) drawn = &f;
      n += !drawn || drawn->region != grid.at(i, j);
    }
  return n;
}

}  // namespace stickslip
