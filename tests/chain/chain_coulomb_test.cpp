// The coulomb chain (studies' chain2_coulomb: mu_s 0.4, mu_k 0.3, beta 0,
// kc 0.5, v 0.2) against its closed form (chain_coulomb_reference.hpp): every
// piece exp(t [[A, b], [0, 0]]) (z0, 1) in long double, switch times bisected.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "chain/chain.hpp"
#include "chain/chain_coulomb_reference.hpp"
#include "stickslip/flow/flow.hpp"

namespace stickslip::chain {
namespace {

using namespace coulomb_reference;

TEST(ChainCoulomb, TrajectoryMatchesClosedFormPieces) {
  const Coulomb q;
  Params p;
  p.law = LawKind::kCoulomb;
  p.mu_s = 0.4;
  p.mu_k = 0.3;
  p.beta = 0;
  p.v = 0.2;
  const Chain chain(Uniform(2, p, 0.5));
  const double t_max = 40;
  Vec z0{0.1L, 0, -0.25L, 0.05L, 1};
  int m[2] = {0, 0};
  std::vector<Switch> ref;
  const Vec zr = Walk(q, z0, m, t_max, &ref);
  ASSERT_GE(ref.size(), 8u);

  FlowOptions fo;
  fo.rtol = 1e-13;
  fo.atol = 1e-15;
  Flow flow(chain, fo);
  std::vector<FlowSwitch> sw;
  FlowRequest rq;
  rq.t_max = t_max;
  rq.switches = &sw;
  Eigen::VectorXd z(4);
  z << 0.1, 0, -0.25, 0.05;
  ModeSet below;
  below.set(1, Mode::kSlipBelow);
  const FlowRun r = flow.Run(FlowPoint{0, z, below}, rq);
  ASSERT_TRUE(r.ok()) << r.message;
  std::vector<FlowSwitch> changes;
  for (const FlowSwitch& s : sw)
    if (s.kind != SwitchKind::kTouch) changes.push_back(s);
  ASSERT_EQ(changes.size(), ref.size());
  for (size_t k = 0; k < ref.size(); ++k) {
    EXPECT_NEAR(changes[k].t, double(ref[k].t), 1e-10) << k;
    EXPECT_EQ(changes[k].contact, ref[k].block) << k;
  }
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(r.end.z[i], double(zr[i]), 1e-10) << i;
  EXPECT_EQ(r.end.mode[0] == Mode::kStick, m[0] == 1);
  EXPECT_EQ(r.end.mode[1] == Mode::kStick, m[1] == 1);
}

}  // namespace
}  // namespace stickslip::chain
