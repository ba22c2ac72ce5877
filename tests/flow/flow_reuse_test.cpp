// One Flow handed a new system (set_system) computes what a new Flow does:
// its event sets and rest points are kept only where the contacts are the
// same, and the Taylor field is bound again to the new parameter values.
#include <gtest/gtest.h>

#include <Eigen/Dense>

#include "stickslip/flow/flow.hpp"
#include "stickslip/systems/belt/model.hpp"
#include "stickslip/systems/forced/forced.hpp"

namespace {

using namespace stickslip;

FlowRun RunBelt(Flow& flow, double x0) {
  FlowPoint start;
  start.z = Eigen::Vector2d(x0, 0.0);
  start.mode = ModeSet(Mode::kSlipBelow);
  FlowRequest rq;
  rq.t_max = 40;
  rq.variational = true;
  rq.extrema = {0, 1};
  return flow.Run(start, rq);
}

// The forced oscillator's slip start at x = 0.1 and a 30-long run with Phi.
FlowPoint ForcedStart() {
  FlowPoint start;
  start.z = Eigen::Vector3d(0.1, 0.0, 0.0);
  start.mode = ModeSet(Mode::kSlipBelow);
  return start;
}
FlowRequest WithPhi() {
  FlowRequest rq;
  rq.t_max = 30;
  rq.variational = true;
  return rq;
}

void ExpectSame(const FlowRun& a, const FlowRun& b) {
  EXPECT_EQ(a.status, b.status);
  EXPECT_EQ(a.sticks, b.sticks);
  EXPECT_EQ(a.steps, b.steps);
  EXPECT_EQ(a.end.t, b.end.t);
  EXPECT_EQ(a.end.z, b.end.z);  // bit for bit: the same computation
  EXPECT_EQ(a.jacobian, b.jacobian);
  EXPECT_EQ(a.lo, b.lo);
  EXPECT_EQ(a.hi, b.hi);
}

TEST(FlowReuse, ANewParameterGivesWhatANewFlowGives) {
  Params p;  // the seed set
  Flow reused{Model(p), FlowOptions()};
  const FlowRun first = RunBelt(reused, 0.8);
  EXPECT_GT(first.sticks, 0);
  Params q = p;
  q.beta = 0.2;  // the contacts are the same: the events are kept
  reused.set_system(Model(q));
  Flow fresh_beta{Model(q), FlowOptions()};
  ExpectSame(RunBelt(reused, 0.8), RunBelt(fresh_beta, 0.8));
  q.v = 0.3;  // the belt speed moves the contact: events built again
  reused.set_system(Model(q));
  Flow fresh_v{Model(q), FlowOptions()};
  ExpectSame(RunBelt(reused, 0.8), RunBelt(fresh_v, 0.8));
  reused.set_system(Model(p));  // and back
  ExpectSame(RunBelt(reused, 0.8), first);
}

TEST(FlowReuse, ANewForcingGivesWhatANewFlowGives) {
  ForcedBeltParams p;
  p.force = 0.3, p.omega = 0.8;
  Flow reused{ForcedBelt(p), FlowOptions()};
  const FlowPoint start = ForcedStart();
  const FlowRequest rq = WithPhi();
  const FlowRun before = reused.Run(start, rq);
  p.force = 0.5, p.omega = 1.1;
  reused.set_system(ForcedBelt(p));
  Flow fresh{ForcedBelt(p), FlowOptions()};
  const FlowRun a = reused.Run(start, rq), b = fresh.Run(start, rq);
  ExpectSame(a, b);
  EXPECT_NE(a.end.z, before.end.z);
}

// Held extrema (FlowRequest::hold_extrema, Newton's early evaluations): the
// steps and the end of a run that seeks them, to the bit, without their
// extremes; leaving them out instead changes the steps (the forced field
// takes a higher order where no roots are sought inside steps). One flow
// alternating the two shapes keeps both sets of events.
TEST(FlowReuse, HeldExtremaTakeTheStepsOfARunThatSeeksThem) {
  ForcedBeltParams p;  // forced_bench's stick-slip belt
  p.base.mu_s = 0.4, p.base.mu_k = 0.25, p.base.beta = 0.05, p.base.v = 0.2;
  p.force = 0.3, p.omega = 0.8;
  const ForcedBelt m(p);
  FlowOptions o = ForcedBelt::FlowDefaults();
  o.rtol = o.atol = 1e-12;
  const FlowPoint start = ForcedStart();
  FlowRequest seek = WithPhi();
  seek.extrema = {0, 1};
  FlowRequest held = seek, none = seek;
  held.hold_extrema = true;
  none.extrema.clear();
  Flow flow{m, o}, fresh{m, o};
  const FlowRun a = flow.Run(start, seek), b = flow.Run(start, held);
  const FlowRun c = flow.Run(start, seek), n = fresh.Run(start, none);
  EXPECT_GT(a.sticks, 0);
  EXPECT_EQ(b.steps, a.steps);
  EXPECT_EQ(b.end.t, a.end.t);
  EXPECT_EQ(b.end.z, a.end.z);
  EXPECT_EQ(b.jacobian, a.jacobian);
  EXPECT_GT(a.hi[0], b.hi[0]);  // held: x's largest at a switch or an end only
  ExpectSame(c, a);
  EXPECT_LT(n.steps, a.steps);
}

}  // namespace
