// The Taylor stepper's order fallback (TaylorStepper::NewStep): the seed law
// steps at order p + 6 (Tolerances::kTaylorExtraOrderCubic); where those
// coefficients overflow it recomputes the step at Jorba and Zou's p. Checked
// on a stiff field against the long-double reference integrator.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "integrate/taylor_stepper.hpp"
#include "numerics/tolerances.hpp"
#include "reference/reference_orbit.hpp"
#include "stickslip/systems/belt/belt_flow.hpp"
#include "stickslip/systems/belt/params.hpp"

namespace stickslip {
namespace {

namespace ref = reference;

// v_m = 1e-6 makes the cubic law stiff: k3 = (mu_s - mu_m) / (2 v_m^3) =
// 7.5e16. From rest, x' = 0, the slip speed s = v - x' = 0.25 starts far above
// v_m, where the field's Jacobian has -mu'(s) ~ -3 k3 s^2 ~ -1.4e16: c_k grows
// like 1.4e16^k / k!, past the double range before order p + 6 = 20 (rtol
// 1e-11). As s falls (s ~ 1 / sqrt(2 k3 t)) the stiffness falls with it, the
// coefficients fit again, and x' reaches v near t = 1e-5 (then stick).
Params Stiff() {
  Params p;
  p.v_m = 1e-6;
  return p;
}

// The reference: slip below from (0, 0) on the smooth field (seed eq. 3.5),
// RKF78 in long double at tol, to each of the times ts (ascending): the step
// that passes one is redone to end there. The step cap keeps trial steps
// where the field is stable for them (odeint's control would accept the NaN
// error of an overflowing one): 0.1 / |J| at the start, |J| = 3 k3 v^2, and
// on [t_a, t_b] the time t_a, since |J| ~ 3 k3 s^2 ~ 1.5 / t as s falls.
std::vector<ref::State<2>> Reference(const Params& p, const std::vector<double>& ts,
                                     ref::Real tol) {
  const ref::Model rm(p);
  const ref::Real v = p.v, h0 = 0.1L / (3 * ref::CubicK3(p) * v * v);
  ref::State<2> s{0, 0};
  ref::Real t = 0;
  std::vector<ref::State<2>> out;
  for (double ts_i : ts) {
    ref::Stepper<2> st(ref::SlipField<2>{&rm, -1}, tol, t > 0 ? t : h0);
    for (;;) {
      const ref::State<2> s0 = s;
      const ref::Real t0 = t;
      if (st.Step(s, t) <= 0) return out;  // the control failed: fewer samples
      if (t >= ts_i) {
        s = st.From(s0, t0, ref::Real(ts_i) - t0);
        t = ts_i;
        break;
      }
    }
    out.push_back(s);
  }
  return out;
}

TEST(TaylorFallback, StiffStartFallsBackToJzOrderAndMatchesTheReference) {
  const Params p = Stiff();
  const Model m(p);
  FlowOptions o;  // the defaults: rtol 1e-11, atol 1e-13
  const int jz = OrderFor(o.rtol);
  // The driver resolves times from 1e-14 after the start (its output; a stop
  // time skips a rest below 8e-16), after the 9 fallback steps (t < 3e-16):
  // their errors reach these samples damped by the contraction below.
  const std::vector<double> ts = {1e-13, 1e-12, 1e-11, 1e-10, 1e-9, 1e-8, 1e-7, 1e-6};
  const std::vector<ref::State<2>> want = Reference(p, ts, 1e-19L);
  ASSERT_EQ(want.size(), ts.size());
  BeltFlow flow(m, o);
  for (size_t i = 0; i < ts.size(); ++i) {
    StopRule stop;
    stop.t_max = 2 * ts[i];
    std::vector<Sample> got;  // the start, then ts[i] by dense output
    const FlowResult r =
        flow.Run(0.0, Vec2(0.0, 0.0), Mode::kSlipBelow, stop, false, ts[i], [&](const Sample& s) {
          if (s.t == ts[i]) got.push_back(s);
        });
    ASSERT_EQ(r.status, FlowStatus::kTimeLimit) << r.message;
    ASSERT_EQ(got.size(), 1u) << "t = " << ts[i];
    ASSERT_EQ(got[0].mode, Mode::kSlipBelow) << "t = " << ts[i];  // still slipping: x' < v
    // Each step's error is at most rtol |z|_inf (JZ 3.2 with heyoka's safety
    // factor); the field contracts (-2 beta - mu'(s) < 0 for s > v_m), so they
    // do not grow: 10 rtol |z|_inf bounds their sum.
    const double x = static_cast<double>(want[i][0]), xdot = static_cast<double>(want[i][1]);
    const double bound = 10 * o.rtol * std::max(std::abs(x), std::abs(xdot));
    EXPECT_NEAR(got[0].z[0], x, bound) << "t = " << ts[i];
    EXPECT_NEAR(got[0].z[1], xdot, bound) << "t = " << ts[i];
  }
  // The fallback happened, at JZ's order p, and the steps that fit took p + 6.
  const TaylorOrders& orders = flow.taylor_orders();
  EXPECT_GT(orders.fallbacks, 0);
  EXPECT_EQ(orders.min, jz);
  EXPECT_EQ(orders.max, jz + Tolerances::kTaylorExtraOrderCubic);
  EXPECT_LT(orders.fallbacks, orders.steps);
}

// The seed set never needs the fallback: every step at p + 6.
TEST(TaylorFallback, SeedOrbitStepsAtTheExtraOrderOnly) {
  const Model m{Params()};
  FlowOptions o;
  BeltFlow flow(m, o);
  StopRule stop;
  stop.at_stick = true;
  stop.t_max = 100;
  const FlowResult r = flow.Run(0.0, m.ExitPoint(), Mode::kSlipBelow, stop, false);
  ASSERT_EQ(r.status, FlowStatus::kStick) << r.message;
  const TaylorOrders& orders = flow.taylor_orders();
  EXPECT_EQ(orders.fallbacks, 0);
  EXPECT_EQ(orders.steps, flow.total_steps());
  EXPECT_EQ(orders.min, OrderFor(o.rtol) + Tolerances::kTaylorExtraOrderCubic);
  EXPECT_EQ(orders.max, orders.min);
  EXPECT_EQ(orders.sum, orders.steps * orders.min);
}

}  // namespace
}  // namespace stickslip
