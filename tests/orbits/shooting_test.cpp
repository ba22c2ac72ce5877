// One shooting on three sections (shooting.hpp): the belt's stick exit and
// its x' = 0 section against the long-double reference integrator, the
// forced oscillator's stroboscopic map against Den Hartog (1931) and the
// coulomb closed form, and one forced orbit through two sections with the
// same multipliers (they do not depend on the section).
#include "stickslip/orbits/shooting.hpp"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "forced_reference.hpp"
#include "reference/reference_orbit.hpp"
#include "stickslip/errors.hpp"
#include "stickslip/flow/switching.hpp"
#include "stickslip/orbits/settle.hpp"
#include "stickslip/systems/belt/model.hpp"
#include "stickslip/systems/forced/forced.hpp"

namespace stickslip {
namespace {

ShootingOptions TightShooting() {
  ShootingOptions o;
  o.flow.rtol = 1e-14;
  o.flow.atol = 1e-14;
  return o;
}

Params SeedShooting(double v) {
  Params p;
  p.v = v;
  return p;
}

FlowPoint At(const Eigen::VectorXd& z, Mode mode, double t = 0) { return {t, z, ModeSet(mode)}; }

// The belt's stick-slip orbit (seed case 1) from its exit point, and from a
// point off it: the exit set is a point, so DP = 0 and one step lands there.
TEST(Shooting, BeltStickExitMatchesTheReference) {
  for (double v : {0.05, 0.25, 0.39}) {
    const Model m(SeedShooting(v));
    Shooting shooting(m, TightShooting());
    const reference::StickSlipOrbit ref = reference::StickSlip(SeedShooting(v));
    ASSERT_TRUE(ref.found);
    for (double off : {0.0, 0.1}) {
      const Eigen::Vector2d exit(m.ExitPoint()[0] + off, v);
      const PeriodicOrbit o =
          shooting.Find(At(exit, Mode::kSlipBelow), PoincareSection::StickExit(0));
      ASSERT_TRUE(o.ok()) << "v = " << v << ": " << o.message;
      EXPECT_EQ(o.iterations, off == 0 ? 1 : 2) << "v = " << v;
      EXPECT_NEAR(o.period, static_cast<double>(ref.period), 1e-9) << "v = " << v;
      EXPECT_NEAR(o.hi[0], static_cast<double>(ref.x_max), 1e-9) << "v = " << v;
      EXPECT_NEAR(o.lo[0], static_cast<double>(ref.x_min), 1e-9) << "v = " << v;
      EXPECT_NEAR(o.lo[1], static_cast<double>(ref.xdot_min), 1e-9) << "v = " << v;
      ASSERT_EQ(o.multipliers.size(), 1u);
      EXPECT_LT(std::abs(o.multipliers[0]), 1e-9) << "v = " << v;  // superstable
      EXPECT_TRUE(o.stable);
      EXPECT_EQ(o.sticks, 1);
    }
  }
}

// Pure slip on x' = 0 falling: the reference's fixed point and the trace
// formula's multiplier exp(oint(-2 beta + F'(x' - v)) dt).
TEST(Shooting, BeltPureSlipOnASurfaceMatchesTheReference) {
  for (double v : {0.40, 0.42, 0.44}) {
    const Model m(SeedShooting(v));
    Shooting shooting(m, TightShooting());
    PoincareSection s;
    s.kind = SectionKind::kSurface;
    s.surface.g.terms[0] = {1, 1.0};
    s.surface.g.size = 1;
    s.surface.direction = -1;
    const double xbar = m.SteadySliding().x;
    const PeriodicOrbit o = shooting.Find(At(Eigen::Vector2d(xbar + 0.3, 0), Mode::kSlipBelow), s);
    ASSERT_TRUE(o.ok()) << "v = " << v << ": " << o.message;
    const reference::PureSlipOrbit ref =
        reference::PureSlip(SeedShooting(v), static_cast<long double>(o.start.z[0]));
    ASSERT_TRUE(ref.found);
    EXPECT_NEAR(o.start.z[0], static_cast<double>(ref.x_section), 1e-10) << "v = " << v;
    EXPECT_NEAR(o.period, static_cast<double>(ref.period), 1e-9) << "v = " << v;
    ASSERT_EQ(o.multipliers.size(), 1u);
    EXPECT_NEAR(o.multipliers[0].real(), static_cast<double>(ref.multiplier), 1e-8) << "v = " << v;
    EXPECT_TRUE(o.stable);
  }
}

namespace ref = forced_reference;
using ref::Real;

ForcedBeltParams Floor(double w) {
  ForcedBeltParams p;
  p.base.law = LawKind::kCoulomb;
  p.base.mu_s = p.base.mu_k = 0.3;
  p.base.beta = 0, p.base.v = 0;
  p.force = 1, p.omega = w;
  return p;
}

// Den Hartog's non-stop amplitude X = sqrt(V^2 - (mu U)^2), V = A / (1 -
// Omega^2), U = sin(pi / Omega) / (Omega (1 + cos(pi / Omega))), checked
// against its closed-form pieces in tests/forced/forced_orbit_test.cpp.
TEST(Shooting, StroboscopicMapFindsDenHartogsNonStopOrbits) {
  for (double w : {0.75, 0.9, 1.3, 2.0}) {
    const ForcedBelt m(Floor(w));
    Shooting shooting(m, TightShooting());
    const Eigen::Vector3d z(1 / (1 - w * w), 0.01, 0);
    const PeriodicOrbit o =
        shooting.Find(At(z, Mode::kSlipBelow), PoincareSection::Stroboscopic(m, z, 1));
    ASSERT_TRUE(o.ok()) << "Omega = " << w << ": " << o.message;
    const double V = 1 / (1 - w * w), U = std::sin(M_PI / w) / (w * (1 + std::cos(M_PI / w)));
    const double X = std::sqrt(V * V - 0.09 * U * U);
    EXPECT_NEAR(o.hi[0], X, 1e-9) << "Omega = " << w;
    EXPECT_NEAR(o.lo[0], -X, 1e-9) << "Omega = " << w;
    EXPECT_EQ(o.sticks, 0);
    EXPECT_EQ(o.crossings, 2);
    EXPECT_NEAR(o.period, 2 * M_PI / w, 1e-15 * o.period);
    EXPECT_EQ(o.multipliers.size(), 2u);
    // From the orbit itself Newton converges at once, on an evaluation that
    // held its extremes back: it is run again for them.
    const PeriodicOrbit again = shooting.Find(o.start, PoincareSection::Stroboscopic(m, z, 1));
    ASSERT_TRUE(again.ok()) << again.message;
    EXPECT_EQ(again.iterations, 1);
    ASSERT_EQ(again.hi.size(), 2);
    EXPECT_NEAR(again.hi[0], X, 1e-9) << "Omega = " << w;
    EXPECT_NEAR(again.lo[0], -X, 1e-9) << "Omega = " << w;
    EXPECT_EQ(again.crossings, 2);
    // Its re-run seeks them on the steps of one evaluation at its start.
    Eigen::VectorXd r;
    PeriodicOrbit mapped;
    ASSERT_TRUE(
        shooting.Map(again.start, PoincareSection::Stroboscopic(m, z, 1), true, &r, &mapped));
    EXPECT_EQ(mapped.lo, again.lo);
    EXPECT_EQ(mapped.hi, again.hi);
    EXPECT_EQ(mapped.period, again.period);
  }
}

// The closed-form map over t_end from (t0, x, y): its end.
Eigen::Vector2d ClosedFormMap(const ForcedBeltParams& p, Real t0, Real x, Real y, Real t_end) {
  ref::PieceSim<ref::CoulombPiece> sim(
      ref::Setup{reference::Law(p.base), p.base.beta, p.base.v, p.force, p.omega});
  sim.Run(t0, x, y, t_end);
  return Eigen::Vector2d(static_cast<double>(x), static_cast<double>(y));
}

// A forced stick-slip orbit on the belt by the stroboscopic map, then by its
// stick exit: a fixed point of the coulomb closed form, one period, and the
// same multipliers from both sections' Jacobians (the stick exit's carries
// the clock's column from the flow identity).
TEST(Shooting, ForcedOrbitThroughTwoSectionsHasOneSetOfMultipliers) {
  ForcedBeltParams p = Floor(0.8);
  p.base.beta = 0.05, p.base.mu_s = 0.4, p.base.mu_k = 0.25, p.base.v = 0.2, p.force = 0.3;
  const ForcedBelt m(p);
  Shooting shooting(m, TightShooting());
  const Eigen::Vector3d z0(0.3, 0.2, 0);
  const PeriodicOrbit strobe =
      shooting.Find(At(z0, Mode::kSlipBelow), PoincareSection::Stroboscopic(m, z0, 1));
  ASSERT_TRUE(strobe.ok()) << strobe.message;
  ASSERT_EQ(strobe.sticks, 1);
  const Eigen::Vector2d back =
      ClosedFormMap(p, 0, strobe.start.z[0], strobe.start.z[1], strobe.period);
  EXPECT_NEAR(back[0], strobe.start.z[0], 1e-11);
  EXPECT_NEAR(back[1], strobe.start.z[1], 1e-11);
  // Its stick exit, a little off, starts the second shooting.
  std::vector<FlowSwitch> switches;
  FlowRequest rq;
  rq.t_max = strobe.period;
  rq.switches = &switches;
  shooting.flow().Run(strobe.start, rq);
  const FlowSwitch* exit = nullptr;
  for (const FlowSwitch& s : switches)
    if (s.kind == SwitchKind::kStickOut) exit = &s;
  ASSERT_NE(exit, nullptr);
  Eigen::Vector3d e = exit->z;
  e[2] += 1e-3;
  const PeriodicOrbit o = shooting.Find(At(e, exit->after[0]), PoincareSection::StickExit(0, 1, 1));
  ASSERT_TRUE(o.ok()) << o.message;
  EXPECT_GT(o.iterations, 1);
  EXPECT_NEAR(o.period, strobe.period, 1e-11);
  EXPECT_NEAR(o.start.z[0], exit->z[0], 1e-10);
  EXPECT_NEAR(std::remainder(o.start.z[2] - exit->z[2], 2 * M_PI), 0, 1e-10);
  ASSERT_EQ(o.multipliers.size(), 2u);
  for (int i = 0; i < 2; ++i)
    EXPECT_LT(std::abs(o.multipliers[i] - strobe.multipliers[i]), 1e-9)
        << i << ": " << o.multipliers[i] << " vs " << strobe.multipliers[i];
  EXPECT_EQ(o.stable, strobe.stable);
  // The exit section's multipliers by deflation are the monodromy's whole
  // spectrum by Eigen's QR algorithm, less the flow direction's 0.
  const Eigen::VectorXcd all = Eigen::EigenSolver<Eigen::MatrixXd>(o.monodromy).eigenvalues();
  std::vector<std::complex<double>> qr(all.data(), all.data() + all.size());
  std::sort(qr.begin(), qr.end(), [](auto a, auto b) { return std::abs(a) > std::abs(b); });
  for (int i = 0; i < 2; ++i)
    EXPECT_LT(std::abs(o.multipliers[i] - qr[i]), 1e-13 * (1 + std::abs(qr[i])))
        << i << ": " << o.multipliers[i] << " vs " << qr[i];
  EXPECT_LT(std::abs(qr[2]), 1e-13);
  std::printf("[ measured ] multipliers: stroboscopic %.12g, %.3g; stick exit %.12g, %.3g\n",
              std::abs(strobe.multipliers[0]), std::abs(strobe.multipliers[1]),
              std::abs(o.multipliers[0]), std::abs(o.multipliers[1]));
}

// A system with a clock settles on its stroboscopic map (settle.hpp): from
// rest, the forced Coulomb belt above reaches a periodic attractor whose
// point the coulomb closed form maps onto itself over its m periods.
TEST(Shooting, AClockedSystemSettlesOnItsStroboscopicMap) {
  ForcedBeltParams p = Floor(0.8);
  p.base.beta = 0.05, p.base.mu_s = 0.4, p.base.mu_k = 0.25, p.base.v = 0.2, p.force = 0.3;
  const ForcedBelt m(p);
  SettleOptions o;
  o.shooting = TightShooting();
  const SettledOrbit st = SettleOnStickSlip(m, Eigen::Vector3d(0, 0, 0), o);
  ASSERT_TRUE(st.found) << st.message;
  EXPECT_EQ(st.section.kind, SectionKind::kTime);
  ASSERT_GE(st.section.turns, 1);
  EXPECT_NEAR(st.orbit.period, st.section.turns * 2 * M_PI / 0.8, 1e-12);
  EXPECT_EQ(st.orbit.start.z[2], 0);  // at theta = 0
  EXPECT_TRUE(st.orbit.stable);
  const Eigen::Vector2d back =
      ClosedFormMap(p, 0, st.orbit.start.z[0], st.orbit.start.z[1], st.orbit.period);
  EXPECT_NEAR(back[0], st.orbit.start.z[0], 1e-11);
  EXPECT_NEAR(back[1], st.orbit.start.z[1], 1e-11);
  EXPECT_THROW(SettleOnStickSlip(m, Eigen::Vector2d(0, 0), o), InvalidArgument);
}

TEST(Shooting, MisuseThrowsAndAMissingReturnIsAStatus) {
  const Model m(SeedShooting(0.2));
  ShootingOptions opt = TightShooting();
  opt.max_return_time = 1;  // far less than one period
  Shooting shooting(m, opt);
  const FlowPoint z = At(Eigen::Vector2d(m.ExitPoint()[0], 0.2), Mode::kSlipBelow);
  EXPECT_THROW(shooting.Find(z, PoincareSection::StickExit(1)), InvalidArgument);
  EXPECT_THROW(shooting.Find(z, PoincareSection::StickExit(0, 0)), InvalidArgument);
  EXPECT_THROW(
      shooting.Find(At(Eigen::Vector3d::Zero(), Mode::kSlipBelow), PoincareSection::StickExit(0)),
      InvalidArgument);
  EXPECT_THROW(PoincareSection::Stroboscopic(m, z.z, 1), InvalidArgument);  // no clock
  const PeriodicOrbit o = shooting.Find(z, PoincareSection::StickExit(0));
  EXPECT_EQ(o.status, OrbitStatus::kNoReturn);
  EXPECT_NE(o.message.find("stick-exit"), std::string::npos) << o.message;
  ShootingOptions bad;
  bad.tol = 0;
  EXPECT_THROW(Shooting(m, bad), InvalidArgument);
}

// A map without switching (a grazing curve's gap margin) from a state that
// sticks: Den Hartog's block at rest on the floor (x' = v = 0) with the
// spring balancing the force at theta = 0 (x = A), where Filippov's rule
// sticks. It has no slip field to follow: a status, not an exception (it
// escaped ss_chart once, from a Newton iterate on the surface). With
// switching the same start is an ordinary one.
TEST(Shooting, AStickingStartWithoutSwitchingIsAStatus) {
  const ForcedBelt m(Floor(1.75));
  const Eigen::Vector3d z(1.0, 0.0, 0.0);
  ASSERT_TRUE(ModeOf(m, z).sticks(0));
  const PoincareSection strobe = PoincareSection::Stroboscopic(m, z, 1);
  ShootingOptions opt = TightShooting();
  opt.switching = false;
  Shooting gap(m, opt);
  const PeriodicOrbit o = gap.Find(At(z, Mode::kSlipBelow), strobe);
  EXPECT_EQ(o.status, OrbitStatus::kSticks);
  EXPECT_NE(o.message.find("without switching"), std::string::npos) << o.message;
  Eigen::VectorXd r;
  PeriodicOrbit mapped;
  EXPECT_FALSE(gap.Map(At(z, Mode::kSlipBelow), strobe, true, &r, &mapped));
  EXPECT_EQ(mapped.status, OrbitStatus::kSticks);
  opt.switching = true;
  Shooting switching(m, opt);
  EXPECT_TRUE(switching.Map(At(z, Mode::kSlipBelow), strobe, true, &r, &mapped)) << mapped.message;
  ASSERT_FALSE(mapped.modes.empty());
  EXPECT_TRUE(mapped.modes[0].sticks(0));  // the run starts in stick and leaves it
  EXPECT_GT(mapped.exits, 0);
}

}  // namespace
}  // namespace stickslip
