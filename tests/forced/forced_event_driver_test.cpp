// The forced oscillator (ForcedBelt: x, x', theta = Omega t) on the one
// flow's steppers in the one event loop (RunSegment): the terminal arrival on x' = v and the
// non-terminal extrema of x and x' against the closed form of a coulomb slip
// piece under A cos(Omega t) (forced_reference.hpp, long double), located
// there by scanning and bisection.
#include <gtest/gtest.h>

#include <vector>

#include "integrate/event_driver.hpp"
#include "stickslip/systems/forced/forced.hpp"
#include "tests/forced_reference.hpp"

namespace stickslip {
namespace {

namespace ref = forced_reference;
using Real = ref::Real;

struct Hit {
  int g;
  double x, xdot;
};

void Record(void* context, int g, const double* y) {
  static_cast<std::vector<Hit>*>(context)->push_back(Hit{g, y[0], y[1]});
}

// Slip below from (t0, x0, x'0) = (0.3, 1, -1): x' falls to a minimum (x''
// = 0), rises through 0 (a minimum of x), turns twice below v and reaches it
// (the arrival).
class ForcedEventDriver : public ::testing::Test {
 protected:
  const ForcedBeltParams p_ = ref::Coulomb(0.4, 0.25, 0.05, 0.3, 0.5, 0.8);
  const ForcedBelt m_{p_};
  const ref::Setup s_{reference::Law(p_.base), p_.base.beta, p_.base.v, p_.force, p_.omega};
  const ref::CoulombPiece piece_{s_, 1, 0.3L, 1.0L, -1.0L};
  const double omega_ = 0.8, zero_ = 0;
  const double t0_ = 0.3, y0_[3] = {1.0, -1.0, 0.3 * 0.8};  // theta = Omega t0

  // The closed form's x, x', x'' at t.
  void At(Real t, Real* x, Real* y, Real* acc) const {
    piece_.At(t, *x, *y);
    *acc = -*x - 2 * s_.beta * *y + s_.law.mu_k + s_.a * std::cos(s_.w * t);
  }
  // The first t after a where f(t) changes sign, by scanning and bisection.
  template <class F>
  Real FirstRoot(F f, Real a) const {
    const Real step = 1e-3L;
    for (Real t = a; t < a + 50; t += step)
      if ((f(t) > 0) != (f(t + step) > 0))
        return ref::Bisect([&](Real u) { return (f(u) > 0) != (f(t) > 0); }, t, t + step);
    return NAN;
  }
  // g0 = x' - v (the arrival), g1 = x'' (extrema of x'), g2 = x' (of x).
  SegmentProblem Problem(bool switching, std::vector<Hit>* hits, const FlowOptions& o) const {
    SegmentProblem p;
    p.system = &m_;
    p.mode = ModeSet(Mode::kSlipBelow);
    p.rtol = o.rtol;
    p.atol = o.atol;
    p.layout = TaylorLayout{3, 2, false, false, 0};
    p.derivative_of = {1, -1, -1};
    p.clock_rate = &omega_;
    p.clock_offset = &zero_;
    EventFunction g0, g1, g2;
    g0.size = g1.size = g2.size = 1;
    g0.terms[0] = g1.terms[0] = g2.terms[0] = {1, 1.0};
    g0.offset = m_.v();
    g0.zero_sign = -1;
    g0.surface = true;
    g1.derivative = true;
    p.events.Add(g0);
    p.events.Add(g1);
    p.events.Add(g2);
    if (switching) p.events.Add(Event{0, +1, true, true});
    p.events.Add(Event{1, kAnyRoot, false});
    p.events.Add(Event{2, kAnyRoot, false});
    p.on_event = EventHook{&Record, hits};
    return p;
  }
  static FlowOptions Options(Integrator i) {
    FlowOptions o;
    o.integrator = i;
    o.rtol = i == Integrator::kTaylor ? 1e-12 : 1e-10;
    o.atol = i == Integrator::kTaylor ? 1e-12 : 1e-12;
    return o;
  }
};

TEST_F(ForcedEventDriver, TaylorArrivalAndExtremaMatchTheClosedForm) {
  const FlowOptions o = Options(Integrator::kTaylor);
  auto stepper = MakeStepper(o, m_, false, std::nullopt);
  std::vector<Hit> hits;
  std::vector<int> roots;
  const SegmentProblem p = Problem(true, &hits, o);
  const SegmentEnd e = RunSegment(*stepper, p, t0_, y0_, 100.0, SegmentOutput{}, &roots);
  auto part = [&](int i, Real shift) {  // x' (i = 1) or x'' (i = 2) of the closed form, minus shift
    return [this, i, shift](Real t) {
      Real z[3];
      At(t, &z[0], &z[1], &z[2]);
      return z[i] - shift;
    };
  };
  const auto y_minus_v = part(1, s_.v), xdot = part(1, 0), xddot = part(2, 0);
  const Real t_arr = FirstRoot(y_minus_v, 0.3L), t_xmin = FirstRoot(xdot, 0.3L),
             t_ydmin = FirstRoot(xddot, 0.3L);
  ASSERT_LT(t_ydmin, t_xmin);
  ASSERT_LT(t_xmin, t_arr);
  ASSERT_EQ(e.kind, SegmentEnd::kEvent);
  EXPECT_EQ(e.g, 0);
  EXPECT_EQ(e.direction, +1);
  EXPECT_NEAR(e.t, double(t_arr), 1e-11);
  Real x, y, a;
  At(t_arr, &x, &y, &a);
  EXPECT_NEAR(e.y[0], double(x), 1e-11);
  // Every extremum before the arrival, per function in order of time (a
  // step reports those of x before those of x').
  std::vector<double> got[3], want[3];
  for (const Hit& h : hits) got[h.g].push_back(h.g == 1 ? h.xdot : h.x);
  for (Real t = FirstRoot(xddot, 0.3L); t < t_arr; t = FirstRoot(xddot, t + 1e-9L))
    want[1].push_back((At(t, &x, &y, &a), double(y)));
  for (Real t = FirstRoot(xdot, 0.3L); t < t_arr; t = FirstRoot(xdot, t + 1e-9L))
    want[2].push_back((At(t, &x, &y, &a), double(x)));
  ASSERT_EQ(want[1].size(), 3u);  // x' falls to a minimum, rises to a maximum below v, falls again
  ASSERT_EQ(want[2].size(), 1u);
  for (int g : {1, 2}) {
    ASSERT_EQ(got[g].size(), want[g].size()) << "g" << g;
    for (size_t k = 0; k < want[g].size(); ++k) EXPECT_NEAR(got[g][k], want[g][k], 1e-11);
  }
}

TEST_F(ForcedEventDriver, WithoutTheArrivalEventTheSegmentRunsOnToTheStopTime) {
  const FlowOptions o = Options(Integrator::kTaylor);
  auto stepper = MakeStepper(o, m_, false, std::nullopt);
  std::vector<Hit> hits;
  std::vector<int> roots;
  const SegmentProblem p = Problem(false, &hits, o);
  const SegmentEnd e = RunSegment(*stepper, p, t0_, y0_, 4.0, SegmentOutput{}, &roots);
  ASSERT_EQ(e.kind, SegmentEnd::kTime);
  EXPECT_EQ(e.t, 4.0);
  Real x, y, a;
  At(4.0L, &x, &y, &a);
  EXPECT_NEAR(e.y[0], double(x), 1e-11);
  EXPECT_NEAR(e.y[1], double(y), 1e-11);
}

TEST_F(ForcedEventDriver, CvodeArrivalMatchesTheClosedForm) {
  const FlowOptions o = Options(Integrator::kCvode);
  auto stepper = MakeStepper(o, m_, false, std::nullopt);
  std::vector<Hit> hits;
  std::vector<int> roots;
  const SegmentProblem p = Problem(true, &hits, o);
  const SegmentEnd e = RunSegment(*stepper, p, t0_, y0_, 100.0, SegmentOutput{}, &roots);
  const long steps = stepper->steps();
  auto y_minus_v = [&](Real t) {
    Real x, y, a;
    return At(t, &x, &y, &a), y - s_.v;
  };
  const Real t_arr = FirstRoot(y_minus_v, 0.3L);
  ASSERT_EQ(e.kind, SegmentEnd::kEvent);
  EXPECT_EQ(e.g, 0);
  EXPECT_EQ(e.direction, +1);
  EXPECT_NEAR(e.t, double(t_arr), 1e-7);
  EXPECT_GT(steps, 0);
}

}  // namespace
}  // namespace stickslip
