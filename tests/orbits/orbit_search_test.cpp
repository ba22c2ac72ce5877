// Every periodic orbit of a system with a clock at a parameter point
// (orbit_search.hpp), on the forced oscillator: the search against Den
// Hartog's closed form and against the closed-form (long double,
// piecewise-linear) coulomb simulation.
#include "stickslip/orbits/orbit_search.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>

#include "forced_reference.hpp"
#include "stickslip/errors.hpp"
#include "stickslip/orbits/forced_orbit.hpp"
#include "stickslip/systems/belt/model.hpp"

namespace stickslip {
namespace {

namespace ref = forced_reference;
using ref::Real;

using ref::Coulomb;

// The forced tools' search: the forced flow's defaults, the model's box.
OrbitSearchOptions ForcedSearch(const ForcedBelt& model) {
  OrbitSearchOptions o;
  o.orbit = ShootingOptions(ForcedBelt::FlowDefaults());
  o.half_width = model.SearchBox();
  return o;
}

FoundOrbits Scan(const ForcedBeltParams& p, bool model_box = true) {
  const auto t0 = std::chrono::steady_clock::now();
  const ForcedBelt model(p);
  OrbitSearchOptions o = ForcedSearch(model);
  if (!model_box) o.half_width = {0, 0};
  const FoundOrbits r = FindOrbits(model, o);
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::printf("[ measured ] scan: %zu orbits from %d shots (%d converged) in %.3f s\n",
              r.orbits.size(), r.shots, r.converged, s);
  for (const FoundOrbit& o : r.orbits)
    std::printf("             m = %d, sticks %d, x_max %.12g, |mult| %.3g, %s, %s\n", o.m,
                o.orbit.sticks, OrbitExtrema(o.orbit).x_max, std::abs(o.orbit.multipliers[0]),
                o.orbit.stable ? "stable" : "unstable", o.from_exit_map ? "exit map" : "strobe");
  return r;
}

// Den Hartog (1931), mu_s = mu_k = mu, beta = 0, v = 0, no stop:
// X = sqrt(V^2 - (mu U)^2), V = A / (1 - Omega^2), U = sin(pi/Omega) / (Omega (1 + cos(pi/Omega))).
double DenHartogX(double mu, double a, double w) {
  const double V = a / (1 - w * w), U = std::sin(M_PI / w) / (w * (1 + std::cos(M_PI / w)));
  return std::sqrt(V * V - mu * mu * U * U);
}

TEST(OrbitSearch, FindsDenHartogsNonStopOrbit) {
  for (double w : {0.8, 1.5, 2.2})
    for (bool model_box : {true, false}) {  // the box a run sizes finds it too
      const FoundOrbits r = Scan(Coulomb(0.3, 0.3, 0, 0, 1, w), model_box);
      ASSERT_TRUE(r.ok());
      int nonstop = 0;
      for (const FoundOrbit& o : r.orbits) {
        if (o.m != 1 || o.orbit.sticks != 0) continue;
        ++nonstop;
        EXPECT_NEAR(OrbitExtrema(o.orbit).x_max, DenHartogX(0.3, 1, w), 1e-9) << "Omega = " << w;
        EXPECT_NEAR(-OrbitExtrema(o.orbit).x_min, DenHartogX(0.3, 1, w), 1e-9) << "Omega = " << w;
      }
      EXPECT_EQ(nonstop, 1) << "Omega = " << w;
      if (!model_box) {
        EXPECT_GT(r.half_width[0], DenHartogX(0.3, 1, w));
      }
    }
}

// Each orbit's stroboscopic points are mapped onto each other by the
// closed-form simulation, which sticks as often.
void CheckAgainstClosedForm(const ForcedBeltParams& p, const FoundOrbits& r) {
  for (const FoundOrbit& o : r.orbits) {
    ASSERT_EQ(static_cast<int>(o.points.size()), o.m);
    ref::PieceSim<ref::CoulombPiece> sim(
        ref::Setup{reference::Law(p.base), p.base.beta, p.base.v, p.force, p.omega});
    Real t = 0, x = o.points[0][0], y = o.points[0][1];
    const Real T = 2 * std::acos(Real(-1)) / p.omega;
    for (int j = 1; j <= o.m; ++j) {
      sim.Run(t, x, y, j * T);
      const Eigen::VectorXd& next = o.points[j % o.m];
      EXPECT_NEAR(static_cast<double>(x), next[0], 1e-9) << "m " << o.m << " point " << j;
      EXPECT_NEAR(static_cast<double>(y), next[1], 1e-9) << "m " << o.m << " point " << j;
    }
    EXPECT_EQ(sim.sticks, o.orbit.sticks) << "m " << o.m;
  }
}

TEST(OrbitSearch, FloorStickSlipOrbitsAgreeWithTheClosedForm) {
  const ForcedBeltParams p = Coulomb(0.4, 0.3, 0.05, 0, 0.7, 0.6);
  const FoundOrbits r = Scan(p);
  ASSERT_TRUE(r.ok());
  int stick_slip = 0;
  for (const FoundOrbit& o : r.orbits) stick_slip += o.orbit.sticks > 0;
  EXPECT_GE(stick_slip, 1);
  CheckAgainstClosedForm(p, r);
}

TEST(OrbitSearch, BeltStickSlipOrbitsAgreeWithTheClosedForm) {
  const ForcedBeltParams p = Coulomb(0.4, 0.25, 0.05, 0.2, 0.3, 0.8);
  const FoundOrbits r = Scan(p);
  ASSERT_TRUE(r.ok());
  ASSERT_FALSE(r.orbits.empty());
  CheckAgainstClosedForm(p, r);
}

// Past the PD of the forced Stribeck scene (studies/stribeck_forced.ini, PD at
// Omega = 0.6182) the scan finds the doubled orbit: m = 2, two sticks, stable,
// with the m = 1 orbit unstable; the long-double RKF78 reference maps its two
// stroboscopic points onto each other.
TEST(OrbitSearch, FindsThePeriodDoubledOrbit) {
  ForcedBeltParams p;
  p.base.law = LawKind::kStribeck;
  p.base.beta = 0.05, p.base.v = 0.25, p.base.mu_s = 0.4, p.base.mu_k = 0.25, p.base.v_s = 0.2;
  p.force = 0.3, p.omega = 0.612;
  const FoundOrbits r = Scan(p);
  ASSERT_TRUE(r.ok());
  const FoundOrbit* doubled = nullptr;
  bool m1_unstable = false;
  for (const FoundOrbit& o : r.orbits) {
    if (o.m == 2 && o.orbit.stable) doubled = &o;
    if (o.m == 1 && o.orbit.sticks == 1) m1_unstable = !o.orbit.stable;
  }
  EXPECT_TRUE(m1_unstable);
  ASSERT_NE(doubled, nullptr);
  EXPECT_EQ(doubled->orbit.sticks, 2);
  const Real T = 2 * std::acos(Real(-1)) / p.omega;
  for (int j = 0; j < 2; ++j) {
    ref::PieceSim<ref::OdeintPiece> sim(
        ref::Setup{reference::Law(p.base), p.base.beta, p.base.v, p.force, p.omega});
    Real t = 0, x = doubled->points[j][0], y = doubled->points[j][1];
    sim.Run(t, x, y, T);
    EXPECT_NEAR(static_cast<double>(x), doubled->points[1 - j][0], 1e-9) << "point " << j;
    EXPECT_NEAR(static_cast<double>(y), doubled->points[1 - j][1], 1e-9) << "point " << j;
  }
}

TEST(OrbitSearch, RejectsBadOptions) {
  const ForcedBelt model(Coulomb(0.3, 0.3, 0, 0, 1, 1.5));
  OrbitSearchOptions o;
  o.max_m = 0;
  EXPECT_THROW(FindOrbits(model, o), InvalidArgument);
  o = OrbitSearchOptions();
  o.plane = {0, 2};  // the clock
  EXPECT_THROW(FindOrbits(model, o), InvalidArgument);
  o.plane = {1, 1};
  EXPECT_THROW(FindOrbits(model, o), InvalidArgument);
  o = OrbitSearchOptions();
  o.center = Eigen::Vector2d(0, 0);  // (x, x', theta) has 3
  EXPECT_THROW(FindOrbits(model, o), InvalidArgument);
  o.center = Eigen::Vector3d(0, NAN, 0);
  EXPECT_THROW(FindOrbits(model, o), InvalidArgument);
  o = OrbitSearchOptions();
  o.half_width = {-1, 1};
  EXPECT_THROW(FindOrbits(model, o), InvalidArgument);
  // The belt has no clock: its orbits are FindPeriodicOrbits' (orbit_scan.hpp).
  EXPECT_THROW(FindOrbits(Model(Params()), OrbitSearchOptions()), InvalidArgument);
}

TEST(OrbitSearch, CancelKeepsWhatWasFound) {
  const ForcedBelt model(Coulomb(0.3, 0.3, 0, 0, 1, 1.5));
  OrbitSearchOptions o = ForcedSearch(model);
  int polls = 0;
  const FoundOrbits all = FindOrbits(model, o);
  ASSERT_TRUE(all.ok());
  ASSERT_FALSE(all.orbits.empty());
  // Cancelled at the poll after the first orbit was found: that orbit is kept,
  // with its data, and the scan stopped short.
  int found_at = -1;
  for (int k = 1; k < 10000 && found_at < 0; k *= 2) {
    o.cancelled = [&] { return ++polls > k; };
    polls = 0;
    const FoundOrbits r = FindOrbits(model, o);
    EXPECT_EQ(r.status, OrbitScanStatus::kCancelled) << "after " << k << " polls";
    if (r.orbits.empty()) continue;
    found_at = k;
    EXPECT_LT(r.shots, all.shots);
    for (const FoundOrbit& c : r.orbits) {
      bool known = false;
      for (const FoundOrbit& a : all.orbits)
        known = known || (a.m == c.m && std::abs(OrbitExtrema(a.orbit).x_max -
                                                 OrbitExtrema(c.orbit).x_max) < 1e-10);
      EXPECT_TRUE(known) << "m = " << c.m << ", x_max " << OrbitExtrema(c.orbit).x_max;
      EXPECT_TRUE(c.orbit.ok());
      EXPECT_EQ(static_cast<int>(c.points.size()), c.m);
    }
  }
  EXPECT_GT(found_at, 0) << "no cancelled scan kept an orbit";
}

}  // namespace
}  // namespace stickslip
