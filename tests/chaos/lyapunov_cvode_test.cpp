// The largest Lyapunov exponent with the slip phases by CVODE (issue 21 item
// 2: "on chaotic parameters the Taylor and CVODE paths must agree within the
// estimate's own error"): two integrators of different kind (Taylor series,
// Adams multistep) on the same chaotic Stribeck point; and the CVODE path on
// a stick-slip window against the exit map's multiplier (an independent Newton solve).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "forced_reference.hpp"
#include "forced_run.hpp"
#include "stickslip/chaos/lyapunov.hpp"
#include "stickslip/errors.hpp"
#include "stickslip/orbits/forced_orbit.hpp"

namespace stickslip {
namespace {

ForcedBeltParams Params(LawKind law, double beta, double v, double force, double omega) {
  return forced_reference::Belt(law, beta, v, force, omega);
}

LyapunovOptions Cvode(double rtol) {
  LyapunovOptions o;
  o.flow.integrator = Integrator::kCvode;
  o.flow.rtol = rtol, o.flow.atol = rtol;
  return o;
}

TEST(LyapunovCvode, ChaoticStribeckAgreesWithTaylor) {
  // The chaotic point of forced_stribeck_orbit_diagram.ini (lyapunov_test.cpp).
  const ForcedBelt m(Params(LawKind::kStribeck, 0.01, 0.1, 0.5, 0.35));
  LyapunovOptions taylor;
  LyapunovOptions cvode = Cvode(1e-10);
  for (LyapunovOptions* o : {&taylor, &cvode}) o->transient = 200, o->keep = 1000;
  const SectionRun a = IterateStroboscopic(m, ForcedStart(m, 0, 0, 0.1), taylor);
  const SectionRun b = IterateStroboscopic(m, ForcedStart(m, 0, 0, 0.1), cvode);
  ASSERT_EQ(a.status, LyapunovStatus::kDone) << a.message;
  ASSERT_EQ(b.status, LyapunovStatus::kDone) << b.message;
  const double err = std::hypot(a.lyapunov_err, b.lyapunov_err);
  std::printf("chaotic: taylor %.5f +- %.1e (%ld steps), cvode %.5f +- %.1e (%ld steps)\n",
              a.lyapunov, a.lyapunov_err, a.steps, b.lyapunov, b.lyapunov_err, b.steps);
  EXPECT_GT(a.lyapunov, 3 * a.lyapunov_err);  // chaotic on both paths
  EXPECT_GT(b.lyapunov, 3 * b.lyapunov_err);
  EXPECT_NEAR(a.lyapunov, b.lyapunov, 3 * err);
}

TEST(LyapunovCvode, StickSlipWindowMatchesExitMapMultiplier) {
  const ForcedBelt m(Params(LawKind::kCoulomb, 0.05, 0.2, 0.3, 0.8));
  const SectionRun r = IterateStroboscopic(m, ForcedStart(m, 0, 0, 0.2), Cvode(1e-10));
  ASSERT_EQ(r.status, LyapunovStatus::kDone) << r.message;
  ShootingOptions o(ForcedBelt::FlowDefaults());
  const PeriodicOrbit exit = ExitPhaseOrbit(m, 1.9, Mode::kSlipBelow, 1, 1, o);
  ASSERT_TRUE(exit.ok()) << exit.message;
  EXPECT_NEAR(r.lyapunov, std::log(std::abs(exit.multipliers[0].real())) / m.period(), 1e-3);
  for (const SectionPoint& q : r.points) EXPECT_EQ(q.sticks, 1);
}

// CVODE finds the extremes inside its steps as roots of x' and x'' (its
// rootfinding on the flow's extremum events): they agree with the Taylor
// flow's at a tighter tolerance. Below CVODE's floor the flow refuses.
TEST(LyapunovCvode, CvodeExtremesInsideStepsAgreeWithTaylor) {
  const ForcedBelt m(Params(LawKind::kCoulomb, 0.05, 0.2, 0.3, 0.8));
  FlowOptions o = ForcedBelt::FlowDefaults();
  o.rtol = o.atol = 1e-13;
  const FlowPoint start = ForcedStart(m, 0, 0, 0.2);
  const FlowRun taylor = testing_util::RunForced(m, start, 3 * m.period(), {}, o);
  o.integrator = Integrator::kCvode;
  o.rtol = 1e-12, o.atol = 1e-14;
  const FlowRun cvode = testing_util::RunForced(m, start, 3 * m.period(), {}, o);
  ASSERT_TRUE(Reached(taylor) && Reached(cvode)) << taylor.message << cvode.message;
  ASSERT_GT(taylor.sticks, 0);
  EXPECT_EQ(cvode.sticks, taylor.sticks);
  for (int j = 0; j < 2; ++j) {
    EXPECT_NEAR(cvode.lo[j], taylor.lo[j], 1e-8) << j;
    EXPECT_NEAR(cvode.hi[j], taylor.hi[j], 1e-8) << j;
  }
  o.rtol = 5e-14;
  EXPECT_THROW(Flow(m, o), InvalidArgument);
  EXPECT_NE(o.ValidationError().find("CVODE needs"), std::string::npos) << o.ValidationError();
}

}  // namespace
}  // namespace stickslip
