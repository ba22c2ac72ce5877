// Periodic orbits against the independent long-double integrator, the trace
// formula, Leine et al. (1998) and the stick-set structure.
#include "stickslip/orbits/orbit.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "coulomb_damped.hpp"
#include "numerics/roots.hpp"
#include "reference/reference_orbit.hpp"
#include "stickslip/continuation/continuation.hpp"

namespace stickslip {
namespace {

OrbitOptions Tight(bool floquet = false) {
  OrbitOptions o;
  o.flow.rtol = 1e-12;
  o.flow.atol = 1e-14;
  o.floquet = floquet;
  return o;
}

Params Seed(double v) {
  Params p;
  p.v = v;
  return p;
}

double VMax(const Params& p) { return std::sqrt((p.k1() - 2 * p.beta) / (3 * p.k3())); }

TEST(Orbit, StickSlipMatchesTheReferenceIncludingHardCases) {
  // v = 0.005: long stick; 0.39 and 0.395: the slip ends in a near-tangential touch.
  for (double v : {0.005, 0.05, 0.25, 0.39, 0.395}) {
    const Params p = Seed(v);
    OrbitFinder finder(Model(p), Tight());
    const OrbitResult r = finder.StickSlip();
    ASSERT_TRUE(r.ok()) << "v = " << v << ": " << r.message;
    const reference::StickSlipOrbit ref = reference::StickSlip(p);
    ASSERT_TRUE(ref.found);
    const double scale = v < 0.01 ? 1e-9 / v : 1e-9;  // T ~ 1/v: x_a errors amplify
    EXPECT_NEAR(r.orbit.period, static_cast<double>(ref.period), scale) << "v = " << v;
    EXPECT_NEAR(r.orbit.t_stick, static_cast<double>(ref.t_stick), scale) << "v = " << v;
    EXPECT_NEAR(r.orbit.extrema.x_max, static_cast<double>(ref.x_max), 1e-9) << "v = " << v;
    EXPECT_NEAR(r.orbit.extrema.x_min, static_cast<double>(ref.x_min), 1e-9) << "v = " << v;
    EXPECT_NEAR(r.orbit.extrema.xdot_min, static_cast<double>(ref.xdot_min), 1e-9) << "v = " << v;
    EXPECT_GT(r.orbit.t_stick, 0.0);
  }
}

TEST(Orbit, StickSlipMultipliersAreOneAndZero) {
  for (double v : {0.05, 0.25, 0.39}) {
    OrbitFinder finder(Model(Seed(v)), Tight(true));
    const OrbitResult r = finder.StickSlip();
    ASSERT_TRUE(r.ok());
    EXPECT_NEAR(std::abs(r.orbit.eigenvalues[0] - 1.0), 0.0, 1e-9) << "v = " << v;
    EXPECT_NEAR(std::abs(r.orbit.eigenvalues[1]), 0.0, 1e-9) << "v = " << v;
    EXPECT_TRUE(r.orbit.stable);
  }
  // Coulomb: the field jumps at the exit, S_out != I; still {1, 0}.
  Params c;  // beta = 0: with damping the coulomb law has no stick-slip orbit
  c.law = LawKind::kCoulomb;
  c.beta = 0;
  c.v = 0.25;
  OrbitFinder finder(Model(c), Tight(true));
  const OrbitResult r = finder.StickSlip();
  ASSERT_TRUE(r.ok());
  EXPECT_NEAR(std::abs(r.orbit.eigenvalues[0] - 1.0), 0.0, 1e-9);
  EXPECT_NEAR(std::abs(r.orbit.eigenvalues[1]), 0.0, 1e-9);
}

TEST(Orbit, PureSlipMatchesReferenceAndTheTraceFormula) {
  for (double v : {0.40, 0.42, 0.44}) {
    const Params p = Seed(v);
    OrbitFinder finder(Model(p), Tight(true));
    const OrbitResult r = finder.PureSlip(0.3);
    ASSERT_TRUE(r.ok()) << "v = " << v << ": " << r.message;
    const reference::PureSlipOrbit ref =
        reference::PureSlip(p, static_cast<long double>(r.orbit.start[0]));
    ASSERT_TRUE(ref.found);
    EXPECT_NEAR(r.orbit.period, static_cast<double>(ref.period), 1e-9) << "v = " << v;
    EXPECT_NEAR(r.orbit.extrema.x_max, static_cast<double>(ref.x_max), 1e-9) << "v = " << v;
    EXPECT_NEAR(r.orbit.extrema.xdot_min, static_cast<double>(ref.xdot_min), 1e-9) << "v = " << v;
    // Trace formula exp(oint(-2 beta + F'(x' - v)) dt), integrated by the reference.
    EXPECT_NEAR(r.orbit.multiplier, static_cast<double>(ref.multiplier), 1e-8) << "v = " << v;
    EXPECT_NEAR(std::abs(r.orbit.eigenvalues[0] - 1.0), 0.0, 1e-7);
    EXPECT_NEAR(r.orbit.eigenvalues[1].real(), r.orbit.multiplier, 1e-7);
    EXPECT_TRUE(r.orbit.stable);
    EXPECT_LT(r.orbit.extrema.xdot_max, v);
  }
}

TEST(Orbit, JustAboveGrazingPassesWithinAHairOfTheBeltAndDoesNotStick) {
  const Params base;
  const double v_gr = static_cast<double>(reference::GrazingSpeed(base, 0.39L, 0.40L));
  const Params p = Seed(v_gr + 5e-7);
  OrbitFinder finder(Model(p), Tight());
  EXPECT_EQ(finder.StickSlip(true).status, OrbitStatus::kMissed);
  const OrbitResult r = finder.PureSlip(0.45);
  ASSERT_TRUE(r.ok()) << r.message;
  EXPECT_LT(r.orbit.extrema.xdot_max, p.v);
  EXPECT_LT(p.v - r.orbit.extrema.xdot_max, 1e-5);  // within a hair of x' = v
  EXPECT_EQ(r.orbit.t_stick, 0.0);
  // Just below: the stick phase is short but present.
  OrbitFinder below(Model(Seed(v_gr - 5e-7)), Tight());
  const OrbitResult s = below.StickSlip();
  ASSERT_TRUE(s.ok()) << s.message;
  EXPECT_GT(s.orbit.t_stick, 0.0);
  EXPECT_LT(s.orbit.t_stick, 1e-2);
}

TEST(Orbit, ConvergesCloseUnderTheHopfPoint) {
  const Params p = Seed(VMax(Params()) - 1e-4);
  OrbitFinder finder(Model(p), Tight(true));
  const OrbitResult r = finder.PureSlip(0.05);
  ASSERT_TRUE(r.ok()) << r.message;
  EXPECT_GT(r.orbit.multiplier, 0.99);
  EXPECT_LT(r.orbit.multiplier, 1.0);
  // Averaging (Thomsen & Fidlin 2003): amplitude 2 sqrt((k1 - 2b - 3 k3 v^2) / (3 k3)),
  // exact to leading order at the Hopf point.
  const double a_avg = 2 * std::sqrt((p.k1() - 2 * p.beta - 3 * p.k3() * p.v * p.v) / (3 * p.k3()));
  EXPECT_NEAR(r.orbit.extrema.xdot_max - r.orbit.extrema.xdot_min, 2 * a_avg, 0.05 * a_avg);
}

TEST(Orbit, LeinePublishedValues) {
  // Leine et al. (1998): beta 0, mu_s 1, delta 3, v 0.2.
  Params p;
  p.law = LawKind::kLeine;
  p.beta = 0;
  p.mu_s = 1;
  p.delta = 3;
  p.v = 0.2;
  OrbitFinder finder(Model(p), Tight(true));
  const OrbitResult r = finder.StickSlip();
  ASSERT_TRUE(r.ok()) << r.message;
  // The published x_max agrees to 7e-9 only; this code and the independent
  // long-double integrator agree to 1e-12 at 1.13394467644 (docs/validation.md).
  EXPECT_NEAR(r.orbit.extrema.x_max, static_cast<double>(reference::kLeineXMax), 1e-8);
  EXPECT_NEAR(r.orbit.period, static_cast<double>(reference::kLeinePeriod), 1e-3);
  const reference::StickSlipOrbit ref = reference::StickSlip(p);
  ASSERT_TRUE(ref.found);
  EXPECT_NEAR(r.orbit.extrema.x_max, static_cast<double>(ref.x_max), 1e-10);
  EXPECT_NEAR(r.orbit.period, static_cast<double>(ref.period), 1e-9);
}

TEST(Orbit, BetaZeroAndAllTolerances) {
  Params p;
  p.beta = 0;
  const reference::StickSlipOrbit ref = reference::StickSlip(p);
  ASSERT_TRUE(ref.found);
  for (double tol : {1e-4, 1e-6, 1e-8, 1e-10, 1e-12}) {
    OrbitOptions o;
    o.flow.rtol = tol;
    o.flow.atol = tol * 1e-2;
    OrbitFinder finder(Model(p), o);
    const OrbitResult r = finder.StickSlip();
    ASSERT_TRUE(r.ok()) << "rtol " << tol;
    EXPECT_NEAR(r.orbit.period, static_cast<double>(ref.period), 300 * tol) << "rtol " << tol;
  }
}

TEST(Orbit, StribeckCoexistenceOfThreeSolutions) {
  Params p;
  p.law = LawKind::kStribeck;
  p.mu_s = 0.4;
  p.mu_k = 0.25;
  p.v_s = 0.5;
  p.beta = 0.05;
  p.v = 0.6;
  const Model m(p);
  OrbitFinder finder(m, Tight(true));
  const OrbitResult ss = finder.StickSlip();
  ASSERT_TRUE(ss.ok());
  EXPECT_TRUE(ss.orbit.stable);
  EXPECT_TRUE(m.SteadySliding().stable());
  const std::vector<Orbit> ps = finder.PureSlipScan(1e-3, 1.0, 40);
  ASSERT_EQ(ps.size(), 1u);
  EXPECT_FALSE(ps[0].stable);
  EXPECT_GT(ps[0].multiplier, 1.0);
  EXPECT_LT(ps[0].extrema.xdot_max, p.v);
  const reference::PureSlipOrbit ref =
      reference::PureSlip(p, static_cast<long double>(ps[0].start[0]));
  ASSERT_TRUE(ref.found);
  EXPECT_NEAR(ps[0].period, static_cast<double>(ref.period), 1e-8);
  EXPECT_NEAR(ps[0].multiplier, static_cast<double>(ref.multiplier), 1e-7);
}

}  // namespace
}  // namespace stickslip

namespace stickslip {
namespace {

// A stick-slip orbit whose slip phase reaches x' = v left of Omega, crosses
// into slip above the belt, and sticks on the way down (Leine law, v = 1):
// the same machinery, segment by segment, with a crossing saltation matrix.
TEST(Orbit, StickSlipThroughSlipAboveTheBelt) {
  Params p;
  p.law = LawKind::kLeine;
  p.beta = 0;
  p.mu_s = 1;
  p.delta = 3;
  p.v = 1;
  OrbitFinder finder(Model(p), Tight(true));
  const OrbitResult r = finder.StickSlip();
  ASSERT_TRUE(r.ok()) << r.message;
  const reference::StickSlipOrbit ref = reference::StickSlip(p);
  ASSERT_TRUE(ref.found);
  EXPECT_EQ(r.orbit.crossings, ref.crossings);
  EXPECT_EQ(r.orbit.crossings, 1);
  ASSERT_GE(r.orbit.modes.size(), 3u);
  EXPECT_EQ(r.orbit.modes[0], Mode::kSlipBelow);
  EXPECT_EQ(r.orbit.modes[1], Mode::kSlipAbove);
  EXPECT_EQ(r.orbit.modes.back(), Mode::kStick);
  EXPECT_NEAR(r.orbit.period, static_cast<double>(ref.period), 1e-9);
  EXPECT_NEAR(r.orbit.extrema.xdot_max, static_cast<double>(ref.xdot_max), 1e-9);
  EXPECT_NEAR(r.orbit.extrema.x_min, static_cast<double>(ref.x_min), 1e-9);
  // Still superstable: S_in kills the velocity perturbation whatever came before.
  EXPECT_NEAR(std::abs(r.orbit.eigenvalues[0] - 1.0), 0.0, 1e-8);
  EXPECT_NEAR(std::abs(r.orbit.eigenvalues[1]), 0.0, 1e-8);
}

// Pure-slip orbits at the options the apps use (not Tight), across
// (GR, HB) including near both ends, against the long-double reference's
// fixed point of the section map: the section point, period and x' range to
// 1e-9. A Newton tolerance looser than the integration shows here.
TEST(Orbit, PureSlipAtDefaultOptionsMatchesTheReferenceFixedPoint) {
  for (double v : {0.397, 0.41, 0.43, 0.44}) {
    const Params p = Seed(v);
    const OrbitOptions defaults;
    OrbitFinder finder(Model(p), defaults);
    const OrbitResult r = finder.PureSlip(0.3);
    ASSERT_TRUE(r.ok()) << "v = " << v << ": " << r.message;
    const reference::PureSlipOrbit ref =
        reference::PureSlip(p, static_cast<long double>(r.orbit.start[0]));
    ASSERT_TRUE(ref.found) << "v = " << v;
    EXPECT_NEAR(r.orbit.start[0], static_cast<double>(ref.x_section), 1e-9) << "v = " << v;
    EXPECT_NEAR(r.orbit.period, static_cast<double>(ref.period), 1e-9) << "v = " << v;
    EXPECT_NEAR(r.orbit.extrema.xdot_min, static_cast<double>(ref.xdot_min), 1e-9) << "v = " << v;
    EXPECT_NEAR(r.orbit.extrema.xdot_max, static_cast<double>(ref.xdot_max), 1e-9) << "v = " << v;
  }
}

// At the default options, the amplitude a = x* - mu(v) against the
// reference's fixed point, from several guesses: small orbits just past the
// Hopf point of each law with a smooth slip field (G_a ~ a there), and a large
// one (leine, a = 2.5). The orbit reported is the Newton iterate before its
// last step, so that step must be at the integration noise (0.1 rtol), not at
// the Newton tolerance (1e-10 max(1, a)).
TEST(Orbit, PureSlipAmplitudeIsAtTheIntegrationNoiseFromAnyGuess) {
  Params seed = Seed(0.4405);  // v_max = 0.44096 (seed 3.16)
  Params stribeck = seed, leine = seed, large = seed;
  stribeck.law = LawKind::kStribeck, stribeck.v = 0.5496;         // HB at 0.549306
  leine.law = LawKind::kLeine, leine.mu_s = 1, leine.v = 1.4927;  // HB at 1.492409
  large.law = LawKind::kLeine, large.mu_s = 1, large.v = 2.5;
  const struct {
    Params p;
    double a;
  } cases[] = {{seed, 0.05}, {stribeck, 0.05}, {leine, 0.05}, {large, 2.5}};
  for (const auto& c : cases) {
    SCOPED_TRACE(std::string(Name(c.p.law)) + " v " + std::to_string(c.p.v));
    const reference::Real xbar = reference::Law(c.p).Mu(c.p.v);
    const reference::PureSlipOrbit ref = reference::PureSlip(c.p, xbar + c.a);
    ASSERT_TRUE(ref.found);
    const double a_ref = static_cast<double>(ref.x_section - xbar);
    for (double guess : {0.6 * a_ref, 0.9 * a_ref, 1.2 * a_ref}) {
      OrbitFinder finder{Model(c.p), OrbitOptions{}};
      const OrbitResult r = finder.PureSlip(guess);
      ASSERT_TRUE(r.ok()) << r.message;
      const double a = r.orbit.start[0] - Model(c.p).SteadySliding().x;
      EXPECT_NEAR(a, a_ref, 1e-12 * std::max(1.0, a_ref)) << "guess " << guess;
      EXPECT_NEAR(r.orbit.period, static_cast<double>(ref.period), 1e-12 * r.orbit.period);
    }
  }
}

// The desingularised return map G(a) = (P(mu(v) + a) - mu(v) - a) / a of a
// small orbit (a = 1e-4) next to each smooth law's Hopf point, at the default
// options and without the variational equations (as for the dG/dp difference
// and the section scans): the Taylor step measures x from steady sliding, so
// the error of P is relative to a, not to mu(v) (it was 1.4e-10 .. 2.5e-10 in G).
TEST(Orbit, ReturnMapOfASmallOrbitIsAccurateRelativeToItsAmplitude) {
  Params seed = Seed(0.43896);  // v_max = 0.44096 (seed 3.16)
  Params stribeck = seed, leine = seed;
  stribeck.law = LawKind::kStribeck, stribeck.v = 0.5513;         // HB at 0.549306
  leine.law = LawKind::kLeine, leine.mu_s = 1, leine.v = 1.4944;  // HB at 1.492409
  const double a = 1e-4;
  for (const Params& p : {seed, stribeck, leine}) {
    SCOPED_TRACE(Name(p.law));
    OrbitFinder finder{Model(p), OrbitOptions{}};
    double g = 0;
    ASSERT_EQ(finder.Desingularised(a, &g, nullptr), OrbitStatus::kOk);
    const reference::Model m(p);
    const reference::Real xbar = m.law.Mu(m.v);
    const reference::SectionReturn r = reference::ReturnToSection(m, xbar + a, 1e-18L, 100);
    ASSERT_TRUE(r.ok);
    EXPECT_NEAR(g, static_cast<double>((r.x - xbar - a) / a), 5e-11);
  }
}

// The seed's Hopf point is supercritical (mu''' = 6 k3 > 0; v_max of seed
// (3.16)): stable pure-slip orbits are born where steady sliding is unstable
// (v < v_max), which the reference confirms; the label must say so.
TEST(Orbit, SeedHopfPointIsLabelledSupercritical) {
  const Params base;
  const double v_max = VMax(base);
  ContinuationOptions o;
  o.from = 0.43;
  o.to = 0.45;
  const ContinuationResult c = Continue(base, o);
  ASSERT_FALSE(c.partial()) << c.message;
  int hopf = 0;
  for (const SpecialPoint& s : c.special) {
    if (s.kind != SpecialKind::kHopf) continue;
    ++hopf;
    EXPECT_NEAR(s.p, v_max, 1e-9);
    EXPECT_NE(s.description.find("supercritical"), std::string::npos) << s.description;
    EXPECT_EQ(s.description.find("subcritical"), std::string::npos) << s.description;
  }
  EXPECT_EQ(hopf, 1);
  const reference::PureSlipOrbit ref = reference::PureSlip(Seed(v_max - 1e-3), 0.3L);
  ASSERT_TRUE(ref.found);
  EXPECT_FALSE(ref.sticks);
  EXPECT_LT(std::abs(static_cast<double>(ref.multiplier)), 1.0);  // stable: supercritical
}

}  // namespace
}  // namespace stickslip

namespace stickslip {
namespace {

// Coulomb law with damping: slip is a damped linear oscillator, so no
// pure-slip orbit exists, and the stick-slip orbit disappears where its first
// return touches x' = v tangentially at the fold x = mu_k - 2 beta v of the
// slip field, inside the stick band (closed form: coulomb_damped.hpp).
TEST(Orbit, CoulombWithDampingGrazesAtTheClosedFormInsideTheStickBand) {
  for (double beta : {0.05, 0.2}) {
    Params p;
    p.law = LawKind::kCoulomb;
    p.beta = beta;
    const double v_end = static_cast<double>(coulomb_damped::EndSpeed(p.mu_s, p.mu_k, beta));
    auto gap = [&](double v) {
      p.v = v;
      OrbitFinder finder(Model(p), Tight());
      double g = NAN;
      EXPECT_EQ(finder.GrazingGap(&g), OrbitStatus::kOk);
      return g;
    };
    const RootResult root = FindRoot(gap, 0.5 * v_end, 1.5 * v_end, 1e-13);
    ASSERT_TRUE(root.ok);
    EXPECT_NEAR(root.x, v_end, 1e-9) << "beta = " << beta;
    // Where it touches: the fold of the slip field, strictly inside the band.
    p.v = v_end;
    OrbitFinder finder(Model(p), Tight());
    double g = 0;
    FlowResult run;
    ASSERT_EQ(finder.GrazingGap(&g, &run), OrbitStatus::kOk);
    EXPECT_NEAR(run.z[0], p.mu_k - 2 * beta * v_end, 1e-7);
    EXPECT_NEAR(run.t,
                static_cast<double>(coulomb_damped::FirstMaxTime(p.mu_s, p.mu_k, beta, v_end)),
                1e-7);
    // Just below the end the orbit sticks, with about Delta / v of stick.
    p.v = v_end * (1 - 1e-9);
    finder.set_model(Model(p));
    const OrbitResult r = finder.StickSlip();
    ASSERT_TRUE(r.ok()) << r.message;
    EXPECT_NEAR(r.orbit.period,
                static_cast<double>(coulomb_damped::EndPeriod(p.mu_s, p.mu_k, beta)), 1e-3);
    EXPECT_GT(r.orbit.t_stick, 0.9 * (p.mu_s - p.mu_k) / v_end);
    // Just above it the first return stays below the belt.
    p.v = v_end * (1 + 1e-6);
    finder.set_model(Model(p));
    EXPECT_EQ(finder.StickSlip(true).status, OrbitStatus::kMissed);
  }
}

}  // namespace
}  // namespace stickslip
