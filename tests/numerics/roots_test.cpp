// Root finding and minimisation (Boost.Math) against closed forms.
#include "numerics/roots.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace ss = stickslip;

// cos x = x: the Dottie number, 0.739085133215160641655...
TEST(Roots, FindsTheDottieNumber) {
  const ss::RootResult r = ss::FindRoot([](double x) { return std::cos(x) - x; }, 0, 1, 1e-14);
  ASSERT_TRUE(r.ok);
  EXPECT_NEAR(r.x, 0.7390851332151607, 2e-14);
  EXPECT_LT(r.evaluations, 20);
}

TEST(Roots, NoSignChangeOrNonFiniteValueIsNotOk) {
  EXPECT_FALSE(ss::FindRoot([](double x) { return x * x + 1; }, -1, 1, 1e-12).ok);
  EXPECT_FALSE(
      ss::FindRoot([](double x) { return x > 0.3 ? std::nan("") : x - 0.5; }, 0, 1, 1e-12).ok);
}

// x e^x has its minimum at x = -1 (value -1/e).
TEST(Roots, FindsTheMinimumOfXExpX) {
  const ss::RootResult r = ss::FindMinimum([](double x) { return x * std::exp(x); }, -3, 2, 1e-8);
  ASSERT_TRUE(r.ok);
  EXPECT_NEAR(r.x, -1.0, 1e-7);
  EXPECT_NEAR(r.fx, -std::exp(-1.0), 1e-14);
}
