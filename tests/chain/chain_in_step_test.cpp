// Two identical blocks started in step (x2 = x1 + 1e-15) stay in step: the
// synchronized stick-slip orbit attracts the difference (issue 32 item 1,
// contacts switching at once). Each instant where both arrive or leave to
// rounding must give both the same switch; a root lost to rounding used to
// leave one block slipping on the wrong side of its surface (|x1 - x2| jumped
// to 0.06), and a surface left with x'' = 1e-14 stalled the flow ("events
// repeat"). The difference obeys the linear transverse equation, so it can
// only shrink or grow smoothly, never jump.
#include <gtest/gtest.h>

#include <cmath>

#include "chain/chain.hpp"
#include "stickslip/flow/flow.hpp"

namespace stickslip::chain {
namespace {

TEST(ChainInStep, TwoBlocksStartedInStepStayInStepThroughEverySwitch) {
  Params p;
  p.law = LawKind::kCubic;
  p.beta = 0.05, p.mu_s = 0.4, p.mu_m = 0.25, p.v_m = 0.5, p.v = 0.3;
  const Chain chain(Uniform(2, p, 0.5));
  Flow flow(chain, FlowOptions());
  FlowPoint z;
  z.z = Eigen::Vector4d(0.65, 0, 0.65 + 1e-15, 0);
  z.mode = ModeOf(chain, z.z);
  double worst = 0;
  int sticks = 0;
  FlowRequest rq;
  rq.t_max = 3000;
  rq.step_observer = [&](double, const double* y, const ModeSet& m) {
    worst = std::max({worst, std::abs(y[0] - y[2]), std::abs(y[1] - y[3])});
    for (int i = 0; i < 2; ++i) {  // a slipping block on its own side of x' = v
      if (m[i] == Mode::kStick) continue;
      EXPECT_LE((m[i] == Mode::kSlipBelow ? 1 : -1) * (y[2 * i + 1] - 0.3), 1e-12);
    }
  };
  std::vector<FlowSwitch> switches;
  rq.switches = &switches;
  const FlowRun r = flow.Run(z, rq);
  ASSERT_EQ(r.status, FlowStatus::kTimeLimit) << r.message;
  for (const FlowSwitch& s : switches) sticks += s.kind == SwitchKind::kStickIn;
  EXPECT_GT(sticks, 2 * 400);  // both blocks, every period (6.46) of 3000
  EXPECT_LT(worst, 1e-9);
}

}  // namespace
}  // namespace stickslip::chain
