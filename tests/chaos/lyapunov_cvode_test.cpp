// The largest Lyapunov exponent with the slip phases by CVODE (issue 21 item
// 2: "on chaotic parameters the Taylor and CVODE paths must agree within the
// estimate's own error"): two integrators of different kind (Taylor series,
// Adams multistep) on the same chaotic Stribeck point; and the CVODE path on
// a stick-slip window against the exit map's multiplier (an independent Newton solve).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "forced_reference.hpp"
#include "stickslip/chaos/lyapunov.hpp"
#include "stickslip/errors.hpp"
#include "stickslip/forced/orbit.hpp"

namespace stickslip {
namespace {

ForcedParams Params(LawKind law, double beta, double v, double force, double omega) {
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
  const ForcedModel m(Params(LawKind::kStribeck, 0.01, 0.1, 0.5, 0.35));
  LyapunovOptions taylor;
  LyapunovOptions cvode = Cvode(1e-10);
  for (LyapunovOptions* o : {&taylor, &cvode}) o->transient = 200, o->keep = 1000;
  const StroboscopicRun a = IterateStroboscopic(m, ForcedStart(m, 0, 0, 0.1), taylor);
  const StroboscopicRun b = IterateStroboscopic(m, ForcedStart(m, 0, 0, 0.1), cvode);
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
  const ForcedModel m(Params(LawKind::kCoulomb, 0.05, 0.2, 0.3, 0.8));
  const StroboscopicRun r = IterateStroboscopic(m, ForcedStart(m, 0, 0, 0.2), Cvode(1e-10));
  ASSERT_EQ(r.status, LyapunovStatus::kDone) << r.message;
  ForcedOrbitOptions o;
  const ForcedExitOrbit exit = ExitPhaseOrbit(m, 1.9, Mode::kSlipBelow, 1, 1, o);
  ASSERT_EQ(exit.status, ForcedOrbitStatus::kConverged) << exit.message;
  EXPECT_NEAR(r.lyapunov, std::log(std::abs(exit.multiplier)) / m.period(), 1e-3);
  for (const SectionPoint& q : r.points) EXPECT_EQ(q.sticks, 1);
}

TEST(LyapunovCvode, ExtremesInsideStepsNeedTaylor) {
  const ForcedModel m(Params(LawKind::kCoulomb, 0.05, 0.2, 0.3, 0.8));
  ForcedOptions o;
  o.integrator = Integrator::kCvode;
  const ForcedFlow flow(m, o);
  ForcedRequest rq;
  rq.t_end = 1;  // extremes = true by default
  EXPECT_THROW(flow.Run(ForcedStart(m, 0, 0, 0.2), rq), InvalidArgument);
  o.rtol = 1e-15;
  EXPECT_THROW(ForcedFlow(m, o), InvalidArgument);
}

}  // namespace
}  // namespace stickslip
