// The response grid of two unequal blocks (m2 = 1.3, studies/chain2.ini
// otherwise) in (v, kc) (Responses, response_grid.hpp) against the orbit a
// run settles on (SettleOnStickSlip, settle.hpp: a transient, the recurring
// stick exit and Newton on its map): every row's first cell starts from the
// belt start, so where that cell is periodic, the orbit settled on from the
// same start sticks as often per period.
#include <gtest/gtest.h>

#include <cstdio>

#include "chain/chain.hpp"
#include "stickslip/chart/response_grid.hpp"
#include "stickslip/orbits/settle.hpp"
#include "stickslip/systems/belt/model.hpp"

namespace stickslip::chain {
namespace {

Chain UnequalBlocks(double v, double kc) {
  Params p;  // the seed's cubic law, beta 0.05
  p.v = v;
  ChainParams c = Uniform(2, p, kc);
  c.blocks[1].m = 1.3;
  return Chain(c);
}

TEST(ChainResponse, FirstCellsStickAsTheSettledOrbit) {
  const Chain base = UnequalBlocks(0.2, 0.5);
  SystemPlane pl;
  pl.p1 = base.ParameterIndex("v"), pl.p2 = base.ParameterIndex("kc");
  pl.from1 = 0.1, pl.to1 = 0.5, pl.from2 = 0.1, pl.to2 = 1;
  ResponseOptions o;
  o.n1 = 4, o.n2 = 6;
  const ResponseGrid g = Responses(base, pl, o);
  ASSERT_EQ(g.failed, 0) << g.failure;
  int checked = 0;
  for (int j = 0; j < g.n2; ++j) {
    const Attractor& a = g.at(0, j);
    if (a.kind != AttractorKind::kPeriodic || a.sticks == 0) continue;
    const Chain s = UnequalBlocks(g.x1[0], g.x2[j]);
    const SettledOrbit st = SettleOnStickSlip(s, BeltStart(s).z, SettleOptions());
    ASSERT_TRUE(st.found) << "kc = " << g.x2[j] << ": " << st.message;
    EXPECT_EQ(st.orbit.sticks, a.sticks) << "kc = " << g.x2[j] << ", m " << a.m;
    ++checked;
  }
  std::printf("[ measured ] %d first cells checked; grid in %.3f s\n", checked, g.seconds);
  EXPECT_GE(checked, 3);
}

}  // namespace
}  // namespace stickslip::chain
