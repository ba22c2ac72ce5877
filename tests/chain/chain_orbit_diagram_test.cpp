// The orbit diagram of a chain of two identical blocks (issue 32 item 3):
// each sweep starts from rest on the belt, both blocks stuck at x = 0, a start
// the dynamics keep symmetric, so every value settles on the blocks-in-step
// orbit (stable there): the single block's, whose maximum of x on x' = 0
// falling the belt's own 2-D orbit finder gives (an independent code path).
#include <gtest/gtest.h>

#include <cmath>

#include "chain/chain.hpp"
#include "stickslip/chaos/orbit_diagram.hpp"
#include "stickslip/errors.hpp"
#include "stickslip/orbits/orbit_scan.hpp"
#include "stickslip/systems/belt/model.hpp"

namespace stickslip::chain {
namespace {

Params SeedCubic(double v) {
  Params p;
  p.law = LawKind::kCubic;
  p.beta = 0.05, p.mu_s = 0.4, p.mu_m = 0.25, p.v_m = 0.5, p.v = v;
  return p;
}

TEST(ChainOrbitDiagram, BlocksStartedTogetherRunTheSingleBlocksOrbitAtEveryValue) {
  const Chain chain(Uniform(2, SeedCubic(0.3), 0.5));
  OrbitDiagramOptions o;
  o.from = 0.26, o.to = 0.34, o.n = 3, o.down = false;
  o.iterate.transient = 200, o.iterate.keep = 20, o.iterate.align = 20, o.iterate.batches = 4;
  const int v = chain.ParameterIndex("v");
  ASSERT_GE(v, 0);
  const OrbitDiagram d = ComputeOrbitDiagram(chain, v, o);
  ASSERT_TRUE(d.error.empty()) << d.error;
  ASSERT_EQ(d.failed, 0);
  ASSERT_EQ(d.columns.size(), 3u);
  for (const DiagramColumn& c : d.columns) {
    SCOPED_TRACE("v = " + std::to_string(c.value));
    ASSERT_EQ(c.run.status, LyapunovStatus::kDone) << c.run.message;
    const PeriodicOrbits belt = FindPeriodicOrbits(Model(SeedCubic(c.value)), OrbitScanOptions());
    ASSERT_TRUE(belt.has_stick_slip);
    ASSERT_EQ(c.run.points.size(), 20u);
    for (const SectionPoint& q : c.run.points) {
      EXPECT_NEAR(q.z[0], belt.stick_slip.extrema.x_max, 1e-9);
      EXPECT_NEAR(q.z[2], q.z[0], 1e-9);  // in step
      EXPECT_EQ(q.sticks, 2);
      EXPECT_NEAR(q.dt, belt.stick_slip.period, 1e-9);
    }
    EXPECT_LT(c.run.lyapunov, 0);
  }
}

// Above the Hopf point (v = 0.441) steady sliding is the attractor: a value
// settled there is one row at x_i = mu(v), and its exponent is the real part
// of steady sliding's complex pair, -(2 beta + mu'(v)) / 2 (both modes of the
// stiffness share the damping; docs/theory.md, "A chain of blocks").
TEST(ChainOrbitDiagram, ValuesSettledOnSteadySlidingGiveItsPointAndExponentInClosedForm) {
  const Chain chain(Uniform(2, SeedCubic(0.45), 0.5));
  OrbitDiagramOptions o;
  o.from = 0.45, o.to = 0.47, o.n = 3, o.down = false;
  const OrbitDiagram d = ComputeOrbitDiagram(chain, chain.ParameterIndex("v"), o);
  ASSERT_EQ(d.failed, 0);
  int settled = 0;
  for (const DiagramColumn& c : d.columns) {
    if (c.run.status != LyapunovStatus::kRest) continue;
    const double s = c.value / 0.5;
    const double mu = 0.4 - 1.5 * 0.15 * (s - s * s * s / 3), dmu = -0.45 * (1 - s * s);
    ASSERT_EQ(c.run.points.size(), 1u);
    EXPECT_NEAR(c.run.points[0].z[0], mu, 1e-12);
    EXPECT_NEAR(c.run.points[0].z[2], mu, 1e-12);
    EXPECT_NEAR(c.run.lyapunov, -(0.1 + dmu) / 2, 1e-12);
    ++settled;
  }
  EXPECT_GE(settled, 2);  // the first may still spiral after 700 returns
}

TEST(ChainOrbitDiagram, ASweptValueTheSystemRefusesThrows) {
  const Chain chain(Uniform(2, SeedCubic(0.3), 0.5));
  OrbitDiagramOptions o;
  o.from = -0.1, o.to = 0.3;  // v must be > 0
  EXPECT_THROW(ComputeOrbitDiagram(chain, chain.ParameterIndex("v"), o), InvalidArgument);
  o.from = 0.2;
  EXPECT_THROW(ComputeOrbitDiagram(chain, chain.parameters(), o), InvalidArgument);
}

}  // namespace
}  // namespace stickslip::chain
