// The chain of blocks (systems/chain/chain.hpp) against independent
// references: one block without coupling is the seed belt (model.hpp, its
// own Taylor recurrences); two identical blocks started together move as
// one, on the seed's orbit.
#include "chain/chain.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "stickslip/flow/flow.hpp"
#include "stickslip/orbits/shooting.hpp"
#include "stickslip/systems/belt/model.hpp"

namespace stickslip::chain {
namespace {

FlowOptions Tight() {
  FlowOptions fo;
  fo.rtol = 1e-13;
  fo.atol = 1e-15;
  return fo;
}

// The belt and the one-block chain from the same start, through slip,
// stick and exits, to t = 60: the same state to 1e-12.
TEST(Chain, OneBlockIsTheBelt) {
  for (LawKind law : {LawKind::kCubic, LawKind::kCoulomb, LawKind::kStribeck, LawKind::kLeine}) {
    Params p;
    p.law = law;
    p.mu_k = 0.3;
    p.v_s = 0.3;
    p.delta = 2;
    const Model belt(p);
    const Chain chain(Uniform(1, p, 0));
    Flow fb(belt, Tight()), fc(chain, Tight());
    FlowRequest rq;
    rq.t_max = 60;
    const FlowPoint start{0, Eigen::Vector2d(0.9, -0.2), ModeSet(Mode::kSlipBelow)};
    const FlowRun rb = fb.Run(start, rq), rc = fc.Run(start, rq);
    ASSERT_TRUE(rb.ok() && rc.ok()) << rb.message << rc.message;
    ASSERT_GE(rb.sticks, 1) << Name(law);
    EXPECT_EQ(rc.switches, rb.switches) << Name(law);
    EXPECT_EQ(rc.end.mode, rb.end.mode) << Name(law);
    EXPECT_NEAR(rc.end.z[0], rb.end.z[0], 1e-12) << Name(law);
    EXPECT_NEAR(rc.end.z[1], rb.end.z[1], 1e-12) << Name(law);
    EXPECT_NEAR(rc.t_stick, rb.t_stick, 1e-12) << Name(law);
  }
}

// The stick-exit orbit of the seed set by the one shooting on both systems.
TEST(Chain, OneBlockOrbitIsTheBeltsOrbit) {
  const Params p;
  const Model belt(p);
  const Chain chain(Uniform(1, p, 0));
  ShootingOptions so;
  so.flow = Tight();
  Shooting sb(belt, so), sc(chain, so);
  const FlowPoint start{0, Eigen::Vector2d(0.3, p.v), ModeSet(Mode::kSlipBelow)};
  const PeriodicOrbit ob = sb.Find(start, PoincareSection::StickExit(0));
  const PeriodicOrbit oc = sc.Find(start, PoincareSection::StickExit(0));
  ASSERT_TRUE(ob.ok() && oc.ok()) << ob.message << oc.message;
  EXPECT_NEAR(oc.period, ob.period, 1e-12);
  EXPECT_NEAR(oc.start.z[0], ob.start.z[0], 1e-15);
  ASSERT_EQ(oc.multipliers.size(), ob.multipliers.size());
  for (size_t i = 0; i < ob.multipliers.size(); ++i)
    EXPECT_NEAR(std::abs(oc.multipliers[i] - ob.multipliers[i]), 0.0, 1e-12);
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(oc.monodromy(i), ob.monodromy(i), 1e-12) << i;
  EXPECT_NEAR(oc.hi[0], ob.hi[0], 1e-12);
  EXPECT_NEAR(oc.lo[0], ob.lo[0], 1e-12);
}

// Two identical blocks started together: x1 = x2 at all times (their
// arithmetic is the same), so the orbit is the seed's, both blocks sticking
// and leaving at one instant (ConsistentMode), whatever the coupling.
TEST(Chain, SynchronizedBlocksRunTheSeedOrbit) {
  Params p;
  p.beta = 0.05;
  const Model belt(p);
  ShootingOptions so;
  so.flow = Tight();
  Shooting sb(belt, so);
  const PeriodicOrbit ob =
      sb.Find(FlowPoint{0, Eigen::Vector2d(0.3, p.v), ModeSet(Mode::kSlipBelow)},
              PoincareSection::StickExit(0));
  ASSERT_TRUE(ob.ok()) << ob.message;
  const Chain chain(Uniform(2, p, 0.2));
  Shooting sc(chain, so);
  Eigen::VectorXd z(4);
  z << ob.start.z[0], p.v, ob.start.z[0], p.v;
  ModeSet below;
  below.set(1, Mode::kSlipBelow);
  const PeriodicOrbit oc = sc.Find(FlowPoint{0, z, below}, PoincareSection::StickExit(0));
  ASSERT_TRUE(oc.ok()) << oc.message;
  EXPECT_NEAR(oc.period, ob.period, 1e-12);
  EXPECT_EQ(oc.start.z[0], oc.start.z[2]);
  EXPECT_EQ(oc.sticks, 2);
  EXPECT_EQ(oc.exits, 2);
  EXPECT_NEAR(oc.hi[0], ob.hi[0], 1e-12);
  EXPECT_NEAR(oc.lo[0], ob.lo[0], 1e-12);
  EXPECT_NEAR(oc.hi[2], ob.hi[0], 1e-12);
  ASSERT_EQ(oc.multipliers.size(), 3u);
}

// Twenty identical blocks started in step stay in step (to rounding) on the
// one block's motion: at every stick entry and exit they switch within
// rounding of one instant, each in turn (the flow allows two switches per
// contact at one t; eight in all stopped twelve blocks at t = 81).
TEST(Chain, TwentyBlocksInStepRunTheOneBlocksMotion) {
  Params p;
  const Chain one(Uniform(1, p, 0)), twenty(Uniform(20, p, 0.5));
  FlowRequest rq;
  rq.t_max = 300;
  Flow f1(one, Tight()), f20(twenty, Tight());
  const FlowRun r1 = f1.Run(FlowPoint{0, Eigen::Vector2d(0.1, 0.0), ModeSet()}, rq);
  Eigen::VectorXd z(40);
  for (int i = 0; i < 20; ++i) z[2 * i] = 0.1, z[2 * i + 1] = 0.0;
  const FlowRun r20 = f20.Run(FlowPoint{0, z, ModeSet()}, rq);
  ASSERT_EQ(r1.status, FlowStatus::kTimeLimit) << r1.message;
  ASSERT_EQ(r20.status, FlowStatus::kTimeLimit) << r20.message;
  EXPECT_EQ(r20.sticks, 20 * r1.sticks);
  for (int i = 0; i < 20; ++i) {
    EXPECT_NEAR(r20.end.z[2 * i], r1.end.z[0], 1e-8) << i;
    EXPECT_NEAR(r20.end.z[2 * i + 1], r1.end.z[1], 1e-8) << i;
  }
}

}  // namespace
}  // namespace stickslip::chain
