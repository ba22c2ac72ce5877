// Tests of the seed's estimates (section 3) and the averaging estimates.
#include "stickslip/estimates/estimates.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "stickslip/errors.hpp"

namespace stickslip {
namespace {

// Independent brute force: the tightest a1 of (3.18) is max over D1 of
// -h(x1)/x1, the tightest a2 of (3.20) the inf over D2 of -h/(x1^2 - r1^2);
// evaluated with the raw h (3.10) on a dense grid.
double BruteA1(const Params& p, double r1) {
  double best = -HUGE_VAL;
  const int n = 2000000;
  for (int i = 0; i <= n; ++i) {
    const double x = r1 + (p.v - r1) * i / n;
    if (x != 0) best = std::max(best, -SeedH(p, x) / x);
  }
  return best;
}
double BruteA2(const Params& p, double r1, double lo) {
  double best = HUGE_VAL;
  const int n = 2000000;
  for (int i = 0; i < n; ++i) {  // x < r1 strictly, D2 is open at r1
    const double x = lo + (r1 - lo) * i / n;
    best = std::min(best, -SeedH(p, x) / (x * x - r1 * r1));
  }
  return best;
}

TEST(Estimates, SeedRootsMatchPrintedNumbers) {
  const Params p;  // the seed set
  EXPECT_NEAR(p.k1(), 0.45, 1e-15);
  EXPECT_NEAR(p.k3(), 0.6, 1e-15);
  const SeedRoots r = ComputeSeedRoots(p);
  ASSERT_TRUE(r.applies) << r.reason;
  EXPECT_EQ(r.r0, 0.0);
  EXPECT_NEAR(r.r2, 1.1074, 5e-5);
  EXPECT_NEAR(r.r1, -0.3574, 5e-5);
  EXPECT_NEAR(r.v_max, 0.44096, 5e-6);
  EXPECT_NEAR(SeedVMax(p), 0.44096, 5e-6);
  for (double z : {r.r0, r.r1, r.r2}) EXPECT_NEAR(SeedH(p, z), 0.0, 1e-12) << z;
  EXPECT_NEAR(SeedEquilibrium(p), 0.4 - 0.45 * 0.25 + 0.6 * 0.25 * 0.25 * 0.25, 1e-15);
}

TEST(Estimates, HPrimeIsTheDerivativeOfH) {
  const Params p;
  for (double z : {-0.7, -0.3, 0.0, 0.2, 1.1}) {
    const double eps = 1e-6;
    const double fd = (SeedH(p, z + eps) - SeedH(p, z - eps)) / (2 * eps);
    EXPECT_NEAR(SeedHPrime(p, z), fd, 1e-8) << z;
  }
}

TEST(Estimates, MisprintedDGivesOtherNumbersThatAreNotRoots) {
  const Params p;
  const SeedRoots good = ComputeSeedRoots(p, SeedDForm::kCorrected);
  const SeedRoots bad = ComputeSeedRoots(p, SeedDForm::kAsPrinted);
  ASSERT_TRUE(bad.applies);
  EXPECT_GT(std::abs(bad.r1 - good.r1), 0.05);  // -0.448 vs the printed -0.3574
  EXPECT_GT(std::abs(bad.r2 - good.r2), 0.05);  // 1.198 vs the printed 1.1074
  EXPECT_GT(std::abs(SeedH(p, bad.r1)), 1e-3);
  EXPECT_GT(std::abs(SeedH(p, bad.r2)), 1e-3);
}

TEST(Estimates, FittedBoundsHoldAndAreTight) {
  const Params p;
  const SeedBounds b = FitSeedBounds(p);
  ASSERT_TRUE(b.roots.applies);
  const double r1 = b.roots.r1;
  for (const BoundFit* f : {&b.a1, &b.a2}) {
    EXPECT_EQ(f->status, BoundStatus::kFitted) << f->reason;
    EXPECT_TRUE(f->holds) << f->worst_violation;
    EXPECT_GT(f->a, 0.0);
    EXPECT_GE(f->nlopt_code, 1);
  }
  EXPECT_DOUBLE_EQ(b.a1.lo, r1);
  EXPECT_DOUBLE_EQ(b.a1.hi, p.v);
  EXPECT_DOUBLE_EQ(b.a2.lo, 2 * r1);  // the documented fallback
  // Tight: equal to the brute-force extreme of the same constraint ...
  EXPECT_NEAR(b.a1.a, BruteA1(p, r1), 1e-6);
  EXPECT_NEAR(b.a2.a, BruteA2(p, r1, 2 * r1), 1e-6);
  // ... and to the closed forms: -h(v)/v and the slope limit k3 sqrt(D) at r1.
  EXPECT_NEAR(b.a1.a, p.k1() - 2 * p.beta - p.k3() * p.v * p.v, 1e-9);
  EXPECT_NEAR(b.a2.a, p.k3() * std::sqrt(b.roots.d), 1e-9);

  // The seed's inequalities themselves, on a fine grid.
  const double a1 = b.a1.a, a2 = b.a2.a;
  for (int i = 0; i <= 100000; ++i) {
    const double x = r1 + (p.v - r1) * i / 100000.0;
    const double xh = x * SeedH(p, x);
    EXPECT_LE(xh, 1e-15);                                   // (3.18) left
    EXPECT_GE(xh - x * (-a1 * x), -1e-12) << "x1 = " << x;  // (3.18) right
  }
  for (int i = 0; i < 100000; ++i) {
    const double x = 4 * r1 + (r1 - 4 * r1) * i / 100000.0;  // beyond x1_low too
    EXPECT_GT(x * SeedH(p, x) - x * (-a2 * (x * x - r1 * r1)), -1e-12) << "x1 = " << x;  // (3.20)
  }
  // A slightly looser a1 / tighter a2 is violated: they are the extremes.
  EXPECT_LT(p.v * SeedH(p, p.v) + (a1 - 1e-6) * p.v * p.v, 0.0);
  const double x = r1 - 1e-3;
  EXPECT_LT(x * SeedH(p, x) + (a2 + 1e-3) * x * (x * x - r1 * r1), 0.0);
}

TEST(Estimates, LowerEndOfD2IsHonoured) {
  const Params p;
  BoundFitOptions o;
  o.x1_low = -0.5;
  const SeedBounds b = FitSeedBounds(p, o);
  EXPECT_DOUBLE_EQ(b.a2.lo, -0.5);
  EXPECT_NEAR(b.a2.a, BruteA2(p, b.roots.r1, -0.5), 1e-6);
  o.x1_low = -0.3;  // the orbit never goes below r1
  const SeedBounds c = FitSeedBounds(p, o);
  EXPECT_EQ(c.a2.status, BoundStatus::kFitted);
  EXPECT_FALSE(c.a2.reason.empty());
  EXPECT_NEAR(c.a2.a, p.k3() * std::sqrt(c.roots.d), 1e-9);
}

TEST(Estimates, SeedChainAtTheSeedSet) {
  const Params p;
  // As printed, y1 needs y0^2 + (v - a1 y0)^2 >= r1^2, false here (a1 = 0.3125 is not << 1).
  const SeedEstimate paper = EstimateSeed(p);
  EXPECT_FALSE(paper.applies);
  EXPECT_NE(paper.reason.find("y1"), std::string::npos) << paper.reason;
  EXPECT_NEAR(paper.velocity_amplitude, -0.3574, 5e-5);
  EXPECT_NEAR(paper.y0, 0.375 - 0.296875, 1e-14);
  EXPECT_NEAR(paper.displacement_bound, std::hypot(paper.y0, 0.25 - 0.3125 * paper.y0), 1e-9);
  EXPECT_NEAR(paper.x_max_bound - paper.x_min_bound, 2 * paper.displacement_bound, 1e-14);

  SeedEstimateOptions o;
  o.y1_rule = SeedY1Rule::kExactCrossing;
  const SeedEstimate e = EstimateSeed(p, o);
  ASSERT_TRUE(e.applies) << e.reason;
  EXPECT_GT(e.y1, 0);
  EXPECT_LT(e.c, 1);
  // y2 (3.27) solves the Pade form of (3.26) only with 2 a2 in place of a2.
  EXPECT_NEAR(e.y2, -e.y1 / (1 + e.bounds.a2.a * e.y1), 1e-15);
  EXPECT_NEAR((1 + 2 * e.bounds.a2.a * e.y2_exact) * std::exp(-2 * e.bounds.a2.a * e.y2_exact), e.c,
              1e-12);
  EXPECT_LT(e.y2_exact, 0);
  EXPECT_LT(e.ydot_m, e.velocity_amplitude);  // below r1
  EXPECT_NEAR(
      e.ydot_m * e.ydot_m,
      e.velocity_amplitude * e.velocity_amplitude + (1 - e.c) / (2 * e.bounds.a2.a * e.bounds.a2.a),
      1e-12);
  EXPECT_DOUBLE_EQ(e.min_velocity_bound, e.velocity_amplitude + e.ydot_m);
  EXPECT_LT(e.y3, 0);
  EXPECT_TRUE(e.y3_in_stick);
  EXPECT_LT(e.y3, -e.y0);  // the seed's "y3 >= -y0" does not hold

  Params slow;
  slow.v = 0.1;  // (3.22) returns to y' = v before it reaches r1 = -0.609
  const SeedEstimate s = EstimateSeed(slow, o);
  EXPECT_FALSE(s.applies);
  EXPECT_NE(s.reason.find("y1"), std::string::npos) << s.reason;
}

TEST(Estimates, AveragingMatchesPrintedNumbers) {
  Params p;
  const AveragingEstimate e = EstimateAveraging(p);
  EXPECT_NEAR(e.amplitude, 0.7265, 5e-5);
  EXPECT_NEAR(e.grazing_speed, 0.3944, 5e-5);
  EXPECT_NEAR(e.hopf_speed, 0.44096, 5e-6);
  EXPECT_FALSE(e.applies);  // a_ps > v: the orbit sticks
  p.v = e.grazing_speed;    // a_ps = v there
  EXPECT_NEAR(EstimateAveraging(p).amplitude, p.v, 1e-12);
  p.v = 0.42;
  EXPECT_TRUE(EstimateAveraging(p).applies);
  // Hopf estimate of beta at fixed v: the linear coefficient of h vanishes.
  p.beta = EstimateAveraging(p).hopf_beta;
  EXPECT_NEAR(SeedHPrime(p, 0.0), 0.0, 1e-15);
  EXPECT_FALSE(EstimateAveraging(p).applies);  // a_ps = 0 (or NaN by rounding)
}

TEST(Estimates, NotApplicablePastVMax) {
  Params p;
  p.v = 0.45;  // > v_max = 0.44096
  const SeedRoots r = ComputeSeedRoots(p);
  EXPECT_FALSE(r.applies);
  EXPECT_FALSE(r.reason.empty());
  const SeedBounds b = FitSeedBounds(p);
  EXPECT_EQ(b.a1.status, BoundStatus::kNotApplicable);
  EXPECT_EQ(b.a2.status, BoundStatus::kNotApplicable);
  const SeedEstimate e = EstimateSeed(p);
  EXPECT_FALSE(e.applies);
  EXPECT_TRUE(std::isnan(e.velocity_amplitude));
  const AveragingEstimate a = EstimateAveraging(p);
  EXPECT_FALSE(a.applies);
  EXPECT_TRUE(std::isnan(a.amplitude));
}

TEST(Estimates, RejectsNonCubicLawsAndBadOptions) {
  for (LawKind law : {LawKind::kCoulomb, LawKind::kStribeck, LawKind::kLeine}) {
    Params p;
    p.law = law;
    try {
      EstimateSeed(p);
      ADD_FAILURE() << "no throw for " << Name(law);
    } catch (const InvalidArgument& e) {
      EXPECT_NE(std::string(e.what()).find(Name(law)), std::string::npos) << e.what();
    }
    EXPECT_THROW(ComputeSeedRoots(p), InvalidArgument);
    EXPECT_THROW(EstimateAveraging(p), InvalidArgument);
    EXPECT_THROW(SeedH(p, 0.1), InvalidArgument);
  }
  BoundFitOptions o;
  o.fit_points = 2;
  EXPECT_THROW(FitSeedBounds(Params(), o), InvalidArgument);
  o = BoundFitOptions();
  o.check_points = 10;
  EXPECT_THROW(FitSeedBounds(Params(), o), InvalidArgument);
  o = BoundFitOptions();
  o.x1_low = -HUGE_VAL;
  EXPECT_THROW(FitSeedBounds(Params(), o), InvalidArgument);
  Params bad;
  bad.mu_m = 0.5;  // >= mu_s
  EXPECT_THROW(EstimateSeed(bad), InvalidArgument);
}

}  // namespace
}  // namespace stickslip

namespace stickslip {
namespace {

// The claim of docs/validation.md: with the tightest a1 the chain (3.21)-(3.30), as printed,
// completes at no belt speed below v_max.
TEST(Estimates, PrintedChainCompletesNowhereBelowVMax) {
  Params p;
  const double v_max = SeedVMax(p);
  int tried = 0;
  for (double v = 0.01; v < v_max; v += 0.01, ++tried) {
    p.v = v;
    const SeedEstimate e = EstimateSeed(p);
    EXPECT_FALSE(e.applies) << "v = " << v;
    EXPECT_FALSE(e.reason.empty()) << "v = " << v;
  }
  EXPECT_GE(tried, 40);
}

}  // namespace
}  // namespace stickslip
