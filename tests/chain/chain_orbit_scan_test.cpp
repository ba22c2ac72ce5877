// Every orbit of two identical seed blocks at one v (issue 32: the scan of
// an autonomous system, FindAutonomousOrbits). The synchronized orbit
// (x1 = x2) must be the belt's own orbit (FindPeriodicOrbits on the 1-DOF
// Model: period and x range); at kc = 0.5 the alternating one
// (x2(t) = x1(t + T/2)) is found too, at the period ss_continue gives
// (ss_continue --study chain2 --set kc=0.5); the synchronized orbit's transverse
// multiplier at kc = 0.2 is the one checked against Boost.Odeint in
// chain_floquet_test.cpp (docs/theory.md).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

#include "chain/chain.hpp"
#include "stickslip/errors.hpp"
#include "stickslip/orbits/orbit_scan.hpp"
#include "stickslip/orbits/orbit_search.hpp"
#include "stickslip/systems/belt/model.hpp"
#include "stickslip/systems/forced/forced.hpp"

namespace stickslip::chain {
namespace {

Params ScanBelt(double v) {  // studies/chain2.ini
  Params p;
  p.law = LawKind::kCubic;
  p.beta = 0.05, p.mu_s = 0.4, p.mu_m = 0.25, p.v_m = 0.5, p.v = v;
  return p;
}

// Over one period of o on a grid of 4000 steps: the largest |x1 - x2| and
// |x1' - x2'| (shift false), or |x2(t) - x1(t + T/2)| (shift true).
double ScanSpread(const System& s, const AutonomousOrbit& o, bool shift = false) {
  Flow flow(s, FlowOptions());
  FlowRequest rq;
  const int n = 4000;
  const double dt = o.orbit.period / n;
  rq.t_max = o.orbit.period;
  rq.output_dt = dt;
  std::map<long, Eigen::Vector4d> at;  // grid samples only, not the switches'
  rq.observer = [&](double t, const double* z, const ModeSet&) {
    const long j = std::lround(t / dt);
    if (std::abs(t - j * dt) < 1e-12) at[j] = Eigen::Vector4d(z[0], z[1], z[2], z[3]);
  };
  FlowRun run;
  flow.Run(o.orbit.start, rq, &run);
  EXPECT_GE(at.size(), static_cast<std::size_t>(n));
  double d = 0;
  for (const auto& [j, y] : at) {
    if (!shift) {
      d = std::max({d, std::abs(y[0] - y[2]), std::abs(y[1] - y[3])});
    } else if (at.count(j + n / 2)) {
      d = std::max(d, std::abs(y[2] - at.at(j + n / 2)[0]));
    }
  }
  return d;
}

const AutonomousOrbit* InStep(const System& s, const AutonomousOrbits& r) {
  for (const AutonomousOrbit& o : r.orbits)
    if (std::abs(o.orbit.start.z[0] - o.orbit.start.z[2]) < 1e-9 && ScanSpread(s, o) < 1e-9)
      return &o;
  return nullptr;
}

void PrintScan(const char* what, const AutonomousOrbits& r) {
  for (const AutonomousOrbit& o : r.orbits)
    std::printf(
        "[ measured ] %s: T = %.12g, sticks %d/%d, mu1 = %.12g%+.3gi, stable %d, start %d\n", what,
        o.orbit.period, o.sticks[0], o.sticks[1], o.orbit.multipliers[0].real(),
        o.orbit.multipliers[0].imag(), o.orbit.stable, o.start);
  std::printf("[ measured ] %s: %zu starts, %d shots, %d converged, %zu orbits\n", what,
              r.starts.size(), r.shots, r.converged, r.orbits.size());
}

TEST(ChainOrbitScan, FindsTheSynchronizedOrbitAsTheBeltsAndTheAlternatingOne) {
  const double v = 0.3;
  const PeriodicOrbits belt = FindPeriodicOrbits(Model(ScanBelt(v)), OrbitScanOptions());
  ASSERT_TRUE(belt.has_stick_slip);
  for (double kc : {0.2, 0.5}) {
    SCOPED_TRACE(kc);
    const Chain chain(Uniform(2, ScanBelt(v), kc));
    const AutonomousOrbits r = FindAutonomousOrbits(chain, AutonomousSearchOptions());
    PrintScan(kc == 0.2 ? "kc 0.2" : "kc 0.5", r);
    ASSERT_TRUE(r.ok()) << r.message;
    EXPECT_EQ(r.failed, 0);
    const AutonomousOrbit* sync = InStep(chain, r);
    ASSERT_NE(sync, nullptr);
    EXPECT_NEAR(sync->orbit.period, belt.stick_slip.period, 1e-9);
    EXPECT_NEAR(sync->orbit.lo[0], belt.stick_slip.extrema.x_min, 1e-9);
    EXPECT_NEAR(sync->orbit.hi[0], belt.stick_slip.extrema.x_max, 1e-9);
    EXPECT_EQ(sync->sticks, std::vector<int>({1, 1}));
    ASSERT_EQ(sync->orbit.multipliers.size(), 3u);
    // Transversally unstable at kc = 0.2, stable at 0.5 (docs/systems.md:
    // both attract at v = 0.3, kc = 0.5).
    EXPECT_EQ(sync->orbit.stable, kc == 0.5);
    // The alternating orbit's period: ss_continue's branch at v = 0.3
    // (kc 0.5: --study chain2 --set kc=0.5; kc 0.2: docs/figures/chain2/branch.tsv, 5.4337).
    const double period = kc == 0.5 ? 4.525710084704488 : 5.4337;
    const double tol = kc == 0.5 ? 1e-8 : 5e-5;
    int alternating = 0;
    for (const AutonomousOrbit& o : r.orbits) {
      if (&o == sync || std::abs(o.orbit.period - period) > tol) continue;
      EXPECT_LT(ScanSpread(chain, o, true), 1e-8);
      EXPECT_EQ(o.sticks, std::vector<int>({1, 1}));
      EXPECT_TRUE(o.orbit.stable);
      ++alternating;
    }
    EXPECT_EQ(alternating, 1);
  }
}

TEST(ChainOrbitScan, SynchronizedTransverseMultiplierMatchesTheIndependentIntegrator) {
  ShootingOptions so;  // chain_floquet_test.cpp's tolerances, v = 0.25
  so.flow.rtol = 1e-13, so.flow.atol = 1e-15;
  AutonomousSearchOptions o;
  o.orbit = so;
  const Chain chain(Uniform(2, Params(), 0.2));
  const AutonomousOrbits r = FindAutonomousOrbits(chain, o);
  PrintScan("seed kc 0.2", r);
  const AutonomousOrbit* sync = InStep(chain, r);
  ASSERT_NE(sync, nullptr);
  EXPECT_NEAR(sync->orbit.multipliers[0].real(), 1.3874006783677, 1e-9);  // Odeint, extrapolated
  EXPECT_NEAR(sync->orbit.multipliers[0].imag(), 0.0, 1e-12);
  EXPECT_FALSE(sync->orbit.stable);
}

TEST(ChainOrbitScan, BadOptionsThrowAndCancellingKeepsTheOrbitsSoFar) {
  const Chain chain(Uniform(2, ScanBelt(0.3), 0.5));
  const auto throws = [&](auto change) {
    AutonomousSearchOptions o;
    change(o);
    EXPECT_THROW(FindAutonomousOrbits(chain, o), InvalidArgument);
  };
  throws([](AutonomousSearchOptions& o) { o.amplitudes = {0.1, 0}; });
  throws([](AutonomousSearchOptions& o) { o.amplitudes.assign(17, 0.1); });
  throws([](AutonomousSearchOptions& o) { o.transient = -1; });
  throws([](AutonomousSearchOptions& o) { o.transient = INFINITY; });
  throws([](AutonomousSearchOptions& o) { o.scale = NAN; });
  throws([](AutonomousSearchOptions& o) { o.max_returns = 0; });
  throws([](AutonomousSearchOptions& o) { o.starts = {Eigen::VectorXd::Zero(3)}; });
  throws([](AutonomousSearchOptions& o) { o.starts = {Eigen::Vector4d(0, NAN, 0, 0)}; });
  EXPECT_THROW(FindAutonomousOrbits(ForcedBelt(ForcedBeltParams()), AutonomousSearchOptions()),
               InvalidArgument);
  AutonomousSearchOptions o;
  o.amplitudes = {0.3};
  long polls = 0;  // by the scan between runs and shots, and by the flow within
  o.cancelled = [&] { return ++polls < 0; };
  const AutonomousOrbits all = FindAutonomousOrbits(chain, o);
  ASSERT_TRUE(all.ok());
  const long total = polls;
  polls = 0;
  o.cancelled = [&] { return ++polls > total / 2; };  // half way through
  const AutonomousOrbits r = FindAutonomousOrbits(chain, o);
  std::printf("[ measured ] %ld polls; cancelled half way: %d of %d shots, %zu of %zu orbits\n",
              total, r.shots, all.shots, r.orbits.size(), all.orbits.size());
  EXPECT_EQ(r.status, OrbitScanStatus::kCancelled);
  EXPECT_FALSE(r.ok());
  EXPECT_LT(r.shots, all.shots);
  EXPECT_GE(r.orbits.size(), 1u);
  for (const AutonomousOrbit& f : r.orbits) {
    EXPECT_TRUE(f.orbit.ok());
    EXPECT_TRUE(std::any_of(all.orbits.begin(), all.orbits.end(), [&](const AutonomousOrbit& a) {
      return std::abs(a.orbit.period - f.orbit.period) < 1e-9;
    }));
  }
  o.cancelled = [] { return true; };
  const AutonomousOrbits none = FindAutonomousOrbits(chain, o);
  EXPECT_EQ(none.status, OrbitScanStatus::kCancelled);
  EXPECT_TRUE(none.orbits.empty());
  EXPECT_EQ(none.shots, 0);
}

}  // namespace
}  // namespace stickslip::chain
