// The event driver (src/integrate/event_driver.hpp): terminal and
// non-terminal events, their directions, on both steppers, against the closed
// form of the coulomb law at beta = 0. The functions: g0 = x' - v, g1 = x''
// (the derivative of x'), g2 = x'. In slip below, x'' = -x + mu_k, so from
// (mu_k - A, 0): x = mu_k - A cos t, x' = A sin t, x'' = A cos t.
#include "integrate/event_driver.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "integrate/stepper.hpp"
#include "stickslip/systems/belt/model.hpp"

namespace stickslip {
namespace {

constexpr double kMuK = 0.25, kV = 0.3;

Model Coulomb() {
  Params p;
  p.law = LawKind::kCoulomb;
  p.beta = 0;
  p.v = kV;
  p.mu_s = 0.4;
  p.mu_k = kMuK;
  return Model(p);
}

struct Hit {
  int g;
  double x, xdot;
};

void Record(void* context, int g, const double* y) {
  static_cast<std::vector<Hit>*>(context)->push_back(Hit{g, y[0], y[1]});
}

// The three functions of a slip-below segment of the belt, as indexes 0, 1, 2.
EventList BeltFunctions() {
  EventList ev;
  EventFunction g0, g1, g2;
  g0.size = g1.size = g2.size = 1;
  g0.terms[0] = g1.terms[0] = g2.terms[0] = {1, 1.0};
  g0.offset = kV;
  g0.zero_sign = -1;
  g0.surface = true;
  g1.derivative = true;
  ev.Add(g0);
  ev.Add(g1);
  ev.Add(g2);
  return ev;
}

class EventDriver : public ::testing::TestWithParam<Integrator> {
 protected:
  // Runs the slip-below field from (mu_k - A, 0) at t = 0 with these events.
  SegmentEnd Run(double A, const EventList& events, double t_max = 100) {
    FlowOptions o;
    o.integrator = GetParam();
    o.rtol = 1e-12;
    o.atol = 1e-14;
    stepper_ = MakeStepper(o, model_, false, std::nullopt);
    problem_.system = &model_;
    problem_.mode = ModeSet(Mode::kSlipBelow);
    problem_.rtol = o.rtol;
    problem_.atol = o.atol;
    problem_.layout = TaylorLayout{2, 2, false, false, 0};
    problem_.events = events;
    problem_.on_event = EventHook{&Record, &hits_};
    problem_.derivative_of = {1, -1};
    const double y0[2] = {kMuK - A, 0.0};
    return RunSegment(*stepper_, problem_, 0.0, y0, t_max, SegmentOutput{}, &roots_);
  }
  double Tol() const { return GetParam() == Integrator::kTaylor ? 1e-11 : 1e-8; }

  Model model_ = Coulomb();
  std::unique_ptr<Stepper> stepper_;
  SegmentProblem problem_;
  std::vector<Hit> hits_;
  std::vector<int> roots_;
};

TEST_P(EventDriver, TerminalArrivalEndsAtArcsine) {
  const double A = 0.5;  // reaches x' = v at sin t = v / A, before x'' = 0 at pi / 2
  EventList ev = BeltFunctions();
  ev.Add(Event{0, kAnyRoot, true});
  ev.Add(Event{1, kAnyRoot, false});
  const SegmentEnd e = Run(A, ev);
  ASSERT_EQ(e.kind, SegmentEnd::kEvent);
  EXPECT_EQ(e.g, 0);
  EXPECT_EQ(e.direction, +1);
  EXPECT_NEAR(e.t, std::asin(kV / A), Tol());
  EXPECT_NEAR(e.y[1], kV, Tol());
  EXPECT_TRUE(hits_.empty());  // the maximum of x' lies beyond the end
}

TEST_P(EventDriver, NonTerminalEventsRecordAndGoOn) {
  const double A = 0.2;  // below the belt: x' peaks at A < v, no arrival
  EventList ev = BeltFunctions();
  ev.Add(Event{0, kAnyRoot, true});
  ev.Add(Event{1, kAnyRoot, false});  // extrema of x'
  ev.Add(Event{2, kAnyRoot, false});  // extrema of x
  ev.Add(Event{2, -1, true});         // the maximum of x ends it
  const SegmentEnd e = Run(A, ev);
  ASSERT_EQ(e.kind, SegmentEnd::kEvent);
  EXPECT_EQ(e.g, 2);
  EXPECT_EQ(e.direction, -1);
  EXPECT_NEAR(e.t, M_PI, Tol());
  EXPECT_NEAR(e.y[0], kMuK + A, Tol());
  // x'' = 0 at pi / 2 (x' = A) passed on the way; x' = 0 at pi recorded too,
  // as the terminal event's own non-terminal partner.
  ASSERT_EQ(hits_.size(), 2u);
  EXPECT_EQ(hits_[0].g, 1);
  EXPECT_NEAR(hits_[0].xdot, A, Tol());
  EXPECT_EQ(hits_[1].g, 2);
  EXPECT_NEAR(hits_[1].x, kMuK + A, Tol());
}

TEST_P(EventDriver, DirectionSelectsTheRoot) {
  const double A = 0.2;
  EventList ev = BeltFunctions();
  ev.Add(Event{1, kAnyRoot, false});
  ev.Add(Event{2, +1, true});  // x' rises through 0 at 2 pi, falls at pi
  const SegmentEnd e = Run(A, ev);
  ASSERT_EQ(e.kind, SegmentEnd::kEvent);
  EXPECT_EQ(e.g, 2);
  EXPECT_EQ(e.direction, +1);
  EXPECT_NEAR(e.t, 2 * M_PI, Tol());
  EXPECT_NEAR(e.y[0], kMuK - A, Tol());  // the minimum of x, back at the start
  // x'' = 0 at pi / 2 and 3 pi / 2: x' = A, then -A.
  ASSERT_EQ(hits_.size(), 2u);
  EXPECT_NEAR(hits_[0].xdot, A, Tol());
  EXPECT_NEAR(hits_[1].xdot, -A, Tol());
}

TEST_P(EventDriver, NoTerminalEventRunsToTheStopTime) {
  const double A = 0.2, t_max = 10.0;  // extrema of x at pi, 2 pi, 3 pi
  EventList ev = BeltFunctions();
  ev.Add(Event{2, kAnyRoot, false});
  const SegmentEnd e = Run(A, ev, t_max);
  ASSERT_EQ(e.kind, SegmentEnd::kTime);
  EXPECT_EQ(e.t, t_max);
  EXPECT_NEAR(e.y[0], kMuK - A * std::cos(t_max), Tol());
  ASSERT_EQ(hits_.size(), 3u);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(hits_[k].x, kMuK + (k % 2 == 0 ? A : -A), Tol());
}

TEST(EventList, MasksCombineDirectionsAndFunctionsAreShared) {
  EventList ev = BeltFunctions();
  ev.Add(Event{1, kAnyRoot, false});
  EXPECT_FALSE(ev.Stops(1, -1));
  EXPECT_TRUE(ev.Passes(1, +1));
  ev.Add(Event{1, -1, true});
  EXPECT_TRUE(ev.Stops(1, -1));
  EXPECT_FALSE(ev.Stops(1, +1));
  ev.Add(Event{1, +1, true});
  EXPECT_TRUE(ev.Stops(1, +1));
  // g0 and g2 share one polynomial (x'), g1 has its own; adding g2 again
  // gives g2's index.
  EXPECT_EQ(ev.function(0).base, ev.function(2).base);
  EXPECT_NE(ev.function(1).base, ev.function(2).base);
  EventFunction again;
  again.size = 1;
  again.terms[0] = {1, 1.0};
  EXPECT_EQ(ev.Add(again), 2);
  EXPECT_EQ(ev.functions(), 3);
}

INSTANTIATE_TEST_SUITE_P(Steppers, EventDriver,
                         ::testing::Values(Integrator::kTaylor, Integrator::kCvode),
                         [](const auto& info) { return std::string(Name(info.param)); });

}  // namespace
}  // namespace stickslip
