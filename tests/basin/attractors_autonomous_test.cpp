// Attractors of an autonomous system on a surface section (issue 31 item 6):
// the belt through the one classifier (returns to x' = 0 falling) against
// its own amplitude classifier (basin/basin.hpp) and the unstable pure-slip
// orbit traced by the long-double reference integrator: starts inside that
// closed curve come to rest on steady sliding at the closed-form xbar =
// mu(v), starts outside on the stick-slip orbit, whose section point an
// independent Newton solve (stick-exit shooting) reproduces.
#include <gtest/gtest.h>

#include <cmath>

#include "reference/reference_orbit.hpp"
#include "reference_curve.hpp"
#include "stickslip/basin/attractors.hpp"
#include "stickslip/basin/basin.hpp"
#include "stickslip/errors.hpp"
#include "stickslip/io/attractor_report.hpp"

namespace stickslip {
namespace {

Params BistableBelt(double beta, double v) {
  Params p;
  p.law = LawKind::kStribeck;
  p.beta = beta;
  p.v = v;
  return p;
}

TEST(AutonomousAttractors, BeltAgreesWithItsOwnClassifierAndTheReferenceOrbit) {
  const Params p = BistableBelt(0.05, 0.6);  // studies/stribeck_basin.ini: bistable
  const Model model(p);
  BasinOptions bo;
  bo.nx = bo.ny = 9;
  const BasinResult belt = ClassifyBasins(model, bo);
  ASSERT_FALSE(belt.partial()) << belt.message;
  ASSERT_EQ(belt.orbits.pure_slip.size(), 1u);
  AttractorOptions o;
  o.slice.lo = {belt.x_lo, belt.xdot_lo}, o.slice.hi = {belt.x_hi, belt.xdot_hi};
  o.slice.n = {9, 9};
  o.iterate.flow = bo.scan.orbit.flow;
  const AttractorBasins b = ClassifyAttractors(model, o);
  ASSERT_TRUE(b.error.empty()) << b.error;
  ASSERT_EQ(b.failed, 0);
  const auto curve = testing_util::ReferenceCurve(p, belt.orbits.pure_slip[0].start[0]);
  ASSERT_FALSE(curve.empty());
  const double xbar = static_cast<double>(reference::Law(p).Mu(p.v));
  int rest = 0, stick_slip = 0;
  for (size_t k = 0; k < b.starts.size(); ++k) {
    const AttractorStart& s = b.starts[k];
    const Attractor& a = b.attractors[s.attractor];
    SCOPED_TRACE("start (" + std::to_string(s.at[0]) + ", " + std::to_string(s.at[1]) + ") " +
                 AttractorLabel(a) + ", belt: " + Name(belt.starts[k].fate));
    ASSERT_EQ(belt.starts[k].x, s.at[0]);
    ASSERT_EQ(belt.starts[k].xdot, s.at[1]);
    if (testing_util::Distance(curve, s.at[0], s.at[1]) < 0.01) continue;  // the boundary
    const bool inside = testing_util::Inside(curve, s.at[0], s.at[1]);
    if (inside) {
      EXPECT_EQ(a.kind, AttractorKind::kRest);
      EXPECT_NEAR(a.z[0], xbar, 1e-14);
      EXPECT_EQ(a.z[1], 0);
      ++rest;
    } else {
      EXPECT_EQ(a.kind, AttractorKind::kPeriodic);
      EXPECT_EQ(a.m, 1);
      EXPECT_EQ(a.sticks, 1);
      ++stick_slip;
    }
    if (belt.starts[k].fate != Fate::kUndecided) {
      EXPECT_EQ(belt.starts[k].fate == Fate::kSteadySliding, a.kind == AttractorKind::kRest);
    }
  }
  EXPECT_GT(rest, 4);
  EXPECT_GT(stick_slip, 4);
  // The stick-slip attractor's section point (x' = 0 falling: the orbit's x
  // maximum) against the stick-slip orbit shot on its stick exit.
  ASSERT_TRUE(belt.orbits.has_stick_slip);
  const Orbit& ss = belt.orbits.stick_slip;
  for (const Attractor& a : b.attractors)
    if (a.kind == AttractorKind::kPeriodic) {
      EXPECT_NEAR(a.z[0], ss.extrema.x_max, 1e-7);
      EXPECT_NEAR(a.z[1], 0, 1e-12);
      EXPECT_LT(a.lyapunov, 0);  // superstable: the stick collapses the tangent
    }
}

TEST(AutonomousAttractors, OptionsThatDoNotFitTheSystemThrow) {
  const Model model(Params{});
  AttractorOptions o;
  o.slice.components = {0, 2};  // the belt has 2 states
  EXPECT_THROW(ClassifyAttractors(model, o), InvalidArgument);
  o = AttractorOptions();
  o.slice.base = Eigen::VectorXd::Zero(3);
  EXPECT_THROW(ClassifyAttractors(model, o), InvalidArgument);
  o = AttractorOptions();
  o.iterate.max_return_time = -1;
  EXPECT_THROW(ClassifyAttractors(model, o), InvalidArgument);
}

}  // namespace
}  // namespace stickslip
