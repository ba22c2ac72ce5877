// Test helper: a start list row's point (x0, xdot0) on the seed belt at
// A = 0.1, Omega = 1.5, iterated by the built-in forced model's flow at
// rtol = atol = 1e-13 (independent of the app run that listed it): back
// within 1e-8 after m periods and not before, with `sticks` stick phases on
// the way (forced_start_app_test.cpp, clock_start_app_test.cpp).
#pragma once

#include <gtest/gtest.h>

#include <cmath>

#include "forced_run.hpp"
#include "stickslip/systems/forced/flow.hpp"
#include "stickslip/systems/forced/forced.hpp"

namespace stickslip::testing_util {

inline void ExpectFixedPointOfPm(double x0, double xdot0, int m, int sticks) {
  ForcedBeltParams p;
  p.force = 0.1, p.omega = 1.5;
  const ForcedBelt model(p);
  FlowOptions o = ForcedBelt::FlowDefaults();
  o.rtol = o.atol = 1e-13;
  FlowPoint z = ForcedStart(model, 0, x0, xdot0);
  int counted = 0;
  for (int k = 1; k <= m; ++k) {
    const FlowRun run = RunForced(model, z, k * model.period(), {}, o);
    ASSERT_TRUE(Reached(run)) << run.message;
    z = run.end;
    counted += run.sticks;
    const double gap = std::hypot(z.z[0] - x0, z.z[1] - xdot0);
    if (k < m)
      EXPECT_GT(gap, 1e-3) << "back after " << k << " of m = " << m << " periods";
    else
      EXPECT_LT(gap, 1e-8) << "m = " << m;
  }
  EXPECT_EQ(counted, sticks) << "m = " << m;
}

}  // namespace stickslip::testing_util
