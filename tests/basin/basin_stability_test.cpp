// Exact basin stability (basin_stability.hpp) against an independent Monte
// Carlo estimate (uniform random starts, each followed by the flow until it
// sticks or settles; within 3 standard errors), against the app's grid
// classification (within the grid's resolution), against itself at tighter
// tolerances (1e-9), and on scenes whose answer is known (one attractor).
#include "stickslip/basin/basin_stability.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

namespace stickslip {
namespace {

Params Stribeck(double v) {  // studies/stribeck_basin.ini
  Params p;
  p.law = LawKind::kStribeck;
  p.beta = 0.05, p.v = v, p.mu_s = 0.4, p.mu_k = 0.25, p.v_s = 0.5;
  return p;
}

const Box kBox{-0.4, 1.0, -0.8, 0.7};  // cuts the unstable orbit (x in [-0.15, 0.74])

BasinStability Exact(const Params& p, const FlowOptions& flow = FlowOptions(), int samples = 4000) {
  const Model m(p);
  OrbitScanOptions scan;
  scan.orbit.flow = flow;
  return ExactBasinStability(m, FindPeriodicOrbits(m, scan), kBox, flow, samples);
}

TEST(BasinStability, StribeckSceneMatchesMonteCarloWithinThreeSigma) {
  const Params p = Stribeck(0.6);
  const BasinStability b = Exact(p);
  ASSERT_EQ(b.shares.size(), 2u);
  EXPECT_EQ(b.shares[0].Name(), "steady-sliding");
  EXPECT_EQ(b.shares[1].Name(), "stick-slip");
  EXPECT_NEAR(b.shares[0].fraction + b.shares[1].fraction, 1.0, 1e-15);
  // Independent classification: the flow from each start until it sticks
  // (then it is on the stick-slip orbit: every stick ends at the exit point),
  // or, unstuck after t = 2000, close to steady sliding.
  const Model m(p);
  BeltFlow flow(m, FlowOptions());
  const Vec2 xbar(m.SteadySliding().x, 0.0);
  std::mt19937_64 rng(20261124);
  std::uniform_real_distribution<double> ux(kBox.x_lo, kBox.x_hi), uy(kBox.y_lo, kBox.y_hi);
  const int n = 1500;
  int steady = 0, undecided = 0;
  for (int i = 0; i < n; ++i) {
    const Vec2 z(ux(rng), uy(rng));
    StopRule stop;
    stop.at_stick = true;
    stop.t_max = 2000;
    const FlowResult r = flow.Run(0.0, z, stop);
    ASSERT_TRUE(r.ok()) << r.message;
    if (r.status == FlowStatus::kStick) continue;
    if ((r.z - xbar).norm() < 1e-3)
      ++steady;
    else
      ++undecided;
  }
  EXPECT_EQ(undecided, 0);
  const double p_hat = static_cast<double>(steady) / n;
  const double sigma = std::sqrt(p_hat * (1 - p_hat) / n);
  std::printf("exact %.12f, Monte Carlo %.4f +- %.4f (n = %d)\n", b.Of(Fate::kSteadySliding), p_hat,
              sigma, n);
  EXPECT_NEAR(p_hat, b.Of(Fate::kSteadySliding), 3 * sigma)
      << "Monte Carlo " << p_hat << " +- " << sigma;
}

TEST(BasinStability, GridClassificationAgreesWithinItsResolution) {
  const Params p = Stribeck(0.6);
  BasinOptions o;
  o.auto_range = false;
  o.x_lo = kBox.x_lo, o.x_hi = kBox.x_hi, o.xdot_lo = kBox.y_lo, o.xdot_hi = kBox.y_hi;
  o.nx = o.ny = 61;
  const BasinResult r = ClassifyBasins(Model(p), o);
  ASSERT_FALSE(r.partial()) << r.message;
  const double grid = static_cast<double>(r.count[0]) / r.starts.size();
  const double exact = Exact(p).Of(Fate::kSteadySliding);
  // Only cells the boundary crosses can disagree: at most its length over
  // the cell size (about 3 / 0.024 = 130 of 3721 cells, 3.5 %).
  std::printf("exact %.12f, grid %.4f (%d of %zu)\n", exact, grid, r.count[0], r.starts.size());
  EXPECT_NEAR(grid, exact, 0.035);
  EXPECT_GT(exact, 0.1);
}

TEST(BasinStability, ConvergedTo1e9) {
  FlowOptions tight;
  tight.rtol = 1e-13, tight.atol = 1e-15;
  const double a = Exact(Stribeck(0.6)).Of(Fate::kSteadySliding);
  const double b = Exact(Stribeck(0.6), tight, 8000).Of(Fate::kSteadySliding);
  EXPECT_NEAR(a, b, 1e-9);
}

TEST(BasinStability, OneAttractorTakesTheWholeBox) {
  Params seed;  // v = 0.25: steady sliding unstable, no pure-slip orbit
  BasinStability b = Exact(seed);
  ASSERT_EQ(b.shares.size(), 1u);
  EXPECT_EQ(b.shares[0].Name(), "stick-slip");
  EXPECT_EQ(b.shares[0].fraction, 1.0);
  seed.v = 0.42;  // between GR 0.3958 and HB 0.4410: one stable pure-slip orbit, no stick-slip
  b = Exact(seed);
  ASSERT_EQ(b.shares.size(), 1u);
  EXPECT_EQ(b.shares[0].Name(), "pure-slip");
  EXPECT_EQ(b.shares[0].fraction, 1.0);
  ASSERT_EQ(b.enclosed.size(), 1u);
  EXPECT_GT(b.enclosed[0], 0.0);
}

TEST(BasinStability, SteadyBasinGrowsTowardsTheFoldAlongV) {
  OrbitScanOptions scan;
  const BasinStabilityCurve c =
      BasinStabilityAlong(Stribeck(0.6), ParameterAxis("v"), 0.56, 0.64, 5, kBox, scan);
  ASSERT_EQ(c.status, BasinStatus::kOk) << c.message;
  ASSERT_EQ(c.p.size(), 5u);
  for (size_t i = 1; i < c.p.size(); ++i)
    EXPECT_GT(c.at[i].Of(Fate::kSteadySliding), c.at[i - 1].Of(Fate::kSteadySliding)) << c.p[i];
  EXPECT_NEAR(c.at[2].Of(Fate::kSteadySliding), Exact(Stribeck(0.6)).Of(Fate::kSteadySliding),
              1e-14);
}

}  // namespace
}  // namespace stickslip
