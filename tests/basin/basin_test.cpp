// Basins and the smallest disturbance, against the unstable pure-slip orbit
// traced independently by the long-double reference integrator: which side of
// that closed curve a start lies on (ray casting), and its distances from
// steady sliding by brute force over a dense polygon.
#include "stickslip/basin/basin.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "reference/reference_orbit.hpp"
#include "reference_curve.hpp"
#include "stickslip/errors.hpp"

namespace stickslip {
namespace {

using reference::Real;
using testing_util::Distance;
using testing_util::Inside;
using testing_util::ReferenceCurve;

Params Stribeck(double beta, double v) {
  Params p;
  p.law = LawKind::kStribeck;
  p.beta = beta;
  p.v = v;
  return p;
}

BasinOptions Small(int n) {
  BasinOptions o;
  o.nx = o.ny = n;
  return o;
}

TEST(Basin, EveryClassifiedStartLiesOnTheSideOfTheUnstableOrbit) {
  const Params p = Stribeck(0.05, 0.6);  // studies/stribeck_basin.ini
  const BasinResult r = ClassifyBasins(Model(p), Small(13));
  ASSERT_FALSE(r.partial()) << r.message;
  ASSERT_EQ(r.orbits.pure_slip.size(), 1u);
  ASSERT_FALSE(r.orbits.pure_slip[0].stable);
  const auto curve = ReferenceCurve(p, r.orbits.pure_slip[0].start[0]);
  ASSERT_FALSE(curve.empty());
  int inside = 0, outside = 0;
  for (const BasinStart& s : r.starts) {
    const bool in = Inside(curve, s.x, s.xdot);
    SCOPED_TRACE("start (" + std::to_string(s.x) + ", " + std::to_string(s.xdot) + ") " +
                 Name(s.fate));
    if (s.fate == Fate::kUndecided) {
      EXPECT_LT(Distance(curve, s.x, s.xdot), 0.01);  // only on the boundary itself
      continue;
    }
    EXPECT_NE(s.fate, Fate::kPureSlip);  // no stable pure-slip orbit here
    EXPECT_EQ(s.fate == Fate::kSteadySliding, in);
    (in ? inside : outside)++;
  }
  EXPECT_GT(inside, 4);
  EXPECT_GT(outside, 4);
  EXPECT_EQ(r.count[0] + r.count[1] + r.count[2] + r.count[3], 13 * 13);
}

TEST(Basin, WithoutAnUnstableOrbitEveryStartEndsInStickSlip) {
  const Params p;  // the seed set at v = 0.25: steady sliding unstable, no pure slip
  const BasinResult r = ClassifyBasins(Model(p), Small(7));
  ASSERT_FALSE(r.partial()) << r.message;
  EXPECT_TRUE(r.orbits.pure_slip.empty());
  EXPECT_EQ(r.count[static_cast<int>(Fate::kStickSlip)], 49);
}

TEST(Basin, SmallestDisturbanceMatchesTheReferenceOrbit) {
  for (const Params& p : {Stribeck(0.05, 0.6), Stribeck(0.02, 1.3)}) {
    OrbitScanOptions o;
    o.orbit.flow.rtol = 1e-12;
    o.orbit.flow.atol = 1e-14;
    const PeriodicOrbits po = FindPeriodicOrbits(Model(p), o);
    ASSERT_EQ(po.pure_slip.size(), 1u);
    const Disturbance d = SmallestDisturbance(Model(p), po.pure_slip[0], o.orbit.flow);
    const auto curve = ReferenceCurve(p, po.pure_slip[0].start[0], 400);
    ASSERT_FALSE(curve.empty());
    const Real xbar = reference::Law(p).Mu(p.v);
    const auto [dx, dy, e] = testing_util::BruteDisturbance(curve, xbar);
    // The polygon's vertices are about 4e-5 apart: brute force is good to that.
    EXPECT_NEAR(d.x, static_cast<double>(dx), 1e-4);
    EXPECT_NEAR(d.xdot, static_cast<double>(dy), 1e-4);
    EXPECT_NEAR(d.energy, static_cast<double>(e), 1e-8);
    EXPECT_LE(d.energy, 0.5 * d.x * d.x + 1e-12);
    EXPECT_LE(d.energy, 0.5 * d.xdot * d.xdot + 1e-12);
  }
}

TEST(Basin, InvalidOptionsThrowAndCancelKeepsTheStartsSoFar) {
  BasinOptions o = Small(3);
  o.t_cap = -1;
  EXPECT_THROW(ClassifyBasins(Model(Params()), o), InvalidArgument);
  o = Small(5);
  int calls = 0;
  o.progress = [&](int, int) { ++calls; };
  o.cancelled = [&] { return calls >= 3; };
  const BasinResult r = ClassifyBasins(Model(Stribeck(0.05, 0.6)), o);
  EXPECT_EQ(r.status, BasinStatus::kCancelled);
  EXPECT_EQ(r.starts.size(), 3u);
  EXPECT_NE(r.message.find("start"), std::string::npos);
}

}  // namespace
}  // namespace stickslip
