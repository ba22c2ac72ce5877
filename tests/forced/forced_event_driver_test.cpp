// The forced oscillator's slip steppers (src/forced/forced_stepper.hpp) in the
// one event loop (RunSegment): the terminal arrival on x' = v and the
// non-terminal extrema of x and x' against the closed form of a coulomb slip
// piece under A cos(Omega t) (forced_reference.hpp, long double), located
// there by scanning and bisection.
#include <gtest/gtest.h>

#include <vector>

#include "forced/forced_stepper.hpp"
#include "tests/forced_reference.hpp"

namespace stickslip {
namespace {

namespace ref = forced_reference;
using forced_detail::ForcedSlipProblem;
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
  const ForcedParams p_ = ref::Coulomb(0.4, 0.25, 0.05, 0.3, 0.5, 0.8);
  const ForcedModel m_{p_};
  const ref::Setup s_{reference::Law(p_.base), p_.base.beta, p_.base.v, p_.force, p_.omega};
  const ref::CoulombPiece piece_{s_, 1, 0.3L, 1.0L, -1.0L};
  const double t0_ = 0.3, y0_[2] = {1.0, -1.0};

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
  ForcedSlipProblem Problem(bool switching, std::vector<Hit>* hits) const {
    ForcedSlipProblem p;
    p.mode = Mode::kSlipBelow;
    p.model = &m_;
    p.max_steps = 100000;
    EventList events;
    if (switching) events.Add(Event{0, +1, true, true});
    events.Add(Event{1, kAnyRoot, false});
    events.Add(Event{2, kAnyRoot, false});
    p.SetEvents(events, EventHook{&Record, hits});
    return p;
  }
};

TEST_F(ForcedEventDriver, TaylorArrivalAndExtremaMatchTheClosedForm) {
  ForcedOptions o;
  forced_detail::ForcedTaylorStepper stepper(m_, o, true);
  std::vector<Hit> hits;
  const ForcedSlipProblem p = Problem(true, &hits);
  const SegmentEnd e = RunSegment(stepper, p, t0_, y0_, 100.0, SegmentOutput{});
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
  ForcedOptions o;
  forced_detail::ForcedTaylorStepper stepper(m_, o, true);
  std::vector<Hit> hits;
  const ForcedSlipProblem p = Problem(false, &hits);
  const SegmentEnd e = RunSegment(stepper, p, t0_, y0_, 4.0, SegmentOutput{});
  ASSERT_EQ(e.kind, SegmentEnd::kTime);
  EXPECT_EQ(e.t, 4.0);
  Real x, y, a;
  At(4.0L, &x, &y, &a);
  EXPECT_NEAR(e.y[0], double(x), 1e-11);
  EXPECT_NEAR(e.y[1], double(y), 1e-11);
}

TEST_F(ForcedEventDriver, CvodeArrivalMatchesTheClosedForm) {
  ForcedOptions o;
  o.integrator = Integrator::kCvode;
  o.rtol = 1e-10;
  o.atol = 1e-12;
  auto stepper = forced_detail::MakeForcedCvode(m_, o, false);
  std::vector<Hit> hits;
  ForcedSlipProblem p = Problem(true, &hits);
  long steps = 0;
  const SegmentEnd e = forced_detail::RunSegment(*stepper, p, t0_, y0_, 100.0, &steps);
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
