// The Filippov model: steady sliding, Hopf point, modes, saltation matrices
// (seed eqs. 3.5-3.8, 3.16).
#include "stickslip/systems/belt/model.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>

#include "stickslip/errors.hpp"
#include "stickslip/flow/switching.hpp"

namespace stickslip {
namespace {

Params Seed() { return Params{}; }

Params Coulomb() {
  Params p;
  p.law = LawKind::kCoulomb;
  p.beta = 0;
  p.v = 0.25;
  p.mu_s = 0.4;
  p.mu_k = 0.25;
  return p;
}

void ExpectMatNear(const Mat2& a, const Mat2& b, double tol) {
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j) EXPECT_NEAR(a(i, j), b(i, j), tol) << "(" << i << "," << j << ")";
}

TEST(Model, QuinticFrictionAndDerivatives) {
  // mu(s) = mu_s - k1 s + k3 s^3 - k5 s^5 with k1 = 0.45, k3 = 0.6, k5 = 0.24: at s = 0.5
  // mu = 0.4 - 0.225 + 0.075 - 0.0075, mu' = -0.45 + 0.45 - 0.075, mu'' = 1.8 - 0.6,
  // mu''' = 3.6 - 3.6 (the sign change at sqrt(k3 / (10 k5)) = 0.5).
  Params p = Seed();
  p.k5 = 0.24;
  const Friction f(p);
  EXPECT_NEAR(f.Mu(0.5), 0.2425, 1e-15);
  EXPECT_NEAR(f.DMu(0.5), -0.075, 1e-15);
  EXPECT_NEAR(f.D2Mu(0.5), 1.2, 1e-15);
  EXPECT_NEAR(f.D3Mu(0.5), 0.0, 1e-15);
  // The other laws' second derivatives against central differences of mu'.
  for (LawKind law : {LawKind::kStribeck, LawKind::kLeine, LawKind::kCubic}) {
    Params q = Seed();
    q.law = law;
    const Friction g(q);
    const double s = 0.3, h = 1e-5;
    EXPECT_NEAR(g.D2Mu(s), (g.DMu(s + h) - g.DMu(s - h)) / (2 * h), 1e-8) << Name(law);
    EXPECT_NEAR(g.D3Mu(s), (g.D2Mu(s + h) - g.D2Mu(s - h)) / (2 * h), 1e-7) << Name(law);
  }
}

TEST(Model, QuinticFrictionTurnsNonPositive) {
  // k5 = 0.24: mu(s) = 0.4 - 0.45 s + 0.6 s^3 - 0.24 s^5 has one positive root near 1.46
  // (mu(1.45) > 0 > mu(1.47)); the seed's law and the others stay positive.
  Params p = Seed();
  p.k5 = 0.24;
  const Friction f(p);
  EXPECT_GT(0.4 - 0.45 * 1.45 + 0.6 * std::pow(1.45, 3) - 0.24 * std::pow(1.45, 5), 0);
  EXPECT_LT(0.4 - 0.45 * 1.47 + 0.6 * std::pow(1.47, 3) - 0.24 * std::pow(1.47, 5), 0);
  EXPECT_FALSE(f.NonPositiveUpTo(1.45));
  EXPECT_TRUE(f.NonPositiveUpTo(1.47));
  EXPECT_TRUE(f.NonPositiveUpTo(10.0));
  EXPECT_FALSE(Friction(Seed()).NonPositiveUpTo(100.0));
  // A dip below zero between two positive ends: mu_s 0.1, mu_m 0.001 at v_m 0.25 (k1 0.594,
  // k3 3.168), k5 2: mu(0.25) = 0.001 - 2 / 1024 < 0 < mu(0.5) = 0.1365.
  Params q = Seed();
  q.mu_s = 0.1, q.mu_m = 0.001, q.v_m = 0.25, q.v = 0.05, q.k5 = 2;
  const Friction g(q);
  ASSERT_NEAR(g.Mu(0.25), 0.001 - 2.0 / 1024, 1e-15);
  ASSERT_NEAR(g.Mu(0.5), 0.1365, 1e-12);
  EXPECT_TRUE(g.NonPositiveUpTo(0.5));
  EXPECT_FALSE(g.NonPositiveUpTo(0.1));
}

TEST(Model, RejectsInvalidParameters) {
  Params p = Seed();
  p.mu_m = 0.5;
  EXPECT_THROW(Model{p}, InvalidArgument);
}

TEST(Model, SteadySlidingAtSeedSet) {
  // x_bar = mu_s - k1 v + k3 v^3 = 0.4 - 0.1125 + 0.009375.
  const Params p = Seed();
  const Equilibrium e = Model(p).SteadySliding();
  const double v = p.v;
  EXPECT_NEAR(e.x, p.mu_s - p.k1() * v + p.k3() * v * v * v, 1e-15);
  EXPECT_NEAR(e.x, 0.296875, 1e-15);
}

TEST(Model, SteadySlidingEigenvaluesSolveCharacteristicEquation) {
  // lambda^2 + (2 beta - k1 + 3 k3 v^2) lambda + 1 = 0.
  for (double v : {0.1, 0.25, 0.4, 0.45, 0.6}) {
    Params p = Seed();
    p.v = v;
    const Equilibrium e = Model(p).SteadySliding();
    const double b = 2 * p.beta - p.k1() + 3 * p.k3() * v * v;
    EXPECT_NEAR(e.damping, b, 1e-15) << v;
    for (const std::complex<double> l : {e.lambda1, e.lambda2})
      EXPECT_LT(std::abs(l * l + b * l + 1.0), 1e-14) << "v = " << v << ", lambda = " << l;
    EXPECT_EQ(e.stable(), b > 0) << v;
  }
  // At the seed set the equilibrium is an unstable focus.
  const Equilibrium e = Model(Seed()).SteadySliding();
  EXPECT_FALSE(e.stable());
  EXPECT_GT(e.max_real(), 0);
  EXPECT_NE(e.lambda1.imag(), 0);
}

// Issue 23, N13: at v_m = 1e-6 the damping b = 2 beta + mu'(v) is ~1.4e16 and
// the slow eigenvalue (-b + sqrt(b^2 - 4)) / 2 cancelled to exactly 0. The
// reference: Newton on lambda^2 + b lambda + 1 in long double from -1/b.
TEST(Model, SlowEigenvalueOfAStiffEquilibriumIsNotZero) {
  for (double v_m : {1e-6, 1e-3, 0.05}) {
    Params p = Seed();
    p.v_m = v_m;
    p.mu_m = 0.25;
    const Equilibrium e = Model(p).SteadySliding();
    const double b = e.damping;
    ASSERT_GT(b, 2) << v_m;  // real roots
    const double slow = e.lambda1.real(), fast = e.lambda2.real();
    long double ref = -1.0L / b;
    for (int i = 0; i < 5; ++i) ref -= (ref * ref + b * ref + 1) / (2 * ref + b);
    EXPECT_NEAR(slow, static_cast<double>(ref), 1e-14 * std::abs(static_cast<double>(ref)))
        << "v_m = " << v_m;
    EXPECT_NEAR(slow * fast, 1.0, 1e-14) << "v_m = " << v_m;
    EXPECT_EQ(e.max_real(), slow);
    EXPECT_EQ(e.lambda1.imag(), 0);
  }
}

TEST(Model, HopfPointWhereDampingVanishes) {
  // Seed (3.16): v_max = sqrt((k1 - 2 beta) / (3 k3)) = 0.44096.
  const Params seed = Seed();
  const double v_hopf = std::sqrt((seed.k1() - 2 * seed.beta) / (3 * seed.k3()));
  EXPECT_NEAR(v_hopf, 0.44096, 5e-6);
  Params p = seed;
  p.v = v_hopf;
  const Equilibrium e = Model(p).SteadySliding();
  EXPECT_NEAR(e.damping, 0, 1e-15);
  EXPECT_NEAR(e.max_real(), 0, 1e-15);
  EXPECT_NEAR(std::abs(e.lambda1.imag()), 1, 1e-15);  // frequency 1 at the Hopf point
  p.v = v_hopf - 1e-3;
  EXPECT_FALSE(Model(p).SteadySliding().stable());
  p.v = v_hopf + 1e-3;
  EXPECT_TRUE(Model(p).SteadySliding().stable());
}

TEST(Model, ModeAtOffTheSwitchingSurface) {
  const Model m(Seed());  // v = 0.25
  EXPECT_EQ(m.ModeAt(Vec2(0, 0.2)), Mode::kSlipBelow);
  EXPECT_EQ(m.ModeAt(Vec2(0, -1)), Mode::kSlipBelow);
  EXPECT_EQ(m.ModeAt(Vec2(0, 0.3)), Mode::kSlipAbove);
  EXPECT_EQ(m.ModeAt(Vec2(5, 0.25 + 1e-15)), Mode::kSlipAbove);
  EXPECT_EQ(m.ModeAt(Vec2(-5, 0.25 - 1e-15)), Mode::kSlipBelow);
}

TEST(Model, ModeAtOnTheSwitchingSurface) {
  // Omega: x' = v and |x + 2 beta v| <= mu_s, i.e. x in [-0.425, 0.375].
  const Model m(Seed());
  EXPECT_EQ(m.ModeAt(Vec2(0, 0.25)), Mode::kStick);
  EXPECT_EQ(m.ModeAt(Vec2(0.37, 0.25)), Mode::kStick);
  EXPECT_EQ(m.ModeAt(Vec2(-0.42, 0.25)), Mode::kStick);
  // Beyond the static limit both one-sided fields point the same way.
  EXPECT_EQ(m.ModeAt(Vec2(0.38, 0.25)), Mode::kSlipBelow);  // spring pulls back
  EXPECT_EQ(m.ModeAt(Vec2(-0.43, 0.25)), Mode::kSlipAbove);
  EXPECT_TRUE(m.InStickInterval(0.0));
  EXPECT_FALSE(m.InStickInterval(0.5));
  const Vec2 exit = m.ExitPoint();
  EXPECT_NEAR(exit[0], 0.375, 1e-15);
  EXPECT_EQ(exit[1], 0.25);
}

TEST(Model, ModeAfterArrival) {
  const Model m(Seed());
  auto after = [&](Mode from, double x) {
    return ModeAfterArrival(m, ModeSet(from), 0, Vec2(x, m.v()))[0];
  };
  EXPECT_EQ(after(Mode::kSlipBelow, 0.1), Mode::kStick);
  EXPECT_EQ(after(Mode::kSlipAbove, 0.1), Mode::kStick);
  EXPECT_EQ(after(Mode::kSlipBelow, -0.5), Mode::kSlipAbove);
  EXPECT_EQ(after(Mode::kSlipAbove, 0.5), Mode::kSlipBelow);
}

TEST(Model, ModeNames) {
  EXPECT_STREQ(Name(Mode::kSlipBelow), "slip-below");
  EXPECT_STREQ(Name(Mode::kStick), "stick");
  EXPECT_STREQ(Name(Mode::kSlipAbove), "slip-above");
}

TEST(Model, SaltationEnteringStick) {
  Mat2 expected;
  expected << 1, 0, 0, 0;
  ExpectMatNear(Model::SaltationStickIn(), expected, 0);
}

TEST(Model, SaltationLeavingStickIsIdentityWhenMuAtZeroIsMuS) {
  // cubic, stribeck, leine: mu(0+) = mu_s, the fields agree at the exit point.
  for (LawKind law : {LawKind::kCubic, LawKind::kStribeck, LawKind::kLeine}) {
    Params p = Seed();
    p.law = law;
    ExpectMatNear(Model(p).SaltationStickOut(), Mat2::Identity(), 1e-15);
  }
}

TEST(Model, SaltationLeavingStickCoulomb) {
  // I + (f_slip - f_stick) g^T / (g^T f_stick), g = (1, 0): f_slip - f_stick =
  // (0, mu_k - mu_s) at the exit point and g^T f_stick = v, so S(1, 0) =
  // (mu_k - mu_s) / v = -0.6.
  const Params p = Coulomb();
  Mat2 expected;
  expected << 1, 0, (p.mu_k - p.mu_s) / p.v, 1;
  ExpectMatNear(Model(p).SaltationStickOut(), expected, 1e-15);
  EXPECT_NEAR(expected(1, 0), -0.6, 1e-15);
}

TEST(Model, SaltationCrossingTheSurface) {
  // At x = -0.5 < -mu_s - 2 beta v an arrival from below crosses into slip above:
  // f_before = (v, 0.875), f_after = (v, 0.075); S = I + (f_after - f_before) n^T
  // / (n^T f_before) = diag(1, 0.075 / 0.875).
  const Model m(Seed());
  const Vec2 z(-0.5, 0.25), n(0, 1);
  auto crossing = [&](Mode before, Mode after, const Vec2& at) {
    Mat2 S;
    EXPECT_TRUE(Saltation(m, ModeSet(before), ModeSet(after), at, n, S));
    return S;
  };
  const Mat2 s = crossing(Mode::kSlipBelow, Mode::kSlipAbove, z);
  Mat2 expected;
  expected << 1, 0, 0, 0.075 / 0.875;
  ExpectMatNear(s, expected, 1e-14);
  // A saltation matrix maps the field before onto the field after.
  const Vec2 fb = m.Field(Mode::kSlipBelow, z);
  const Vec2 fa = m.Field(Mode::kSlipAbove, z);
  EXPECT_NEAR((s * fb - fa).norm(), 0, 1e-15);
  // And the other way across, at x = 0.5 from above.
  const Vec2 z2(0.5, 0.25);
  const Mat2 s2 = crossing(Mode::kSlipAbove, Mode::kSlipBelow, z2);
  EXPECT_NEAR((s2 * m.Field(Mode::kSlipAbove, z2) - m.Field(Mode::kSlipBelow, z2)).norm(), 0,
              1e-15);
}

TEST(Model, StickFieldMovesWithTheBelt) {
  const Model m(Seed());
  const Vec2 f = m.Field(Mode::kStick, Vec2(0.1, 0.25));
  EXPECT_EQ(f[0], 0.25);
  EXPECT_EQ(f[1], 0.0);
  // Slip below, seed eq. (3.7): x'' = -x - 2 beta x' + mu(v - x').
  const Vec2 z(0.1, 0.0);
  const double mu = 0.4 - 0.45 * 0.25 + 0.6 * 0.25 * 0.25 * 0.25;
  EXPECT_NEAR(m.Field(Mode::kSlipBelow, z)[1], -0.1 + mu, 1e-15);
}

// The stick set is closed: on x' = v, |x + 2 beta v| = mu_s still sticks
// (seed, definition of Omega), 2^-50 beyond does not. beta = 1/8, v = 1/4,
// mu_s = 1/2 make both ends, and the forces 2^-50 beyond, exact in binary:
// x = 7/16 and x = -9/16.
TEST(Model, StickSetBoundaryIsStick) {
  Params p;
  p.beta = 0.125;
  p.v = 0.25;
  p.mu_s = 0.5;
  const Model m(p);
  for (double edge : {0.4375, -0.5625}) {
    SCOPED_TRACE(edge);
    ASSERT_EQ(std::abs(m.StickForce(edge)), p.mu_s);  // exactly on the boundary
    EXPECT_TRUE(m.InStickInterval(edge));
    EXPECT_EQ(m.ModeAt(Vec2(edge, p.v)), Mode::kStick);
    const double out = edge + std::copysign(std::ldexp(1.0, -50), edge);
    ASSERT_EQ(std::abs(m.StickForce(out)), p.mu_s + std::ldexp(1.0, -50));
    EXPECT_FALSE(m.InStickInterval(out));
    EXPECT_NE(m.ModeAt(Vec2(out, p.v)), Mode::kStick);
  }
}

}  // namespace
}  // namespace stickslip
