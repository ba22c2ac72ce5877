// A start in stick on the static limit (ReleasedAtEdge, switching.hpp): the
// belt (seed eq. 3.5) sticks while |x + 2 beta v| <= mu_s and x grows as v t,
// so from x0 inside the band it leaves at the closed-form time
// (mu_s - 2 beta v - x0) / v; from the band's edge itself, where the stick
// force moves out, it leaves at once (before: the exit root at t = 0 was no
// event, and the block stayed stuck past its limit for good). At the other
// edge the force moves in: it stays.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <vector>

#include "stickslip/flow/flow.hpp"
#include "stickslip/flow/switching.hpp"
#include "stickslip/systems/belt/model.hpp"

namespace {

using namespace stickslip;

std::vector<FlowSwitch> RunFrom(const Model& m, double x0, double t_max, FlowRun* r) {
  Flow flow(m, FlowOptions());
  std::vector<FlowSwitch> switches;
  FlowRequest rq;
  rq.t_max = t_max;
  rq.switches = &switches;
  *r = flow.Run(FlowPoint{0, Eigen::Vector2d(x0, m.v()), ModeSet(Mode::kStick)}, rq);
  return switches;
}

TEST(StickEdge, AStartOnTheLimitLeavesAtOnceAndInsideAtTheClosedForm) {
  const Model m{Params()};  // the seed set: beta 0.05, v 0.25, mu_s 0.4
  const double edge = m.params().mu_s - 2 * m.beta() * m.v();
  FlowRun r;
  std::vector<FlowSwitch> s = RunFrom(m, edge - 0.1, 1.0, &r);
  ASSERT_EQ(s.size(), 1u);
  EXPECT_EQ(s[0].kind, SwitchKind::kStickOut);
  EXPECT_NEAR(s[0].t, 0.1 / m.v(), 1e-13);
  RunFrom(m, edge, 1.0, &r);
  EXPECT_EQ(r.modes.front()[0], Mode::kSlipBelow);  // released at t = 0
  EXPECT_LT(r.end.z[1], m.v());                     // and slipping below since
  const ModeSet stick(Mode::kStick);
  EXPECT_EQ(ReleasedAtEdge(m, stick, Eigen::Vector2d(edge, m.v()))[0], Mode::kSlipBelow);
  // The lower edge, x + 2 beta v = -mu_s: the stick force grows back into the band.
  const double lower = -m.params().mu_s - 2 * m.beta() * m.v();
  EXPECT_EQ(ReleasedAtEdge(m, stick, Eigen::Vector2d(lower, m.v()))[0], Mode::kStick);
}

}  // namespace
