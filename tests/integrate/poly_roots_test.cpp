// Event roots on a step polynomial (src/integrate/poly_roots.hpp) against the
// closed-form roots of products of linear factors.
#include "integrate/poly_roots.hpp"

#include <gtest/gtest.h>

#include <cmath>

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
