// Basins of a chain of two blocks on a 2-D slice of its 4-D state (issue 32
// item 3, through the one classifier of issue 31 item 6): starts in (x1, x1')
// with block 2 at steady sliding, classified on the returns to x1' = 0
// falling. Steady sliding (x_i = mu(v) for identical blocks, the springs
// between them unstretched) is unstable at v = 0.3: the one start placed on
// it stays there and is undecided, not a rest attractor. Each periodic
// attractor's section point must be a fixed point that an independent Newton
// solve (the one shooting on the same surface) converges to, and stable.
// The attractor with the blocks in step (x1 = x2) is the single block's
// orbit, the spring between them unstretched: its period must be the belt's
// stick-slip period, from the belt's own 2-D orbit finder.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "chain/chain.hpp"
#include "stickslip/basin/attractors.hpp"
#include "stickslip/io/attractor_report.hpp"
#include "stickslip/orbits/orbit_scan.hpp"
#include "stickslip/orbits/shooting.hpp"
#include "stickslip/systems/belt/model.hpp"

namespace stickslip::chain {
namespace {

Params CubicBelt(double v) {  // studies/chain2.ini
  Params p;
  p.law = LawKind::kCubic;
  p.beta = 0.05, p.mu_s = 0.4, p.mu_m = 0.25, p.v_m = 0.5, p.v = v;
  return p;
}

// The seed's cubic law mu(s) = mu_s - 3/2 (mu_s - mu_m) (s/v_m - (s/v_m)^3 / 3).
double CubicMu(double s) { return 0.4 - 1.5 * 0.15 * (s / 0.5 - std::pow(s / 0.5, 3) / 3); }

TEST(ChainAttractors, EveryOrbitIsAFixedPointOfTheShootingAndUnstableRestAttractsNothing) {
  const double v = 0.3;  // steady sliding unstable: 2 beta + mu'(v) = -0.188 < 0
  const Chain chain(Uniform(2, CubicBelt(v), 0.5));
  const double xbar = CubicMu(v);
  AttractorOptions o;
  o.slice.base = Eigen::Vector4d(xbar, 0, xbar, 0);
  o.slice.lo = {xbar - 1.2, -1.2}, o.slice.hi = {xbar + 1.2, 1.2};
  o.slice.n = {7, 7};
  const AttractorBasins b = ClassifyAttractors(chain, o);
  ASSERT_TRUE(b.error.empty()) << b.error;
  for (const AttractorStart& s : b.starts) {  // only the centre, steady sliding itself
    const bool centre = std::abs(s.at[0] - xbar) < 1e-12 && s.at[1] == 0;
    EXPECT_EQ(s.message.empty(), !centre) << s.at[0] << " " << s.at[1] << ": " << s.message;
    if (centre) {
      EXPECT_NE(s.message.find("unstable rest point"), std::string::npos) << s.message;
    }
  }
  ASSERT_EQ(b.failed, 0);
  int rest = 0, periodic = 0, in_step = 0;  // rest: the undecided centre
  ShootingOptions so;
  Shooting shooting(chain, so);
  for (const Attractor& a : b.attractors) {
    SCOPED_TRACE(AttractorLabel(a));
    std::printf("[ measured ] %s: x1 = %.10g, %d starts\n", AttractorLabel(a).c_str(), a.z[0],
                a.starts);
    ASSERT_EQ(a.z.size(), 4);
    if (a.kind == AttractorKind::kUndecided) {
      rest += a.starts;
      continue;
    }
    ASSERT_EQ(a.kind, AttractorKind::kPeriodic);
    PoincareSection section;
    section.kind = SectionKind::kSurface;
    section.surface = MaximaSection(chain);
    section.returns = a.m;
    FlowPoint guess;
    guess.z = a.z;
    guess.mode = ModeOf(chain, guess.z);
    const PeriodicOrbit orbit = shooting.Find(guess, section);
    ASSERT_TRUE(orbit.ok()) << orbit.message;
    EXPECT_LT((orbit.start.z - a.z).lpNorm<Eigen::Infinity>(), 1e-6);
    EXPECT_TRUE(orbit.stable);
    EXPECT_EQ(orbit.sticks, a.sticks);
    if (std::abs(a.z[0] - a.z[2]) < 1e-8) {  // in step: the single block's orbit
      const PeriodicOrbits belt = FindPeriodicOrbits(Model(CubicBelt(v)), OrbitScanOptions());
      ASSERT_TRUE(belt.has_stick_slip);
      EXPECT_NEAR(orbit.period, belt.stick_slip.period, 1e-9);
      EXPECT_NEAR(a.z[0], belt.stick_slip.extrema.x_max, 1e-9);
      ++in_step;
    }
    periodic += a.starts;
  }
  EXPECT_EQ(rest, 1);  // the box's centre
  EXPECT_GT(periodic, 0);
  EXPECT_EQ(in_step, 1);
  EXPECT_EQ(rest + periodic, 49);
}

}  // namespace
}  // namespace stickslip::chain
