// HB curves and their criticality (hopf_curve.hpp) through the chart driver:
// every point against closed forms (seed 3.16 and its analogues), the first Lyapunov
// coefficient against the amplitude of pure-slip orbits measured by shooting
// just past the Hopf point, and the GH point of the quintic law.
#include "chart/hopf_curve.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "stickslip/chart/chart.hpp"
#include "stickslip/orbits/orbit.hpp"

namespace stickslip {
namespace {

ChartResult HopfChart(const Params& base, const Plane& plane) {
  ChartOptions o;
  o.plane = plane;
  o.grazing_curves = false;
  o.fold_curves = false;
  return Chart(base, o);
}

int HopfPoints(const ChartResult& r) {
  int n = 0;
  for (const Curve& c : r.curves) n += c.kind == CurveKind::kHopf ? c.points.size() : 0;
  return n;
}

TEST(HopfCurve, CubicMatchesClosedForm) {
  // Seed (3.16): v = sqrt((k1 - 2 beta) / (3 k3)), k1 = 0.45, k3 = 0.6.
  const ChartResult r =
      HopfChart(Params{}, Plane{Parameter::kV, Parameter::kBeta, 0.02, 0.6, 0.0, 0.25});
  ASSERT_EQ(r.curves.size(), 1u);
  EXPECT_GT(HopfPoints(r), 50);
  for (const CurvePoint& p : r.curves[0].points) {
    EXPECT_NEAR(p.p1, std::sqrt((0.45 - 2 * p.p2) / 1.8), 1e-12) << "beta = " << p.p2;
    EXPECT_EQ(p.type, CurvePointType::kSupercritical);
    EXPECT_DOUBLE_EQ(p.l1, -6 * 0.6 / 16);  // mu''' = 6 k3
  }
  // It runs from beta = 0 (v = 0.5) to the left edge v = 0.02.
  const auto& pts = r.curves[0].points;
  EXPECT_EQ(std::min(pts.front().p2, pts.back().p2), 0.0);
  EXPECT_EQ(std::min(pts.front().p1, pts.back().p1), 0.02);
}

TEST(HopfCurve, StribeckMatchesClosedForm) {
  // 2 beta = (mu_s - mu_k) / v_s exp(-v / v_s): v = -v_s ln(2 beta v_s / (mu_s - mu_k)).
  Params p;
  p.law = LawKind::kStribeck;
  p.mu_s = 0.4, p.mu_k = 0.25, p.v_s = 0.5;
  const ChartResult r = HopfChart(p, Plane{Parameter::kV, Parameter::kBeta, 0.02, 0.6, 0.01, 0.14});
  ASSERT_EQ(r.curves.size(), 1u);
  EXPECT_GT(HopfPoints(r), 30);
  for (const CurvePoint& c : r.curves[0].points) {
    EXPECT_NEAR(c.p1, -0.5 * std::log(2 * c.p2 * 0.5 / 0.15), 1e-12) << "beta = " << c.p2;
    EXPECT_EQ(c.type, CurvePointType::kSubcritical);
  }
}

Params QuinticHopf() {
  Params p;
  p.k5 = 0.24;  // mu_s 0.4, mu_m 0.25, v_m 0.5: k1 = 0.45, k3 = 0.6
  return p;
}

TEST(HopfCurve, QuinticMatchesClosedFormAndHasItsGeneralizedHopfPoint) {
  const ChartResult r =
      HopfChart(QuinticHopf(), Plane{Parameter::kV, Parameter::kBeta, 0.05, 0.58, 0.0, 0.12});
  ASSERT_EQ(r.curves.size(), 1u);
  for (const CurvePoint& c : r.curves[0].points) {
    const double v = c.p1;
    EXPECT_NEAR(2 * c.p2, 0.45 - 1.8 * v * v + 1.2 * v * v * v * v, 1e-12) << "v = " << v;
    // mu''' = 6 k3 - 60 k5 v^2 changes sign at v = sqrt(k3 / (10 k5)) = 0.5.
    EXPECT_EQ(c.type, v < 0.5 ? CurvePointType::kSupercritical : CurvePointType::kSubcritical)
        << "v = " << v;
  }
  ASSERT_EQ(r.codim2.size(), 1u);
  EXPECT_EQ(r.codim2[0].label, Codim2Label::kGeneralizedHopf);
  EXPECT_NEAR(r.codim2[0].p1, 0.5, 1e-10);
  EXPECT_NEAR(r.codim2[0].p2, (0.45 - 1.8 * 0.25 + 1.2 * 0.0625) / 2, 1e-10);  // 0.0375
}

TEST(HopfCurve, AnyParameterPair) {
  // (v, mu_s) for the cubic law: 2 beta = k1 - 3 k3 v^2 with k1 = 3 (mu_s - mu_m) / (2 v_m),
  // k3 = (mu_s - mu_m) / (2 v_m^3): mu_s - mu_m = 2 beta / (3 / (2 v_m) - 3 v^2 / (2 v_m^3)).
  const ChartResult r =
      HopfChart(Params{}, Plane{Parameter::kV, Parameter::kMuS, 0.05, 0.45, 0.3, 0.8});
  ASSERT_GE(r.curves.size(), 1u);
  for (const CurvePoint& c : r.curves[0].points) {
    const double v = c.p1, vm = 0.5;
    EXPECT_NEAR(c.p2 - 0.25, 0.1 / (1.5 / vm - 1.5 * v * v / (vm * vm * vm)), 1e-11) << v;
  }
}

// The amplitude of the pure-slip orbit near HB: r^2 = -8 (2 beta + mu') / mu''' = d / (2 l1),
// with a the section amplitude (x_max - xbar ~ r).
void ExpectAmplitudeFollowsL1(Params p, double v_hopf) {
  const double l1 = HopfCriticality([&] {
    Params q = p;
    q.v = v_hopf;
    return q;
  }());
  // The orbit exists on the side where d = 2 beta + mu' has the sign of l1.
  const double d = l1 < 0 ? -2e-5 : 2e-5;
  // Solve HopfFunction(v) = d by Newton in v (mu'' is exact).
  p.v = v_hopf;
  for (int i = 0; i < 50; ++i) p.v -= (HopfFunction(p) - d) / Friction(p).D2Mu(p.v);
  ASSERT_NEAR(HopfFunction(p), d, 1e-15);
  OrbitOptions o;
  o.flow.rtol = 1e-12;
  o.flow.atol = 1e-14;
  OrbitFinder finder(Model(p), o);
  const double r_pred = std::sqrt(d / (2 * l1));
  const OrbitResult orbit = finder.PureSlip(r_pred);
  ASSERT_TRUE(orbit.ok()) << orbit.message;
  const double a = orbit.orbit.start[0] - Model(p).SteadySliding().x;
  EXPECT_NEAR(a / r_pred, 1.0, 0.01) << "a = " << a << ", predicted " << r_pred;
  // Stable exactly when supercritical.
  EXPECT_EQ(orbit.orbit.stable, l1 < 0);
  // And no orbit of that size on the other side.
  Params q = p;
  for (int i = 0; i < 50; ++i) q.v -= (HopfFunction(q) + d) / Friction(q).D2Mu(q.v);
  OrbitFinder other(Model(q), o);
  const OrbitResult none = other.PureSlip(r_pred);
  EXPECT_FALSE(none.ok() &&
               std::abs(none.orbit.start[0] - Model(q).SteadySliding().x - r_pred) < 0.5 * r_pred);
}

TEST(HopfCurve, CriticalityPredictsTheOrbitAmplitudeSupercritical) {
  ExpectAmplitudeFollowsL1(Params{}, std::sqrt((0.45 - 0.1) / 1.8));
}

TEST(HopfCurve, CriticalityPredictsTheOrbitAmplitudeSubcritical) {
  Params p;
  p.law = LawKind::kStribeck;
  p.mu_s = 0.4, p.mu_k = 0.25, p.v_s = 0.5, p.beta = 0.05;
  ExpectAmplitudeFollowsL1(p, -0.5 * std::log(2 * 0.05 * 0.5 / 0.15));
}

TEST(HopfCurve, CriticalityPredictsTheOrbitAmplitudeQuinticPastGH) {
  Params p = QuinticHopf();
  const double v = 0.53;  // mu''' < 0 here: subcritical
  p.beta = (0.45 - 1.8 * v * v + 1.2 * std::pow(v, 4)) / 2;
  ExpectAmplitudeFollowsL1(p, v);
}

}  // namespace
}  // namespace stickslip
