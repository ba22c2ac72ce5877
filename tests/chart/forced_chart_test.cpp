// The forced chart (issue 21 item 3): the GR curve of Den Hartog's non-stop
// orbit against his closed-form stop condition, a PD curve point against a
// one-parameter run located at that curve point's second parameter, and the
// response grid's cells against the orbits FindForcedOrbits finds there.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "forced_reference.hpp"
#include "stickslip/chart/forced_chart.hpp"
#include "stickslip/forced/orbit.hpp"
#include "stickslip/forced/orbit_scan.hpp"

namespace stickslip {
namespace {

using forced_reference::Coulomb;

// Den Hartog (1931), v = 0, beta = 0, mu_s = mu_k = mu: on the non-stop orbit
// a reversal at x = -X has V cos(phi) = -X and V sin(phi) = mu U
// (V = A / (1 - W^2), U = sin(pi/W) / (W (1 + cos(pi/W)))), so the slip
// leaving it starts with x'' = X W^2 - mu: the motion goes on without a stop
// while X W^2 > mu. With X = sqrt(V^2 - (mu U)^2) the boundary is
//   A = mu |1 - W^2| sqrt(U^2 + W^-4).
double DenHartogStopForce(double mu, double w) {
  const double U = std::sin(M_PI / w) / (w * (1 + std::cos(M_PI / w)));
  return mu * std::abs(1 - w * w) * std::sqrt(U * U + 1 / (w * w * w * w));
}

ForcedChartOptions Options(ForcedAxis a1, double from1, double to1, ForcedAxis a2, double from2,
                           double to2) {
  ForcedChartOptions o;
  o.plane.p1 = a1, o.plane.p2 = a2;
  o.plane.from1 = from1, o.plane.to1 = to1, o.plane.from2 = from2, o.plane.to2 = to2;
  o.flow.rtol = o.flow.atol = 1e-13;
  o.max_step = 0.02;
  return o;
}

TEST(ForcedChart, DenHartogGrazingCurveIsHisStopCondition) {
  const double mu = 0.3;
  for (const double w : {0.7, 1.5}) {  // one curve below and one above resonance
    const ForcedChartOptions o =
        Options(ForcedAxis::kOmega, w < 1 ? 0.6 : 1.2, w < 1 ? 0.9 : 2.0, ForcedAxis::kForce, 0.05,
                1.5);
    // The non-stop orbit a little above the boundary, then the seed there.
    const double a = DenHartogStopForce(mu, w) * 1.02;
    const ForcedModel model(Coulomb(mu, mu, 0, 0, a, w));
    ForcedOrbitOptions oo;
    oo.flow = o.flow;
    const ForcedOrbit orbit = ShootStroboscopic(model, a / (1 - w * w), 0.01, 1, oo);
    ASSERT_EQ(orbit.status, ForcedOrbitStatus::kConverged) << orbit.message;
    ASSERT_EQ(orbit.sticks, 0);
    std::string why;
    const ForcedCurve c = TraceForcedCurve(Coulomb(mu, mu, 0, 0, a, w), o, ForcedCurveKind::kGR, 1,
                                           orbit.start.x, orbit.start.xdot, w, a, &why);
    EXPECT_EQ(why, "") << c.ends.Text();
    ASSERT_GT(c.points.size(), 10u);
    double worst = 0;
    for (const ForcedCurvePoint& p : c.points) {
      const double ref = DenHartogStopForce(mu, p.p1);
      EXPECT_NEAR(p.p2, ref, 1e-8 * std::max(1.0, ref)) << "Omega = " << p.p1;
      EXPECT_TRUE(p.flag);  // the crossing margin
      worst = std::max(worst, std::abs(p.p2 - ref));
    }
    std::printf("[ measured ] GR curve Omega in [%g, %g]: %zu points, %d evaluations, %.2f s, "
                "max |A - A_DenHartog| = %.2e, ends %s\n",
                c.points.front().p1, c.points.back().p1, c.points.size(), c.evaluations,
                c.seconds, worst, c.ends.Text().c_str());
  }
}

}  // namespace
}  // namespace stickslip
