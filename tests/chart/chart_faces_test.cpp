// The faces of a chart's arrangement (chart_faces.hpp) against hand-computed
// cases: areas from the vertices by hand, an inscribed polygon's closed form.
#include "stickslip/chart/chart_faces.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace stickslip {
namespace {

// Every face its own label: nothing merges.
std::vector<Face> Distinct(const Plane& pl, const std::vector<std::vector<Point2>>& lines) {
  int n = 0;
  return ArrangementFaces(pl, lines, [&n](const Point2&) { return n++; });
}

std::vector<double> Areas(const std::vector<Face>& faces) {
  std::vector<double> a;
  for (const Face& f : faces) a.push_back(f.area);
  std::sort(a.begin(), a.end());
  return a;
}

double Sum(const std::vector<Face>& faces) {
  double s = 0;
  for (const Face& f : faces) s += f.area;
  return s;
}

// Distance from p to the nearest edge of the face's rings.
double Clearance(const Face& f, const Point2& p) {
  double d = 1e300;
  std::vector<std::vector<Point2>> rings{f.outer};
  rings.insert(rings.end(), f.holes.begin(), f.holes.end());
  for (const auto& r : rings)
    for (size_t i = 0; i < r.size(); ++i) {
      const Point2 a = r[i], b = r[(i + 1) % r.size()];
      const double ex = b[0] - a[0], ey = b[1] - a[1];
      double t = ((p[0] - a[0]) * ex + (p[1] - a[1]) * ey) / (ex * ex + ey * ey);
      t = std::clamp(t, 0.0, 1.0);
      d = std::min(d, std::hypot(p[0] - a[0] - t * ex, p[1] - a[1] - t * ey));
    }
  return d;
}

const Plane kUnit{Parameter::kV, Parameter::kBeta, 0, 1, 0, 1};

TEST(ChartFaces, EmptyRectangleIsOneFace) {
  const Plane pl{Parameter::kV, Parameter::kBeta, 0.05, 0.6, 0, 0.25};
  const auto faces = Distinct(pl, {});
  ASSERT_EQ(faces.size(), 1u);
  EXPECT_NEAR(faces[0].area, 0.55 * 0.25, 1e-15);
  EXPECT_NEAR(faces[0].inside[0], 0.325, 0.55 / 32);
}

TEST(ChartFaces, OneLineCutsTwoTrapezoids) {
  // Through (0.5, 0) and (1, 1) in [0, 2] x [0, 1], given beyond the border:
  // trapezoids of widths 0.5 and 1 (area 0.75) and 1.5 and 1 (area 1.25).
  const Plane pl{Parameter::kV, Parameter::kBeta, 0, 2, 0, 1};
  const auto faces = Distinct(pl, {{{0.25, -0.5}, {1.25, 1.5}}});
  ASSERT_EQ(faces.size(), 2u);
  EXPECT_NEAR(Areas(faces)[0], 0.75, 1e-12);
  EXPECT_NEAR(Areas(faces)[1], 1.25, 1e-12);
  EXPECT_NEAR(Sum(faces), 2.0, 1e-12);
}

TEST(ChartFaces, TwoCrossingLinesCutFour) {
  const auto faces = Distinct(kUnit, {{{0.3, 0}, {0.3, 0.5}, {0.3, 1}}, {{0, 0.6}, {1, 0.6}}});
  ASSERT_EQ(faces.size(), 4u);
  const auto a = Areas(faces);
  EXPECT_NEAR(a[0], 0.12, 1e-12);
  EXPECT_NEAR(a[1], 0.18, 1e-12);
  EXPECT_NEAR(a[2], 0.28, 1e-12);
  EXPECT_NEAR(a[3], 0.42, 1e-12);
  EXPECT_NEAR(Sum(faces), 1.0, 1e-12);
  // Each interior point is well inside its face: the smallest face is
  // 0.3 x 0.4, its inscribed circle's radius 0.15.
  for (const Face& f : faces) EXPECT_GT(Clearance(f, f.inside), 0.1);
}

TEST(ChartFaces, DanglingCurvesDoNotSplit) {
  // A curve from the border ending inside, and a branch hanging off a
  // border-to-border curve, split nothing.
  const auto one = Distinct(kUnit, {{{0, 0.5}, {0.5, 0.5}}});
  ASSERT_EQ(one.size(), 1u);
  EXPECT_NEAR(one[0].area, 1.0, 1e-12);
  const auto two = Distinct(kUnit, {{{0.5, 0}, {0.5, 1}}, {{0.5, 0.5}, {0.8, 0.5}, {0.8, 0.7}}});
  ASSERT_EQ(two.size(), 2u);
  EXPECT_NEAR(two[0].area, 0.5, 1e-12);
  EXPECT_NEAR(two[1].area, 0.5, 1e-12);
  for (const Face& f : two) EXPECT_GT(Clearance(f, f.inside), 0.1);
}

TEST(ChartFaces, EndsNearTheBorderOrACurveAreJoined) {
  // Traced curves end on the border or on another curve to the continuation's
  // accuracy: 1e-4 short of x = 1, a curve still splits the square; a second
  // one ending 1e-4 short of the first splits the right part.
  const auto faces = Distinct(kUnit, {{{0, 0.5}, {0.9999, 0.5}}, {{0.6, 0}, {0.6, 0.4999}}});
  ASSERT_EQ(faces.size(), 3u);
  const auto a = Areas(faces);
  EXPECT_NEAR(a[0], 0.2, 1e-12);
  EXPECT_NEAR(a[1], 0.3, 1e-12);
  EXPECT_NEAR(a[2], 0.5, 1e-12);
}

TEST(ChartFaces, ClosedCurveInsideIsAHole) {
  const auto faces =
      Distinct(kUnit, {{{0.25, 0.25}, {0.75, 0.25}, {0.75, 0.75}, {0.25, 0.75}, {0.25, 0.25}}});
  ASSERT_EQ(faces.size(), 2u);
  EXPECT_NEAR(faces[0].outer_area, 1.0, 1e-12);  // largest first: drawn first
  ASSERT_EQ(faces[0].holes.size(), 1u);
  EXPECT_NEAR(faces[0].area, 0.75, 1e-12);
  EXPECT_NEAR(faces[1].area, 0.25, 1e-12);
  const Point2 p = faces[0].inside;  // outside the hole
  EXPECT_FALSE(p[0] > 0.25 && p[0] < 0.75 && p[1] > 0.25 && p[1] < 0.75);
  EXPECT_GT(Clearance(faces[0], p), 0.05);
}

TEST(ChartFaces, InscribedQuarterCircleArea) {
  // n chords of a quarter circle of radius 0.5 about the corner (0, 0): the
  // inner face is n triangles, area n r^2 sin(pi / 2n) / 2.
  const int n = 400;
  const double r = 0.5, pi = std::acos(-1.0);
  std::vector<Point2> arc;
  for (int k = 0; k <= n; ++k)
    arc.push_back({r * std::cos(0.5 * pi * k / n), r * std::sin(0.5 * pi * k / n)});
  const auto faces = Distinct(kUnit, {arc});
  ASSERT_EQ(faces.size(), 2u);
  const double inner = 0.5 * n * r * r * std::sin(0.5 * pi / n);
  EXPECT_NEAR(Areas(faces)[0], inner, 1e-12);
  EXPECT_NEAR(Sum(faces), 1.0, 1e-12);
}

TEST(ChartFaces, AdjacentFacesOfOneLabelMerge) {
  // Labelled by the side of x = 0.3: the line y = 0.6 separates nothing.
  const auto faces = ArrangementFaces(kUnit, {{{0.3, 0}, {0.3, 1}}, {{0, 0.6}, {1, 0.6}}},
                                      [](const Point2& p) { return p[0] < 0.3 ? 1 : 2; });
  ASSERT_EQ(faces.size(), 2u);
  EXPECT_EQ(faces[0].label, 2);
  EXPECT_NEAR(faces[0].area, 0.7, 1e-12);
  EXPECT_EQ(faces[1].label, 1);
  EXPECT_NEAR(faces[1].area, 0.3, 1e-12);
  EXPECT_EQ(faces[1].outer.size(), 4u);  // the rectangle 0.3 x 1: no vertex left at y = 0.6
}

}  // namespace
}  // namespace stickslip
