// Clipped areas (clipped_area.hpp) against closed forms: polygons clipped by a
// box, and a disk sampled as a curve, clipped by boxes that cut it anywhere,
// against the exact area of a disk intersected with a rectangle.
#include "stickslip/basin/clipped_area.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "stickslip/errors.hpp"

namespace stickslip {
namespace {

TEST(ClippedArea, PolygonsClippedByABoxHaveTheirExactAreas) {
  const std::vector<Vec2> square = {{0, 0}, {2, 0}, {2, 2}, {0, 2}};
  EXPECT_DOUBLE_EQ(ClippedPolygonArea(square, {-1, 3, -1, 3}), 4.0);  // inside
  EXPECT_DOUBLE_EQ(ClippedPolygonArea(square, {1, 3, -1, 1.5}), 1.5);
  EXPECT_DOUBLE_EQ(ClippedPolygonArea(square, {0.5, 1, 0.25, 0.75}), 0.25);  // box inside
  EXPECT_EQ(ClippedPolygonArea(square, {3, 4, 3, 4}), 0.0);                  // apart
  // Clockwise, non-convex: an L of area 3, cut by x <= 1.5 to area 2.5.
  const std::vector<Vec2> ell = {{0, 0}, {0, 2}, {1, 2}, {1, 1}, {2, 1}, {2, 0}};
  EXPECT_DOUBLE_EQ(ClippedPolygonArea(ell, {-5, 5, -5, 5}), 3.0);
  EXPECT_DOUBLE_EQ(ClippedPolygonArea(ell, {-5, 1.5, -5, 5}), 2.5);
}

// Area of the unit disk with X <= x and Y <= y: the integral over s in [-1, x]
// of max(0, min(y, w) + w), w = sqrt(1 - s^2), piece by piece with the
// antiderivative G of w.
double Corner(double x, double y) {
  if (x <= -1 || y <= -1) return 0;
  x = std::min(x, 1.0), y = std::min(y, 1.0);
  auto G = [](double s) { return 0.5 * (s * std::sqrt(1 - s * s) + std::asin(s)); };
  const double c = std::sqrt(1 - y * y);
  auto part = [&](double a, double b, double w_factor, double y_factor) {
    b = std::min(b, x);
    return b <= a ? 0.0 : w_factor * (G(b) - G(a)) + y_factor * y * (b - a);
  };
  const double outer = y >= 0 ? 2 : 0;  // |s| > c: 2w above, nothing below
  return part(-1, -c, outer, 0) + part(-c, c, 1, 1) + part(c, 1, outer, 0);
}

// Disk of radius r about (cx, cy) intersected with the box: by scaling.
double DiskInBox(double r, double cx, double cy, const Box& b) {
  auto F = [&](double x, double y) { return Corner((x - cx) / r, (y - cy) / r); };
  return r * r * (F(b.x_hi, b.y_hi) - F(b.x_lo, b.y_hi) - F(b.x_hi, b.y_lo) + F(b.x_lo, b.y_lo));
}

TEST(ClippedArea, ClosedFormOfTheDiskInABoxChecksItself) {
  EXPECT_NEAR(DiskInBox(1, 0, 0, {-2, 2, -2, 2}), M_PI, 1e-15);
  EXPECT_NEAR(DiskInBox(1, 0, 0, {0, 2, 0, 2}), M_PI / 4, 1e-15);
  EXPECT_NEAR(DiskInBox(1, 0, 0, {-2, 2, -2, 0.5}), M_PI - (std::acos(0.5) - 0.5 * std::sqrt(0.75)),
              1e-15);                                                 // circular segment cut
  EXPECT_NEAR(DiskInBox(2, 1, 1, {0.5, 1.5, 0.2, 1.2}), 1.0, 1e-15);  // box inside
}

TEST(ClippedArea, DiskSampledAsACurveMatchesTheClosedFormTo1e12) {
  const double r = 0.7, cx = 0.3, cy = -0.2;
  const int n = 2000;
  std::vector<double> t;
  std::vector<Vec2> z, dz;
  for (int k = 0; k <= n; ++k) {
    const double a = 2 * M_PI * k / n;
    t.push_back(a);
    z.push_back({cx + r * std::cos(a), cy + r * std::sin(a)});
    dz.push_back({-r * std::sin(a), r * std::cos(a)});
  }
  const Box boxes[] = {{-1, 2, -1, 1},          // whole disk
                       {0.1, 2, -0.5, 0.4},     // cut on three sides
                       {-0.2, 0.5, -0.6, 0.1},  // a corner of the box inside, edges crossing
                       {0.0, 0.6, -0.5, 0.1}};  // box inside the disk
  for (const Box& b : boxes) {
    const double exact = DiskInBox(r, cx, cy, b);
    EXPECT_NEAR(ClippedCurveArea(t, z, dz, b), exact, 1e-12)
        << b.x_lo << " " << b.x_hi << " " << b.y_lo << " " << b.y_hi;
    // The plain polygon through the samples is off by O(n^-2): the refinement matters.
    if (b.x_lo < -0.9) {
      EXPECT_GT(std::abs(ClippedPolygonArea(z, b) - exact), 1e-7);
    }
  }
}

TEST(ClippedArea, TooFewSamplesAreMisuse) {
  EXPECT_THROW(ClippedCurveArea({0, 1}, {{0, 0}, {1, 0}}, {{0, 0}, {0, 0}}, {0, 1, 0, 1}),
               InvalidArgument);
}

}  // namespace
}  // namespace stickslip
