#include "chart/chart_segments.hpp"

#include <algorithm>
#include <cmath>

#include "numerics/tolerances.hpp"

namespace stickslip {

namespace {
// Liang-Barsky clipping of the segment ab to the unit square.
bool Clip(Point2& a, Point2& b) {
  double t0 = 0, t1 = 1;
  const Point2 d{b[0] - a[0], b[1] - a[1]};
  const double p[4] = {-d[0], d[0], -d[1], d[1]};
  const double q[4] = {a[0], 1 - a[0], a[1], 1 - a[1]};
  for (int k = 0; k < 4; ++k) {
    if (p[k] == 0) {
      if (q[k] < 0) return false;
      continue;
    }
    const double r = q[k] / p[k];
    if (p[k] < 0)
      t0 = std::max(t0, r);
    else
      t1 = std::min(t1, r);
    if (t0 > t1) return false;
  }
  b = {a[0] + t1 * d[0], a[1] + t1 * d[1]};
  a = {a[0] + t0 * d[0], a[1] + t0 * d[1]};
  return true;
}

// The point of segment s nearest to p.
Point2 Nearest(const Segment& s, const Point2& p) {
  const double ex = s[1][0] - s[0][0], ey = s[1][1] - s[0][1];
  const double l2 = ex * ex + ey * ey;
  const double t =
      l2 > 0 ? std::clamp(((p[0] - s[0][0]) * ex + (p[1] - s[0][1]) * ey) / l2, 0.0, 1.0) : 0.0;
  return {s[0][0] + t * ex, s[0][1] + t * ey};
}
}  // namespace

std::vector<Segment> UnitSegments(const Plane& plane,
                                  const std::vector<std::vector<Point2>>& polylines) {
  std::vector<Segment> segs{{Point2{0, 0}, Point2{1, 0}},
                            {Point2{1, 0}, Point2{1, 1}},
                            {Point2{1, 1}, Point2{0, 1}},
                            {Point2{0, 1}, Point2{0, 0}}};
  std::vector<size_t> first{segs.size()};  // polyline k's: [first[k], first[k + 1])
  std::vector<std::array<Point2, 2>> ends;
  for (const auto& line : polylines) {
    const size_t begin = segs.size();
    for (size_t i = 0; i + 1 < line.size(); ++i) {
      Point2 a{(line[i][0] - plane.from1) / plane.width1(),
               (line[i][1] - plane.from2) / plane.width2()};
      Point2 b{(line[i + 1][0] - plane.from1) / plane.width1(),
               (line[i + 1][1] - plane.from2) / plane.width2()};
      if (!std::isfinite(a[0] + a[1] + b[0] + b[1]) || !Clip(a, b)) continue;
      if (std::hypot(b[0] - a[0], b[1] - a[1]) > Tolerances::kSegmentMinLength)
        segs.push_back({a, b});
    }
    first.push_back(segs.size());
    if (segs.size() > begin)
      ends.push_back({segs[begin][0], segs.back()[1]});
    else
      ends.push_back({Point2{NAN, NAN}, Point2{NAN, NAN}});
  }
  for (size_t k = 0; k < ends.size(); ++k)
    for (int e : {0, 1}) {
      const Point2 p = ends[k][e];
      if (!std::isfinite(p[0])) continue;
      double best = Tolerances::kEndSnap;
      Point2 to = p;
      auto consider = [&](const Point2& q) {
        const double d = std::hypot(q[0] - p[0], q[1] - p[1]);
        if (d < best) best = d, to = q;
      };
      for (size_t s = 0; s < 4; ++s) consider(Nearest(segs[s], p));
      for (size_t j = 0; j < ends.size(); ++j)
        if (j != k)
          for (size_t s = first[j]; s < first[j + 1]; ++s) consider(Nearest(segs[s], p));
      if (first[k + 1] - first[k] > 2) consider(ends[k][1 - e]);
      if (best > Tolerances::kSegmentMinLength && best < Tolerances::kEndSnap)
        segs.push_back({p, to});
    }
  return segs;
}

}  // namespace stickslip
