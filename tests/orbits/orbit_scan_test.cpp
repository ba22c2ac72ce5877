// Every periodic orbit at one parameter point, against the independent
// long-double reference integrator: each pure-slip orbit's section point,
// period and multiplier (trace formula), the stick-slip orbit, and the count of
// fixed points of the reference's own return map below the belt speed.
#include "stickslip/orbits/orbit_scan.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "reference/reference_orbit.hpp"
#include "stickslip/errors.hpp"

namespace stickslip {
namespace {

struct Case {
  LawKind law;
  double beta, v, mu_s;
  int pure_slip;  // how many the scan must find
};

Params At(const Case& c) {
  Params p;
  p.law = c.law;
  p.beta = c.beta;
  p.v = c.v;
  p.mu_s = c.mu_s;
  return p;
}

OrbitScanOptions TightScan() {
  OrbitScanOptions o;
  o.orbit.flow.rtol = 1e-12;
  o.orbit.flow.atol = 1e-14;
  return o;
}

// Fixed points of the reference return map of x' = 0 whose orbit stays below
// the belt: sign changes of P(x) - x on a grid of section points x > xbar.
int ReferenceFixedPoints(const Params& p, double a_max) {
  const reference::Model m(p);
  const reference::Real xbar = m.law.Mu(m.v);
  int count = 0;
  reference::Real prev = 0;
  bool have = false;
  for (int i = 1; i <= 120; ++i) {
    const reference::Real x = xbar + a_max * i / 120;
    const reference::SectionReturn r = reference::ReturnToSection(m, x, 1e-14L, 200);
    if (!r.ok || r.e.xdot_max >= m.v) break;  // reaches the belt speed: sticks
    const reference::Real g = r.x - x;
    if (have && (g > 0) != (prev > 0)) ++count;
    prev = g, have = true;
  }
  return count;
}

TEST(OrbitScan, FindsEveryPureSlipOrbitAndMatchesTheReference) {
  // Bistable bands: the unstable pure-slip orbit between steady sliding and
  // stick-slip (stribeck beta 0.02 at v 1.3, the stribeck scene at v 0.6, leine
  // at beta 0.05, v 2); a stable one past the seed's grazing point (cubic
  // v 0.42); none at the seed set (v 0.25).
  const Case cases[] = {{LawKind::kStribeck, 0.02, 1.3, 0.4, 1},
                        {LawKind::kStribeck, 0.05, 0.6, 0.4, 1},
                        {LawKind::kLeine, 0.05, 2.0, 1.0, 1},
                        {LawKind::kCubic, 0.05, 0.42, 0.4, 1},
                        {LawKind::kCubic, 0.05, 0.25, 0.4, 0}};
  for (const Case& c : cases) {
    const Params p = At(c);
    SCOPED_TRACE(std::string(Name(c.law)) + " v = " + std::to_string(c.v));
    const PeriodicOrbits r = FindPeriodicOrbits(Model(p), TightScan());
    ASSERT_TRUE(r.ok()) << r.message;
    ASSERT_EQ(static_cast<int>(r.pure_slip.size()), c.pure_slip);
    EXPECT_EQ(ReferenceFixedPoints(p, r.a_stick < r.a_max ? r.a_stick : r.a_max), c.pure_slip);
    for (const Orbit& o : r.pure_slip) {
      const reference::PureSlipOrbit ref = reference::PureSlip(p, o.start[0]);
      ASSERT_TRUE(ref.found);
      EXPECT_NEAR(o.start[0], static_cast<double>(ref.x_section), 1e-8);
      EXPECT_NEAR(o.period, static_cast<double>(ref.period), 1e-8);
      EXPECT_NEAR(o.multiplier, static_cast<double>(ref.multiplier), 1e-7);
      EXPECT_EQ(o.stable, ref.multiplier < 1);
      EXPECT_LT(o.extrema.xdot_max, c.v);
    }
    // Steady sliding: xbar = mu(v), stable where 2 beta + mu'(v) > 0.
    const reference::Law law(p);
    EXPECT_NEAR(r.steady.x, static_cast<double>(law.Mu(c.v)), 1e-14);
    EXPECT_EQ(r.steady.stable(), 2 * c.beta + law.DMu(c.v) > 0);
  }
}

TEST(OrbitScan, StickSlipOrbitMatchesTheReference) {
  const Case cases[] = {{LawKind::kStribeck, 0.02, 1.3, 0.4, 1},
                        {LawKind::kLeine, 0.05, 2.0, 1.0, 1},
                        {LawKind::kCubic, 0.05, 0.25, 0.4, 0}};
  for (const Case& c : cases) {
    const Params p = At(c);
    const PeriodicOrbits r = FindPeriodicOrbits(Model(p), TightScan());
    ASSERT_TRUE(r.ok()) << r.message;
    const reference::StickSlipOrbit ref = reference::StickSlip(p);
    ASSERT_TRUE(ref.found);
    ASSERT_TRUE(r.has_stick_slip);
    EXPECT_NEAR(r.stick_slip.period, static_cast<double>(ref.period), 1e-8);
    EXPECT_NEAR(r.stick_slip.extrema.x_max, static_cast<double>(ref.x_max), 1e-9);
    EXPECT_TRUE(r.stick_slip.stable);
  }
  // Cubic v = 0.42, past grazing: no stick-slip orbit.
  const PeriodicOrbits r =
      FindPeriodicOrbits(Model(At({LawKind::kCubic, 0.05, 0.42, 0.4, 1})), TightScan());
  EXPECT_FALSE(r.has_stick_slip);
}

// Pure-slip orbits of the reference return map next to the sticking amplitude:
// bisection for the reference's own first sticking amplitude a_s, then sign
// changes of P(x) - x on a grid of 60 amplitudes whose last lies 1e-9 a_s below
// it, each refined by reference Newton. Near a grazing or fold point the orbit
// lies in the last cell, the one between the scan's grid and a_s.
std::vector<reference::PureSlipOrbit> ReferenceOrbitsBelowStick(const Params& p) {
  const reference::Model m(p);
  const reference::Real xbar = m.law.Mu(m.v);
  auto sticks = [&](reference::Real a) {
    const reference::SectionReturn r = reference::ReturnToSection(m, xbar + a, 1e-14L, 200);
    return !r.ok || r.e.xdot_max >= m.v;
  };
  reference::Real lo = 0, hi = 2 * (p.mu_s + p.v);  // the scan's a_max
  while (hi - lo > 1e-12L * hi) (sticks((lo + hi) / 2) ? hi : lo) = (lo + hi) / 2;
  std::vector<reference::PureSlipOrbit> found;
  reference::Real a0 = 0, g0 = 0;
  for (int i = 1; i <= 60; ++i) {
    const reference::Real a = lo * (1 - 1e-9L) * i / 60;
    const reference::SectionReturn r = reference::ReturnToSection(m, xbar + a, 1e-14L, 200);
    const reference::Real g = r.x - xbar - a;
    if (i > 1 && (g > 0) != (g0 > 0)) {
      const reference::PureSlipOrbit o = reference::PureSlip(p, xbar + (a0 + a) / 2);
      if (o.found) found.push_back(o);
    }
    a0 = a, g0 = g;
  }
  return found;
}

TEST(OrbitScan, KeepsTheOrbitInTheLastBracketBeforeSticking) {
  // Just past the seed's grazing point (0.3958) the stable pure-slip orbit
  // nearly touches the belt speed; at stribeck v = 0.651, near the fold, the
  // unstable one does. Both lie in the bracket that ends at the first sticking
  // amplitude (issue 23: a scan that skipped that bracket lost them).
  const Case cases[] = {{LawKind::kCubic, 0.05, 0.396, 0.4, 1},
                        {LawKind::kCubic, 0.05, 0.397, 0.4, 1},
                        {LawKind::kStribeck, 0.05, 0.651, 0.4, 1}};
  for (const Case& c : cases) {
    const Params p = At(c);
    SCOPED_TRACE(std::string(Name(c.law)) + " v = " + std::to_string(c.v));
    const std::vector<reference::PureSlipOrbit> ref = ReferenceOrbitsBelowStick(p);
    ASSERT_EQ(static_cast<int>(ref.size()), c.pure_slip);
    for (const OrbitScanOptions& o : {OrbitScanOptions(), TightScan()}) {
      const PeriodicOrbits r = FindPeriodicOrbits(Model(p), o);
      ASSERT_TRUE(r.ok()) << r.message;
      EXPECT_EQ(r.pure_slip.size(), ref.size()) << "rtol " << o.orbit.flow.rtol;
      if (r.pure_slip.size() != ref.size()) continue;
      for (size_t i = 0; i < ref.size(); ++i) {
        const double tol = 1e3 * o.orbit.flow.rtol;
        EXPECT_NEAR(r.pure_slip[i].start[0], static_cast<double>(ref[i].x_section), tol);
        EXPECT_NEAR(r.pure_slip[i].period, static_cast<double>(ref[i].period), tol);
        EXPECT_EQ(r.pure_slip[i].stable, ref[i].multiplier < 1);
      }
    }
  }
}

TEST(OrbitScan, InvalidOptionsThrowAndCancelStops) {
  OrbitScanOptions o;
  o.samples = 2;
  EXPECT_THROW(FindPeriodicOrbits(Model(Params()), o), InvalidArgument);
  o = OrbitScanOptions();
  o.cancelled = [] { return true; };
  const PeriodicOrbits r = FindPeriodicOrbits(Model(Params()), o);
  EXPECT_EQ(r.status, OrbitScanStatus::kCancelled);
  EXPECT_FALSE(r.message.empty());
}

}  // namespace
}  // namespace stickslip
