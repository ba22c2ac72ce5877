// Modes as sets (switching.hpp, ConsistentMode): contacts that switch at one
// instant take the one consistent mode. The system here (mass_coupled.hpp)
// couples two blocks by their masses alone, M = [[1, e], [e, 1]], M x'' = g + r, g_i = -k x_i -
// c x_i', r_i the friction force of contact i (slip below: +mu_k, above:
// -mu_k; stick: the force that holds x_i'' = 0). A sticking contact's force
// then depends on whether the other one sticks: the contact-order rule can
// leave a set that is not consistent. The reference is the enumeration done
// by hand below (2 x 2 solves), and for e = -0.5, g = (0.3, 0.3):
//   contact order: 0 held with 1 below needs r0 = -g0 + e (g1 + mu_k) = -0.6,
//   past mu_s = 0.4, so 0 slips above; 1 held with 0 above needs r1 = -0.3:
//   {slip-above, stick}. But 0 held with 1 stuck needs r0 = -g0 = -0.3:
//   within, so 0 must stick; {stick, stick} is the one consistent set.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <vector>

#include "flow/mass_coupled.hpp"
#include "stickslip/errors.hpp"
#include "stickslip/flow/flow.hpp"
#include "stickslip/flow/switching.hpp"

namespace stickslip {
namespace {

ModeSet Both(Mode a, Mode b) {
  ModeSet m;
  m.set(0, a);
  m.set(1, b);
  return m;
}

// Both contacts on their surfaces with g = (-x1, -x2) (c = 0).
Eigen::VectorXd OnBoth(const Coupling& p, double x1, double x2) {
  Eigen::VectorXd z(4);
  z << x1, p.v, x2, p.v;
  return z;
}

TEST(ModeSets, ContactOrderIsInconsistentTheEnumerationIsNot) {
  const Coupling p;
  const MassCoupled s(p);
  const Eigen::VectorXd z = OnBoth(p, -0.3, -0.3);
  // The hand computation in the header comment.
  EXPECT_NEAR(s.StickForce(Both(Mode::kStick, Mode::kSlipBelow), 0, z), -0.6, 1e-15);
  EXPECT_NEAR(s.StickForce(Both(Mode::kStick, Mode::kStick), 0, z), -0.3, 1e-15);
  const ModeChoiceResult r = ModeChoiceOf(s, z);
  EXPECT_EQ(r.choice, ModeChoice::kUnique);
  EXPECT_EQ(r.consistent, 1);
  EXPECT_EQ(r.mode, Both(Mode::kStick, Mode::kStick));
  EXPECT_EQ(ModeOf(s, z), Both(Mode::kStick, Mode::kStick));
}

// A contact velocity with no term, or a term of weight 0, defines no
// surface: the flow refuses the system by name (ContactVelocityError).
TEST(ModeSets, ContactVelocityWithoutATermIsRefused) {
  Coupling p;
  p.terms = 0;
  try {
    const MassCoupled s(p);
    Flow flow(s, FlowOptions{});
    ADD_FAILURE() << "no terms accepted";
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find("contact 0's velocity has 0 terms"), std::string::npos)
        << e.what();
  }
  p = Coupling();
  p.weight = 0;
  EXPECT_THROW(Flow(MassCoupled(p), FlowOptions()), InvalidArgument);
  EXPECT_EQ(ContactVelocityError(MassCoupled(Coupling())), "");
}

TEST(ModeSets, OneContactGivesFilippovsRule) {
  const Coupling p;
  const MassCoupled s(p);
  Eigen::VectorXd z = OnBoth(p, -0.3, -0.3);
  z[3] = 0.1;  // contact 1 below its surface
  for (double x : {-0.5, -0.1, 0.0, 0.2, 0.6}) {
    z[0] = x;
    const ModeSet base = Both(Mode::kSlipBelow, Mode::kSlipBelow);
    const ModeChoiceResult r = ConsistentMode(s, base, {0}, z);
    EXPECT_EQ(r.choice, ModeChoice::kUnique) << x;
    EXPECT_EQ(r.mode, ModeAfterArrival(s, base, 0, z)) << x;
  }
}

// e = -0.8, g = (0.6, -0.6): {stick, slip-below} and {slip-above, stick}
// are both consistent (found by the same enumeration in Python, numpy 2x2).
TEST(ModeSets, TwoConsistentSetsAreAmbiguous) {
  Coupling p;
  p.e = -0.8;
  const MassCoupled s(p);
  const Eigen::VectorXd z = OnBoth(p, -0.6, 0.6);
  const ModeChoiceResult r = ModeChoiceOf(s, z);
  EXPECT_EQ(r.choice, ModeChoice::kAmbiguous);
  EXPECT_EQ(r.consistent, 2);
  EXPECT_EQ(r.candidates, 2);
  // {stick, below}: r0 = -g0 + e (g1 + mu_k) = -0.6 - 0.8 (-0.3) = -0.36.
  const ModeSet a = Both(Mode::kStick, Mode::kSlipBelow);
  EXPECT_NEAR(s.StickForce(a, 0, z), -0.36, 1e-15);
  EXPECT_GT(s.StickForce(Both(Mode::kStick, Mode::kStick), 1, z), p.mu_s);
}

// The flow: a symmetric start arrives on both surfaces at one instant
// (identical arithmetic) with g = -x in (1/6, 0.4]: both stick, the motion
// stays symmetric, and both leave at x = mu_s together.
TEST(ModeSets, SimultaneousArrivalTakesTheConsistentSet) {
  const Coupling p;
  const MassCoupled s(p);
  FlowOptions fo;
  fo.integrator = Integrator::kCvode;
  fo.rtol = 1e-10;
  fo.atol = 1e-12;
  Flow flow(s, fo);
  std::vector<FlowSwitch> sw;
  FlowRequest rq;
  rq.t_max = 20;
  rq.stop_at_exit = 1;
  rq.switches = &sw;
  Eigen::VectorXd z0(4);
  z0 << -0.35, 0, -0.35, 0;
  const FlowRun r = flow.Run(FlowPoint{0, z0, Both(Mode::kSlipBelow, Mode::kSlipBelow)}, rq);
  ASSERT_TRUE(r.ok()) << r.message;
  ASSERT_EQ(r.status, FlowStatus::kStickExit);
  ASSERT_EQ(sw.size(), 4u);
  EXPECT_EQ(sw[0].kind, SwitchKind::kStickIn);
  EXPECT_EQ(sw[1].kind, SwitchKind::kStickIn);
  EXPECT_EQ(sw[0].t, sw[1].t);
  EXPECT_EQ(sw[1].after, Both(Mode::kStick, Mode::kStick));
  // Closed form of the slip: x'' = (0.3 - x) / (1 + e) from (-0.35, 0).
  const double w = std::sqrt(1 / (1 + p.e)), a = 0.65;
  const double t_in = std::asin(p.v / (a * w)) / w;
  EXPECT_NEAR(sw[0].t, t_in, 1e-8);
  EXPECT_NEAR(sw[0].z[0], 0.3 - a * std::cos(w * t_in), 1e-8);
  // Stick at x' = v to x = mu_s, where both leave into slip below.
  EXPECT_EQ(sw[2].kind, SwitchKind::kStickOut);
  EXPECT_EQ(sw[3].kind, SwitchKind::kStickOut);
  EXPECT_NEAR(r.end.t, t_in + (p.mu_s - sw[0].z[0]) / p.v, 1e-8);
  EXPECT_EQ(r.end.mode, Both(Mode::kSlipBelow, Mode::kSlipBelow));
  EXPECT_EQ(r.end.z[0], r.end.z[2]);
}

}  // namespace
}  // namespace stickslip
