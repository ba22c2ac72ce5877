// Periodic orbits of the forced oscillator (issue 20, item 2): Den Hartog's
// non-stop solution, multipliers against closed-form differences, and
// periodicity checked by the closed-form simulation.
#include "stickslip/orbits/forced_orbit.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>

#include "forced_reference.hpp"

namespace stickslip {
namespace {

namespace ref = forced_reference;
using ref::Real;

const Real kPi = std::acos(Real(-1));

// Den Hartog (1931): X = sqrt(V^2 - (mu U)^2), V = A / (1 - Omega^2),
// U = sin(pi / Omega) / (Omega (1 + cos(pi / Omega))).
Real DenHartogX(Real mu, Real a, Real w) {
  const Real V = a / (1 - w * w), U = std::sin(kPi / w) / (w * (1 + std::cos(kPi / w)));
  return std::sqrt(V * V - mu * mu * U * U);
}

// The same amplitude from the closed-form pieces, not from the formula: a
// half period with x' < 0 from (t0, X, 0) to (t0 + pi / Omega, -X, 0) solves
// x'' + x = mu + A cos(Omega t), x = mu + C1 cos t + C2 sin t + V cos(Omega t).
// Given t0, x(t0) = X, x'(t0) = 0, x(t1) = -X are linear in (C1, C2, X); the
// last condition x'(t1) = 0 is bracketed in t0 and bisected.
Real DenHartogFromPieces(Real mu, Real a, Real w) {
  const Real V = a / (1 - w * w);
  auto solve = [&](Real t0, Real* c) {  // Cramer on rows (C1, C2, -X | rhs)
    const Real t1 = t0 + kPi / w;
    const Real m[3][4] = {{std::cos(t0), std::sin(t0), -1, -mu - V * std::cos(w * t0)},
                          {-std::sin(t0), std::cos(t0), 0, V * w * std::sin(w * t0)},
                          {std::cos(t1), std::sin(t1), 1, -mu - V * std::cos(w * t1)}};
    auto det = [&](int col) {
      Real a3[3][3];
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) a3[i][j] = j == col ? m[i][3] : m[i][j];
      return a3[0][0] * (a3[1][1] * a3[2][2] - a3[1][2] * a3[2][1]) -
             a3[0][1] * (a3[1][0] * a3[2][2] - a3[1][2] * a3[2][0]) +
             a3[0][2] * (a3[1][0] * a3[2][1] - a3[1][1] * a3[2][0]);
    };
    const Real d = det(-1);
    for (int j = 0; j < 3; ++j) c[j] = det(j) / d;
    return -c[0] * std::sin(t1) + c[1] * std::cos(t1) - V * w * std::sin(w * t1);  // x'(t1)
  };
  // x' < 0 inside the half period: sampled.
  auto down = [&](Real t0, const Real* c) {
    for (int i = 1; i < 64; ++i) {
      const Real t = t0 + i * kPi / w / 64;
      if (-c[0] * std::sin(t) + c[1] * std::cos(t) - V * w * std::sin(w * t) >= 0) return false;
    }
    return true;
  };
  const int n = 4000;
  const Real T = 2 * kPi / w;
  Real c[3];
  for (int i = 0; i < n; ++i) {
    Real lo = i * T / n, hi = (i + 1) * T / n;
    const Real flo = solve(lo, c), fhi = solve(hi, c);
    if ((flo > 0) == (fhi > 0)) continue;
    for (int it = 0; it < 200; ++it) {
      const Real mid = (lo + hi) / 2;
      ((solve(mid, c) > 0) == (flo > 0) ? lo : hi) = mid;
    }
    solve(lo, c);
    if (c[2] > 0 && down(lo, c)) return c[2];
  }
  return -1;
}

ForcedBeltParams DenHartog(double w) {
  ForcedBeltParams p;
  p.base.law = LawKind::kCoulomb;
  p.base.mu_s = p.base.mu_k = 0.3;
  p.base.beta = 0, p.base.v = 0;
  p.force = 1, p.omega = w;
  return p;
}

const double kOmegas[] = {0.75, 0.8, 0.9, 0.95, 1.05, 1.1, 1.3, 1.5, 1.75, 2, 2.25, 2.5};

// Checks the formula itself first (design.md: test, do not trust).
TEST(ForcedOrbit, DenHartogFormulaSolvesTheClosedFormPieces) {
  for (double w : kOmegas) {
    const Real pieces = DenHartogFromPieces(0.3L, 1, w);
    ASSERT_GT(pieces, 0) << "Omega = " << w;
    EXPECT_NEAR(static_cast<double>(pieces), static_cast<double>(DenHartogX(0.3L, 1, w)),
                1e-14 * static_cast<double>(pieces))
        << "Omega = " << w;
  }
}

TEST(ForcedOrbit, NonStopOrbitsMatchDenHartog) {
  ShootingOptions o(ForcedBelt::FlowDefaults());
  o.flow.rtol = o.flow.atol = 1e-14;
  double worst = 0;
  for (double w : kOmegas) {
    const ForcedBelt m(DenHartog(w));
    const double V = 1 / (1 - w * w);
    const PeriodicOrbit orbit = ShootStroboscopic(m, V, 0.01, 1, o);
    ASSERT_TRUE(orbit.ok()) << "Omega = " << w << ": " << orbit.message;
    ASSERT_EQ(orbit.sticks, 0) << "Omega = " << w;
    EXPECT_EQ(orbit.crossings, 2) << "Omega = " << w;
    const double X = static_cast<double>(DenHartogX(0.3L, 1, w));
    EXPECT_NEAR(OrbitExtrema(orbit).x_max, X, 1e-9) << "Omega = " << w;
    EXPECT_NEAR(-OrbitExtrema(orbit).x_min, X, 1e-9) << "Omega = " << w;
    worst = std::max(
        {worst, std::abs(OrbitExtrema(orbit).x_max - X), std::abs(OrbitExtrema(orbit).x_min + X)});
  }
  std::printf("[ measured ] Den Hartog x_max, x_min: max error %.2e over %zu Omegas\n", worst,
              std::size(kOmegas));
}

// The closed-form simulation (long double) from z over the period: its end.
Vec2 ClosedFormMap(const ForcedBeltParams& p, Real x, Real y, Real t_end) {
  ref::PieceSim<ref::CoulombPiece> sim(
      ref::Setup{reference::Law(p.base), p.base.beta, p.base.v, p.force, p.omega});
  Real t = 0;
  sim.Run(t, x, y, t_end);
  return Vec2(static_cast<double>(x), static_cast<double>(y));
}

// A fixed point is one for the closed-form map too, and its multipliers are
// those of the closed-form map's central differences.
void CheckAgainstClosedForm(const ForcedBeltParams& p, double x0, double xdot0, int m) {
  ShootingOptions o(ForcedBelt::FlowDefaults());
  o.flow.rtol = o.flow.atol = 1e-14;
  const ForcedBelt model(p);
  const PeriodicOrbit orbit = ShootStroboscopic(model, x0, xdot0, m, o);
  ASSERT_TRUE(orbit.ok()) << orbit.message;
  const Vec2 end = ClosedFormMap(p, orbit.start.z[0], orbit.start.z[1], orbit.period);
  EXPECT_NEAR(end[0], orbit.start.z[0], 1e-11);
  EXPECT_NEAR(end[1], orbit.start.z[1], 1e-11);
  const Real d = 1e-6L;
  Mat2 fd;
  for (int col = 0; col < 2; ++col) {
    if (col == 1 && orbit.start.mode[0] == Mode::kStick) {  // no x' direction in stick
      fd.col(1).setZero();
      continue;
    }
    const Real dx = col == 0 ? d : 0, dy = col == 1 ? d : 0;
    const Vec2 plus = ClosedFormMap(p, orbit.start.z[0] + dx, orbit.start.z[1] + dy, orbit.period);
    const Vec2 minus = ClosedFormMap(p, orbit.start.z[0] - dx, orbit.start.z[1] - dy, orbit.period);
    fd.col(col) = (plus - minus) / static_cast<double>(2 * d);
  }
  std::complex<double> ref_mult[2];
  Multipliers(fd, ref_mult);
  for (int i = 0; i < 2; ++i)
    EXPECT_LT(std::abs(orbit.multipliers[i] - ref_mult[i]), 1e-7)
        << "multiplier " << i << ": " << orbit.multipliers[i] << " vs " << ref_mult[i];
  std::printf(
      "[ measured ] m = %d, %d sticks, %d crossings: multipliers %.10g%+.10gi, "
      "%.10g%+.10gi (differences %.10g, %.10g)\n",
      m, orbit.sticks, orbit.crossings, orbit.multipliers[0].real(), orbit.multipliers[0].imag(),
      orbit.multipliers[1].real(), orbit.multipliers[1].imag(), ref_mult[0].real(),
      ref_mult[1].real());
}

TEST(ForcedOrbit, DampedNonStopOrbitIsAFixedPointOfTheClosedForm) {
  ForcedBeltParams p = DenHartog(1.3);
  p.base.beta = 0.05, p.base.mu_s = 0.35;
  CheckAgainstClosedForm(p, -1.4, 0.0, 1);
}

TEST(ForcedOrbit, FloorStickSlipOrbitIsAFixedPointOfTheClosedForm) {
  ForcedBeltParams p = DenHartog(0.6);
  p.base.beta = 0.05, p.base.mu_s = 0.4, p.force = 0.7;
  CheckAgainstClosedForm(p, 0.5, 0.0, 1);
}

TEST(ForcedOrbit, BeltStickSlipOrbitIsAFixedPointOfTheClosedForm) {
  ForcedBeltParams p = DenHartog(0.8);
  p.base.beta = 0.05, p.base.mu_s = 0.4, p.base.mu_k = 0.25, p.base.v = 0.2, p.force = 0.3;
  CheckAgainstClosedForm(p, 0.3, 0.2, 1);
}

// A shooting per thread is kept between calls with equal options: one with
// switching off after one with it on must not reuse it. Off, the start's
// slip-above field x'' + 2 beta x' + x = -mu_k + A cos(Omega t) goes on across
// x' = 0; its periodic solution is x = -mu_k + Re(A e^{i Omega t} / D),
// D = 1 - Omega^2 + 2 i beta Omega, with x'(0) > 0 (slip-above at the start).
TEST(ForcedOrbit, SwitchingOffIsNotAnsweredByTheCachedSwitchingShooting) {
  ForcedBeltParams p = DenHartog(1.3);
  p.base.beta = 0.05;
  const ForcedBelt m(p);
  ShootingOptions o(ForcedBelt::FlowDefaults());
  o.flow.rtol = o.flow.atol = 1e-13;
  const PeriodicOrbit on = ShootStroboscopic(m, -1.4, 0.3, 1, o);
  ASSERT_TRUE(on.ok()) << on.message;
  EXPECT_EQ(on.crossings, 2);
  o.switching = false;
  const PeriodicOrbit off = ShootStroboscopic(m, -1.4, 0.3, 1, o);
  ASSERT_TRUE(off.ok()) << off.message;
  const std::complex<double> a =
      p.force / std::complex<double>(1 - p.omega * p.omega, 2 * p.base.beta * p.omega);
  const double x0 = -p.base.mu_k + a.real(), xdot0 = (std::complex<double>(0, p.omega) * a).real();
  ASSERT_GT(xdot0, 0);
  EXPECT_EQ(off.crossings, 0);
  EXPECT_NEAR(off.start.z[0], x0, 1e-10);
  EXPECT_NEAR(off.start.z[1], xdot0, 1e-10);
}

}  // namespace
}  // namespace stickslip
