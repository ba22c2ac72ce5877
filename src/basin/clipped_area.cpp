#include "stickslip/basin/clipped_area.hpp"

#include <cmath>
#include <string>

#include "stickslip/errors.hpp"

namespace stickslip {

namespace {

// One Sutherland-Hodgman pass: keep the side where coordinate `axis` is
// >= c (keep_above) or <= c.
std::vector<Vec2> ClipEdge(const std::vector<Vec2>& in, int axis, double c, bool keep_above) {
  std::vector<Vec2> out;
  if (in.empty()) return out;
  out.reserve(in.size() + 4);
  auto inside = [&](const Vec2& p) { return keep_above ? p[axis] >= c : p[axis] <= c; };
  Vec2 prev = in.back();
  bool prev_in = inside(prev);
  for (const Vec2& cur : in) {
    const bool cur_in = inside(cur);
    if (cur_in != prev_in) {  // the crossing of the edge's line
      const double s = (c - prev[axis]) / (cur[axis] - prev[axis]);
      Vec2 q = prev + s * (cur - prev);
      q[axis] = c;
      out.push_back(q);
    }
    if (cur_in) out.push_back(cur);
    prev = cur;
    prev_in = cur_in;
  }
  return out;
}

// Shoelace formula, about the first vertex to limit cancellation.
double SignedArea(const std::vector<Vec2>& p) {
  if (p.size() < 3) return 0;
  double a = 0;
  const Vec2 o = p[0];
  for (size_t k = 1; k + 1 < p.size(); ++k) {
    const Vec2 u = p[k] - o, w = p[k + 1] - o;
    a += u[0] * w[1] - u[1] * w[0];
  }
  return 0.5 * a;
}

// Cubic Hermite point on [0, h] at s in [0, 1].
Vec2 Hermite(const Vec2& p0, const Vec2& d0, const Vec2& p1, const Vec2& d1, double h, double s) {
  const double s2 = s * s, s3 = s2 * s;
  return (2 * s3 - 3 * s2 + 1) * p0 + (s3 - 2 * s2 + s) * h * d0 + (-2 * s3 + 3 * s2) * p1 +
         (s3 - s2) * h * d1;
}

std::vector<Vec2> Refine(const std::vector<double>& t, const std::vector<Vec2>& z,
                         const std::vector<Vec2>& dz, int m) {
  std::vector<Vec2> poly;
  poly.reserve((z.size() - 1) * m);
  for (size_t k = 0; k + 1 < z.size(); ++k) {
    const double h = t[k + 1] - t[k];
    for (int j = 0; j < m; ++j)
      poly.push_back(Hermite(z[k], dz[k], z[k + 1], dz[k + 1], h, static_cast<double>(j) / m));
  }
  return poly;
}

}  // namespace

double ClippedPolygonArea(const std::vector<Vec2>& polygon, const Box& box) {
  std::vector<Vec2> p = ClipEdge(polygon, 0, box.x_lo, true);
  p = ClipEdge(p, 0, box.x_hi, false);
  p = ClipEdge(p, 1, box.y_lo, true);
  p = ClipEdge(p, 1, box.y_hi, false);
  return std::abs(SignedArea(p));
}

double ClippedCurveArea(const std::vector<double>& t, const std::vector<Vec2>& z,
                        const std::vector<Vec2>& dz, const Box& box, int m) {
  if (z.size() < 4 || t.size() != z.size() || dz.size() != z.size() || m < 1)
    throw InvalidArgument("ClippedCurveArea: need >= 4 samples with times and derivatives, m >= 1");
  const double a1 = ClippedPolygonArea(Refine(t, z, dz, m), box);
  const double a2 = ClippedPolygonArea(Refine(t, z, dz, 2 * m), box);
  return (4 * a2 - a1) / 3;  // Richardson: the chord error is c / m^2
}

}  // namespace stickslip
