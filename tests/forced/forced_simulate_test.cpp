// A sampled forced trajectory (forced/simulate.hpp): rows, the stroboscopic
// and exit sections, and a long chaotic run that must not stall.
#include <gtest/gtest.h>

#include <cmath>

#include "forced_run.hpp"
#include "stickslip/forced/simulate.hpp"

namespace stickslip {
namespace {

// The forced Stribeck scene of studies/stribeck_forced.ini at Omega = 0.6,
// past its period-doubling cascade.
ForcedParams StribeckScene() {
  ForcedParams p;
  p.base.law = LawKind::kStribeck;
  p.base.beta = 0.05, p.base.v = 0.25, p.base.mu_s = 0.4, p.base.mu_k = 0.25, p.base.v_s = 0.2;
  p.force = 0.3, p.omega = 0.6;
  return p;
}

// Before the fix the run stopped at t = 520.6 with "switching does not
// advance t": a stick exit left on the stick line 1e-13 off the band's edge
// gave x'' of either sign at the start of slip, and the flow went straight
// back into stick at the same t (mu(0+) = mu_s: the field is continuous there).
TEST(ForcedSimulate, LongStribeckRunCompletesAndEveryExitIsOnTheEdge) {
  const ForcedParams p = StribeckScene();
  const ForcedModel model(p);
  ForcedSimulationOptions o;
  o.t_end = 3000, o.dt = 1000, o.section = ForcedSection::kExit;
  const ForcedSimulation r = SimulateForced(model, ForcedStart(model, 0, 0, p.base.v), o);
  ASSERT_EQ(r.status, ForcedSimulationStatus::kComplete) << r.message;
  ASSERT_GT(r.section.size(), 100u);
  EXPECT_EQ(static_cast<int>(r.section.size()), r.exits);
  for (const ForcedSectionPoint& s : r.section) {
    EXPECT_EQ(s.p.xdot, p.base.v);
    const double phi = model.StickForce(s.p.t, s.p.x);
    EXPECT_NEAR(std::abs(phi), p.base.mu_s, 1e-15);
    EXPECT_GT(phi * model.StickForceRate(s.p.t), 0) << "t = " << s.p.t;  // leaving the band
  }
}

// Before the fix: a short step (h = 1.4e-3, to the next output row) right
// after a stick exit kept x'' h = 3e-20 (rounding) as the deflated constant
// term, above Deflate's noise relative to the O(h^2) polynomial; its sign
// sent the flow back into stick at the same t ("switching does not advance t").
TEST(ForcedSimulate, ShortStepAfterAStickExitLeavesTheSurface) {
  ForcedParams p;  // the seed set, forced: studies/seed_forced.ini
  p.force = 0.3, p.omega = 0.6;
  const ForcedModel model(p);
  std::vector<FlowSwitch> events;
  FlowRequest rq;
  rq.switches = &events;
  const FlowRun r = testing_util::RunForced(
      model, ForcedStart(model, 70.42, 0.32673483409726917, p.base.v, Mode::kStick), 70.43, rq);
  ASSERT_TRUE(Reached(r)) << r.message;
  ASSERT_EQ(events.size(), 1u);
  EXPECT_EQ(events[0].kind, SwitchKind::kStickOut);
  EXPECT_LT(r.end.z[1], p.base.v);  // slipping below the belt
  ForcedSimulationOptions o;
  o.t_end = 1000;
  const ForcedSimulation s = SimulateForced(model, ForcedStart(model, 0, 0, p.base.v), o);
  EXPECT_TRUE(s.ok()) << s.message;
}

// The Stribeck scene from (t0, 0.1, 0) to t_end, a row every dt.
ForcedSimulation SimulateScene(const ForcedModel& model, double t0, double t_end, double dt) {
  ForcedSimulationOptions o;
  o.t_end = t_end, o.dt = dt;
  return SimulateForced(model, ForcedStart(model, t0, 0.1, 0), o);
}

TEST(ForcedSimulate, StroboscopicPointsAreAtMultiplesOfThePeriod) {
  const ForcedModel model(StribeckScene());
  const ForcedSimulation r = SimulateScene(model, 0, 100, 0.3);
  ASSERT_TRUE(r.ok()) << r.message;
  const double T = model.period();
  ASSERT_EQ(r.section.size(), static_cast<size_t>(std::floor(100 / T)) + 1);
  for (size_t i = 0; i < r.section.size(); ++i) EXPECT_EQ(r.section[i].p.t, i * T);
  // Rows: every multiple of dt, plus one per switch, by time.
  EXPECT_EQ(r.rows.size(), static_cast<size_t>(std::floor(100 / 0.3 + 1e-9)) + 2 +
                               static_cast<size_t>(r.sticks + r.exits + r.crossings));
  for (size_t i = 1; i < r.rows.size(); ++i) EXPECT_GE(r.rows[i].t, r.rows[i - 1].t);
}

// A start between rows whose next multiple of dt rounds onto it (0.29 / 0.01
// = 28.999...): the first row after the start lies after it, none at it.
TEST(ForcedSimulate, StartBetweenRowsRoundsItsFirstBreakpointForward) {
  const ForcedSimulation r = SimulateScene(ForcedModel(StribeckScene()), 0.29, 1, 0.01);
  ASSERT_TRUE(r.ok()) << r.message;
  ASSERT_GE(r.rows.size(), 2u);
  EXPECT_EQ(r.rows[0].t, 0.29);
  EXPECT_GT(r.rows[1].t, 0.29);  // a switch's row, or the row at 0.30
  EXPECT_LE(r.rows[1].t, 0.30);
}

}  // namespace
}  // namespace stickslip
