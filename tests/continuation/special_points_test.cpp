// Special points reached directly (not through Continue): the Hopf locator
// against closed forms, the grazing gap and its locator against the
// long-double reference integrator, the fold locator on a parabola.
#include "continuation/special_points.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "reference/reference_orbit.hpp"
#include "stickslip/continuation/continuation.hpp"

namespace stickslip {
namespace {

OrbitOptions TightOrbit() {
  OrbitOptions o;
  o.flow.rtol = 1e-12;
  o.flow.atol = 1e-14;
  return o;
}

TEST(SpecialPoints, HopfDampingIsTheCubicTrace) {
  Params p;  // the seed set: k1 = 0.45, k3 = 0.6
  for (double v : {0.1, 0.3, 0.44, 0.7}) {
    p.v = v;
    EXPECT_NEAR(HopfDamping(p), 2 * 0.05 - 0.45 + 3 * 0.6 * v * v, 1e-15) << "v " << v;
  }
}

TEST(SpecialPoints, HopfLocatorMatchesTheCubicClosedForm) {
  const Params p;
  const RootResult r = LocateHopf(p, ParameterAxis("v"), 0.3, 0.6, 1e-14);
  ASSERT_TRUE(r.ok);
  // Seed (3.16): v_max = sqrt((k1 - 2 beta) / (3 k3)).
  EXPECT_NEAR(r.x, std::sqrt((p.k1() - 2 * p.beta) / (3 * p.k3())), 1e-12);
  // In beta at v = 0.25: 2 beta = k1 - 3 k3 v^2.
  const RootResult b = LocateHopf(p, ParameterAxis("beta"), 0.0, 0.3, 1e-14);
  ASSERT_TRUE(b.ok);
  EXPECT_NEAR(b.x, (p.k1() - 3 * p.k3() * p.v * p.v) / 2, 1e-12);
  // No sign change on a bracket above v_max.
  EXPECT_FALSE(LocateHopf(p, ParameterAxis("v"), 0.5, 0.6, 1e-14).ok);
}

TEST(SpecialPoints, HopfLocatorMatchesTheStribeckClosedForm) {
  Params p;
  p.law = LawKind::kStribeck;
  p.mu_s = 0.4, p.mu_k = 0.25, p.v_s = 0.5, p.beta = 0.05;
  const RootResult r = LocateHopf(p, ParameterAxis("v"), 0.05, 1.0, 1e-14);
  ASSERT_TRUE(r.ok);
  // 2 beta - (mu_s - mu_k) / v_s exp(-v / v_s) = 0.
  EXPECT_NEAR(r.x, -p.v_s * std::log(2 * p.beta * p.v_s / (p.mu_s - p.mu_k)), 1e-12);
  const SpecialPoint sp = HopfPoint(ParameterAxis("v").At(p, r.x), r.x);
  EXPECT_EQ(sp.kind, SpecialKind::kHopf);
  EXPECT_NEAR(sp.extrema.x_max, p.mu_k + (p.mu_s - p.mu_k) * std::exp(-r.x / p.v_s), 1e-15);
  EXPECT_NE(sp.description.find("subcritical"), std::string::npos);  // mu''' < 0
}

TEST(SpecialPoints, GrazingGapMatchesTheReferenceIntegrator) {
  Params p;
  OrbitFinder finder(Model(p), TightOrbit());
  for (double v : {0.2, 0.3, 0.39, 0.42}) {
    p.v = v;
    double gap = 0;
    ASSERT_TRUE(GrazingGap(finder, p, &gap)) << "v " << v;
    const reference::Model m(p);
    const double ref = static_cast<double>(reference::FirstReturnMaxXdot(m, 1e-17L) - m.v);
    EXPECT_NEAR(gap, ref, 1e-9) << "v " << v;
  }
}

TEST(SpecialPoints, GrazingLocatorMatchesTheReferenceIntegrator) {
  const Params p;
  OrbitFinder finder(Model(p), TightOrbit());
  const ParameterAxis axis("v");
  double g0 = 0, g1 = 0;
  ASSERT_TRUE(GrazingGap(finder, axis.At(p, 0.39), &g0));
  ASSERT_TRUE(GrazingGap(finder, axis.At(p, 0.40), &g1));
  EXPECT_GT(g0, 0);  // stick-slip below GR
  EXPECT_LT(g1, 0);
  const RootResult r = LocateGrazing(finder, p, axis, 0.39, 0.40, g0, g1, 1e-13);
  ASSERT_TRUE(r.ok);
  EXPECT_NEAR(r.x, static_cast<double>(reference::GrazingSpeed(p, 0.39L, 0.40L)), 1e-9);
}

// GR (and the non-smooth fold LP at it) at the default options and locate_tol,
// against the reference's grazing speed, within 1e-11 in v: the seed, the
// stribeck scene, its shallow grazing gap at beta = 0.02 (the gap's slope in v
// is small there), and the leine law with damping.
TEST(SpecialPoints, GrazingAtTheDefaultsIsWithin1e11OfTheReference) {
  Params seed, stribeck, shallow, leine;
  stribeck.law = shallow.law = LawKind::kStribeck;
  shallow.beta = 0.02;
  leine.law = LawKind::kLeine;
  const struct {
    Params p;
    double lo, hi;
  } cases[] = {
      {seed, 0.39, 0.40}, {stribeck, 0.65, 0.655}, {shallow, 1.48, 1.485}, {leine, 1.33, 1.335}};
  const ParameterAxis axis("v");
  for (const auto& c : cases) {
    SCOPED_TRACE(Name(c.p.law) + std::string(" beta ") + std::to_string(c.p.beta));
    OrbitFinder finder(Model(c.p), OrbitOptions{});
    double g0 = 0, g1 = 0;
    ASSERT_TRUE(GrazingGap(finder, axis.At(c.p, c.lo), &g0));
    ASSERT_TRUE(GrazingGap(finder, axis.At(c.p, c.hi), &g1));
    const RootResult r =
        LocateGrazing(finder, c.p, axis, c.lo, c.hi, g0, g1, ContinuationOptions{}.locate_tol);
    ASSERT_TRUE(r.ok);
    const double ref = static_cast<double>(reference::GrazingSpeed(c.p, c.lo, c.hi, 1e-14L));
    EXPECT_NEAR(r.x, ref, 1e-11);
  }
}

TEST(SpecialPoints, FoldLocatorFindsTheTopOfAParabola) {
  // G(a, p) = p - 2 + (a - 1)^2 = 0: p(a) has its maximum 2 at a = 1.
  const CurveFunction g = [](double a, double p, double* v) {
    *v = p - 2 + (a - 1) * (a - 1);
    return true;
  };
  double a = 0, p = 0;
  ASSERT_TRUE(LocateFold(g, 0.5, 1.75, 1.4, 1.84, /*minimum=*/false, 1.0, &a, &p));
  EXPECT_NEAR(a, 1.0, 1e-6);
  EXPECT_NEAR(p, 2.0, 1e-12);
  // A failing evaluation is reported, not passed on.
  const CurveFunction bad = [](double, double, double*) { return false; };
  EXPECT_FALSE(LocateFold(bad, 0.5, 1.75, 1.4, 1.84, false, 1.0, &a, &p));
}

}  // namespace
}  // namespace stickslip
