// Event roots on a step polynomial (src/integrate/poly_roots.hpp) against the
// closed-form roots of products of linear factors.
#include "integrate/poly_roots.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace ss = stickslip;

namespace {
constexpr double kUlp = 2.220446049250313e-16;
}

// (u - r)(u + 3): its derivative 2u + 3 - r stays positive on [0, 1], so the
// monotone path refines the root from [0, 1] without Bernstein isolation.
TEST(PolyRoots, MonotoneRootIsTheClosedForm) {
  for (double r : {1e-3, 0.3, 0.5, 0.999}) {
    const double c[3] = {-3 * r, 3 - r, 1};
    EXPECT_TRUE(ss::Monotone(c, 2));
    const ss::PolyRoot root = ss::FirstSignChange(c, 2, -1, -1);
    ASSERT_TRUE(root.found) << r;
    EXPECT_NEAR(root.u, r, 8 * kUlp) << r;
  }
}

// 1 + u/2 - u^3/10: monotone on [0, 1] and positive: no root.
TEST(PolyRoots, MonotoneWithoutRootHasNone) {
  const double c[4] = {1, 0.5, 0, -0.1};
  EXPECT_TRUE(ss::Monotone(c, 3));
  EXPECT_FALSE(ss::FirstSignChange(c, 3, 1, 1).found);
}

// (u - 0.2)(u - 0.7): not monotone on [0, 1]; the first of its two roots.
TEST(PolyRoots, FirstOfTwoRootsByIsolation) {
  const double c[3] = {0.14, -0.9, 1};
  EXPECT_FALSE(ss::Monotone(c, 2));
  const ss::PolyRoot root = ss::FirstSignChange(c, 2, 1, 1);
  ASSERT_TRUE(root.found);
  EXPECT_NEAR(root.u, 0.2, 8 * kUlp);
}

// (u - 0.4)^2 (u + 1) + 1e-3: a near-touch that stays positive (minimum 1e-3
// at u = 0.4): not monotone, and no sign change.
TEST(PolyRoots, NearTouchIsNoRoot) {
  // (u^2 - 0.8u + 0.16)(u + 1) = u^3 + 0.2u^2 - 0.64u + 0.16
  const double c[4] = {0.16 + 1e-3, -0.64, 0.2, 1};
  EXPECT_FALSE(ss::Monotone(c, 3));
  EXPECT_FALSE(ss::FirstSignChange(c, 3, 1, 1).found);
}

namespace {
double AbsSumFrom(const double* c, int n, int from) {
  double s = 0;
  for (int k = from; k <= n; ++k) s += std::abs(c[k]);
  return s;
}
}  // namespace

// 0.2 - u/2 + u^2/2 - u^3/10 + 1e-4 u^4: the quadratic bound fails (|c_3| =
// 0.1 in its tail exceeds the quadratic's minimum 0.075); the cubic's minimum
// (0.058 near u = 0.61) clears the tail 1e-4. Sampled at 10^5 points in long
// double, the polynomial stays above 0.058.
TEST(PolyRoots, CubicBoundExcludesWhereTheQuadraticCannot) {
  const double c[5] = {0.2, -0.5, 0.5, -0.1, 1e-4};
  long double lowest = INFINITY;
  for (int i = 0; i <= 100000; ++i) {
    const long double u = i / 100000.0L;
    lowest = std::min(lowest, c[0] + u * (c[1] + u * (c[2] + u * (c[3] + u * c[4]))));
  }
  EXPECT_GT(lowest, 0.058L);
  EXPECT_FALSE(ss::QuadraticBoundExcludes(c, 4, 1, AbsSumFrom(c, 4, 3)));
  EXPECT_TRUE(ss::CubicBoundExcludes(c, 4, 1, AbsSumFrom(c, 4, 4), AbsSumFrom(c, 4, 0)));
  EXPECT_FALSE(ss::FirstSignChange(c, 4, 1, 1).found);
  // The same with the sign turned: -g is excluded for sign -1, not for +1.
  double m[5];
  for (int k = 0; k < 5; ++k) m[k] = -c[k];
  EXPECT_TRUE(ss::CubicBoundExcludes(m, 4, -1, AbsSumFrom(m, 4, 4), AbsSumFrom(m, 4, 0)));
  EXPECT_FALSE(ss::CubicBoundExcludes(m, 4, 1, AbsSumFrom(m, 4, 4), AbsSumFrom(m, 4, 0)));
}

// g = (r - u) p(u), p > 0 on [0, 1] of degree 19 with decaying random
// coefficients, so g changes sign at r exactly: the bound must never exclude
// it, and the search finds r (to the root's conditioning). 20000 draws, r
// from 1e-6 to 1 - 1e-6.
TEST(PolyRoots, CubicBoundNeverExcludesAKnownRoot) {
  std::mt19937_64 rng(31);
  std::uniform_real_distribution<double> unit(-1, 1);
  constexpr int kN = 20;
  int excluded = 0, missed = 0;
  for (int draw = 0; draw < 20000; ++draw) {
    const double r = draw % 4 == 0 ? 1e-6 : (draw % 4 == 1 ? 1 - 1e-6 : 0.5 * (1 + unit(rng)));
    long double p[kN] = {1.5L};  // p_0 = 1.5 > sum |p_k|, k >= 1
    for (int k = 1; k < kN; ++k) p[k] = unit(rng) * std::pow(0.5, k);
    double c[kN + 1];
    for (int k = 0; k <= kN; ++k)  // (r - u) p(u)
      c[k] = static_cast<double>((k < kN ? r * p[k] : 0.0L) - (k > 0 ? p[k - 1] : 0.0L));
    if (ss::CubicBoundExcludes(c, kN, 1, AbsSumFrom(c, kN, 4), AbsSumFrom(c, kN, 0))) ++excluded;
    const ss::PolyRoot root = ss::FirstSignChange(c, kN, 1, 1);
    if (!root.found || std::abs(root.u - r) > 1e-9) ++missed;
  }
  EXPECT_EQ(excluded, 0);
  EXPECT_EQ(missed, 0);
}

// Cubics whose minimum on (0, 1) lies inside, below 0, while both ends are
// positive: the bound must look at the interior critical points (each root of
// the derivative's quadratic formula in turn), and at its margin.
TEST(PolyRoots, CubicBoundSeesTheInteriorMinimumAndItsMargin) {
  // 0.24 - u + u^2 + 0.001 u^3: minimum about -0.0099 near u = 0.5.
  const double a[4] = {0.24, -1, 1, 0.001};
  // 0.03 + 0.075 u - 0.825 u^2 + u^3: minimum -0.01375 at u = 0.5 exactly.
  const double b[4] = {0.03, 0.075, -0.825, 1};
  for (const double* c : {a, b}) {
    EXPECT_FALSE(ss::CubicBoundExcludes(c, 3, 1, 0.0, AbsSumFrom(c, 3, 0)));
    EXPECT_TRUE(ss::FirstSignChange(c, 3, 1, 1).found);
  }
  const double min_b = 0.03 + 0.075 * 0.5 - 0.825 * 0.25 + 0.125;
  EXPECT_NEAR(min_b, -0.01375, 1e-15);
  // 1 + 1e-15 - u^4: positive on [0, 1] by 1e-15, within the margin.
  const double m[5] = {1 + 1e-15, 0, 0, 0, -1};
  EXPECT_FALSE(ss::CubicBoundExcludes(m, 4, 1, 1.0, AbsSumFrom(m, 4, 0)));
}

// The same root whatever the polynomial's size: (u - 0.2)(u - 0.7) and the
// first cubic above, scaled to 1e154 (b^2 overflows), to 1e-165 (q1^2
// underflows) and to 1e-301: the bounds step aside, the Bernstein search
// finds the root the unscaled polynomial has.
TEST(PolyRoots, BoundsStepAsideForHugeAndTinyCoefficients) {
  const double quad[3] = {0.14, -0.9, 1}, cubic[4] = {0.24, -1, 1, 0.001};
  const double cubic_root = ss::FirstSignChange(cubic, 3, 1, 1).u;
  for (double f : {1e154, 1e-165, 1e-301}) {
    double q[3], c[4];
    for (int k = 0; k < 3; ++k) q[k] = quad[k] * f;
    for (int k = 0; k < 4; ++k) c[k] = cubic[k] * f;
    const ss::PolyRoot rq = ss::FirstSignChange(q, 2, 1, 1), rc = ss::FirstSignChange(c, 3, 1, 1);
    ASSERT_TRUE(rq.found) << f;
    EXPECT_NEAR(rq.u, 0.2, 1e-12) << f;
    ASSERT_TRUE(rc.found) << f;
    EXPECT_NEAR(rc.u, cubic_root, 1e-12) << f;
  }
}

// 1e-3 - 2e-3 u^12: its only root, 0.5^(1/12), comes from a term past the
// low-degree hull (FirstSignChangePast): the hull's slack must keep it.
TEST(PolyRoots, RootMadeByHighTermsIsFound) {
  double c[13] = {1e-3};
  c[12] = -2e-3;
  const ss::PolyRoot root = ss::FirstSignChange(c, 12, 1, 1);
  ASSERT_TRUE(root.found);
  EXPECT_NEAR(root.u, std::pow(0.5, 1.0 / 12), 8 * kUlp);
}

// (u - r)^2 q(u) + d with q > 0 on [0, 1] (degree 20): at least d (1e-9 to
// 1e-3) everywhere, with that minimum near r: no root, whichever of the
// bounds and hulls decides it.
TEST(PolyRoots, NearDoubleRootsOfDegreeTwentyAreNoRoots) {
  std::mt19937_64 rng(47);
  std::uniform_real_distribution<double> unit(-1, 1);
  constexpr int kN = 20;
  int found = 0;
  for (int draw = 0; draw < 5000; ++draw) {
    const double r = 0.5 * (1 + unit(rng)), d = std::pow(10.0, -3 - 6 * (0.5 + 0.5 * unit(rng)));
    long double q[kN - 1] = {1.5L};  // q_0 = 1.5 > sum |q_k|, k >= 1
    for (int k = 1; k < kN - 1; ++k) q[k] = unit(rng) * std::pow(0.5, k);
    const long double s[3] = {static_cast<long double>(r) * r, -2.0L * r, 1.0L};  // (u - r)^2
    long double p[kN + 1] = {};
    for (int k = 0; k < kN - 1; ++k)
      for (int j = 0; j < 3; ++j) p[k + j] += q[k] * s[j];
    double c[kN + 1];
    for (int k = 0; k <= kN; ++k) c[k] = static_cast<double>(p[k] + (k == 0 ? d : 0.0L));
    if (ss::FirstSignChange(c, kN, 1, 1).found) ++found;
  }
  EXPECT_EQ(found, 0);
}
