// The batched stroboscopic orbits of a System (the forced oscillator): each
// row against the closed-form coulomb map (long double, no library code), Den
// Hartog's non-stop amplitude, the single-orbit API from the row's point,
// thread counts, failure rows, cancellation and bad columns.
#include "stickslip/orbits/system_batch.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "forced_reference.hpp"
#include "stickslip/errors.hpp"
#include "stickslip/orbits/forced_orbit.hpp"
#include "stickslip/systems/forced/forced.hpp"

namespace stickslip {
namespace {

namespace ref = forced_reference;
using ref::Real;

// The coulomb belt of forced_orbit_test's closed-form scenes: mu_k 0.25,
// beta 0.05, v 0.2, A 0.3.
ForcedBeltParams Belt() { return ref::Coulomb(0.4, 0.25, 0.05, 0.2, 0.3, 0.8); }

// Omega over [0.6, 1.2] by mu_s over [0.3, 0.5], Omega slowest.
std::vector<SystemColumn> BatchGrid(int nw, int nmu) {
  SystemColumn w{ForcedBelt::kOmegaIndex, {}}, mu{static_cast<int>(Parameter::kMuS), {}};
  for (int i = 0; i < nw; ++i)
    for (int j = 0; j < nmu; ++j) {
      w.values.push_back(0.6 + 0.6 * i / (nw - 1));
      mu.values.push_back(0.3 + 0.2 * j / (nmu - 1));
    }
  return {w, mu};
}

SystemBatchOptions BatchOptions(int threads) {
  SystemBatchOptions o;
  o.threads = threads;
  o.start = Eigen::Vector3d(0.3, 0.2, 0);
  o.shooting.flow.rtol = o.shooting.flow.atol = 1e-13;
  return o;
}

ForcedBeltParams RowParams(const ForcedBeltParams& base, const std::vector<SystemColumn>& cols,
                           std::size_t i) {
  ForcedBelt m(base);
  for (const SystemColumn& c : cols) m.SetParameterValue(c.parameter, c.values[i]);
  return m.params();
}

// The closed-form map over t_end from (x, y) at t = 0.
Vec2 ClosedFormMap(const ForcedBeltParams& p, Real x, Real y, Real t_end) {
  ref::PieceSim<ref::CoulombPiece> sim(
      ref::Setup{reference::Law(p.base), p.base.beta, p.base.v, p.force, p.omega});
  Real t = 0;
  sim.Run(t, x, y, t_end);
  return Vec2(static_cast<double>(x), static_cast<double>(y));
}

TEST(SystemBatch, ForcedRowsAreFixedPointsOfTheClosedFormMap) {
  const ForcedBeltParams base = Belt();
  const auto cols = BatchGrid(7, 5);
  const SystemBatch b = StroboscopicOrbits(ForcedBelt(base), cols, BatchOptions(2));
  ASSERT_EQ(b.rows(), 35u);
  ASSERT_EQ(b.tangent, 2);
  EXPECT_TRUE(b.error.empty()) << b.error;
  double worst = 0;
  int with_sticks = 0, multiples = 0;
  for (std::size_t i = 0; i < b.rows(); ++i) {
    if (b.status[i] != OrbitStatus::kOk) continue;
    const ForcedBeltParams p = RowParams(base, cols, i);
    const double x0 = b.start[2 * i], y0 = b.start[2 * i + 1];
    EXPECT_NEAR(b.period[i], b.m[i] * 2 * M_PI / p.omega, 1e-13 * b.period[i]);
    const Vec2 end = ClosedFormMap(p, x0, y0, b.period[i]);
    worst = std::max({worst, std::abs(end[0] - x0), std::abs(end[1] - y0)});
    EXPECT_NEAR(end[0], x0, 1e-10) << "row " << i;
    EXPECT_NEAR(end[1], y0, 1e-10) << "row " << i;
    // A stable orbit: the batch settles onto attractors.
    EXPECT_EQ(b.stable[i], 1) << "row " << i;
    EXPECT_LT(b.multiplier[i], 1) << "row " << i;
    EXPECT_LE(b.lo[2 * i], x0);
    EXPECT_GE(b.hi[2 * i], x0);
    with_sticks += b.sticks[i] > 0;
    multiples += b.m[i] > 1;
  }
  EXPECT_GE(b.found(), 30u);
  EXPECT_GT(with_sticks, 20);
  std::printf(
      "[ measured ] %zu of %zu rows, %d with sticks, %d with m > 1; closed-form map "
      "residual %.2e\n",
      b.found(), b.rows(), with_sticks, multiples, worst);
}

// Every row equals the single-orbit API (ShootStroboscopic, the forced
// adapter) started from the row's point with the row's m.
TEST(SystemBatch, ForcedRowsEqualTheSingleOrbitApi) {
  const ForcedBeltParams base = Belt();
  const auto cols = BatchGrid(5, 4);
  const SystemBatchOptions opt = BatchOptions(1);
  const SystemBatch b = StroboscopicOrbits(ForcedBelt(base), cols, opt);
  ShootingOptions fo(ForcedBelt::FlowDefaults());
  fo.flow.rtol = fo.flow.atol = 1e-13;
  for (std::size_t i = 0; i < b.rows(); ++i) {
    if (b.status[i] != OrbitStatus::kOk) continue;
    const ForcedBelt model(RowParams(base, cols, i));
    const PeriodicOrbit o =
        ShootStroboscopic(model, b.start[2 * i], b.start[2 * i + 1], b.m[i], fo);
    ASSERT_TRUE(o.ok()) << "row " << i << ": " << o.message;
    EXPECT_EQ(o.sticks, b.sticks[i]) << "row " << i;
    EXPECT_EQ(o.stable, b.stable[i] == 1) << "row " << i;
    EXPECT_NEAR(o.start.z[0], b.start[2 * i], 1e-12) << "row " << i;
    EXPECT_NEAR(OrbitExtrema(o).x_min, b.lo[2 * i], 1e-12) << "row " << i;
    EXPECT_NEAR(OrbitExtrema(o).x_max, b.hi[2 * i], 1e-12) << "row " << i;
    EXPECT_NEAR(OrbitExtrema(o).xdot_max, b.hi[2 * i + 1], 1e-12) << "row " << i;
    EXPECT_NEAR(std::abs(o.multipliers[0]), b.multiplier[i], 1e-9) << "row " << i;
  }
  EXPECT_GE(b.found(), 16u);
}

TEST(SystemBatch, NonStopRowsMatchDenHartog) {
  ForcedBeltParams base = ref::Coulomb(0.3, 0.3, 0, 0, 1, 1.3);
  SystemColumn w{ForcedBelt::kOmegaIndex, {1.3, 1.5, 1.75, 2, 2.25, 2.5}};
  SystemBatchOptions o = BatchOptions(2);
  o.start = Eigen::Vector3d(-0.5, 0.0, 0);
  o.shooting.flow.rtol = o.shooting.flow.atol = 1e-14;
  o.transient = 0;  // Newton from the start: the undamped approach is slow
  o.max_m = 1;
  const SystemBatch b = StroboscopicOrbits(ForcedBelt(base), {w}, o);
  for (std::size_t i = 0; i < b.rows(); ++i) {
    ASSERT_EQ(b.status[i], OrbitStatus::kOk) << "Omega = " << w.values[i];
    EXPECT_EQ(b.sticks[i], 0);
    const double X = ref::DenHartogX(0.3, 1, w.values[i]);
    EXPECT_NEAR(b.hi[2 * i], X, 1e-9) << "Omega = " << w.values[i];
    EXPECT_NEAR(-b.lo[2 * i], X, 1e-9) << "Omega = " << w.values[i];
  }
}

TEST(SystemBatch, OneAndTwoThreadsGiveTheSameColumns) {
  const auto cols = BatchGrid(12, 10);
  const SystemBatch one = StroboscopicOrbits(ForcedBelt(Belt()), cols, BatchOptions(1));
  const SystemBatch two = StroboscopicOrbits(ForcedBelt(Belt()), cols, BatchOptions(2));
  EXPECT_EQ(one.threads, 1);
  EXPECT_EQ(two.threads, 2);
  EXPECT_EQ(one.status, two.status);
  EXPECT_EQ(one.m, two.m);
  EXPECT_EQ(one.sticks, two.sticks);
  EXPECT_EQ(one.period, two.period);
  EXPECT_EQ(one.start, two.start);
  EXPECT_EQ(one.lo, two.lo);
  EXPECT_EQ(one.hi, two.hi);
  EXPECT_EQ(one.multiplier, two.multiplier);
  EXPECT_EQ(one.stable, two.stable);
}

// The seed belt forced at A 0.3 (studies/seed_forced.ini).
ForcedBeltParams BatchSeed(double w) { return ref::SeedBelt(0.25, 0.3, w); }

TEST(SystemBatch, FailedRowsKeepTheirStatusAndZeros) {
  // Omega 0.52: no period up to 4 (the orbit diagram's chaotic band); one
  // Newton step from the start: kNotConverged.
  SystemColumn w{ForcedBelt::kOmegaIndex, {0.52, 0.53}};
  SystemBatchOptions o = BatchOptions(1);
  o.start = Eigen::Vector3d(0, 0, 0);
  SystemBatch b = StroboscopicOrbits(ForcedBelt(BatchSeed(0.52)), {w}, o);
  o.transient = 0, o.max_m = 1, o.shooting.max_newton = 1;
  const SystemBatch c = StroboscopicOrbits(ForcedBelt(BatchSeed(0.52)), {w}, o);
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_EQ(b.status[i], OrbitStatus::kAperiodic);
    EXPECT_EQ(c.status[i], OrbitStatus::kNotConverged);
    for (const SystemBatch* r : {static_cast<const SystemBatch*>(&b), &c}) {
      EXPECT_EQ(r->m[i], 0);
      EXPECT_EQ(r->period[i], 0.0);
      EXPECT_EQ(r->hi[2 * i], 0.0);
      EXPECT_EQ(r->multiplier[i], 0.0);
      EXPECT_EQ(r->stable[i], 0);
    }
  }
}

// Above resonance the seed belt's period-1 orbit attracts slowly (|multiplier|
// 0.87-0.91): its run recurs to 1e-3 after no period up to 4 and comes closest
// after 2 (complex multipliers). The row is still the period-1 orbit, equal to
// the single-orbit API's, not a doubled copy of it.
TEST(SystemBatch, SlowlyAttractingOrbitsKeepTheirLeastPeriod) {
  SystemColumn w{ForcedBelt::kOmegaIndex, {1.45, 1.5}};
  SystemBatchOptions o = BatchOptions(2);
  o.start = Eigen::Vector3d(0, 0, 0);
  const SystemBatch b = StroboscopicOrbits(ForcedBelt(BatchSeed(1.45)), {w}, o);
  ShootingOptions fo(ForcedBelt::FlowDefaults());
  fo.flow.rtol = fo.flow.atol = 1e-13;
  for (std::size_t i = 0; i < 2; ++i) {
    ASSERT_EQ(b.status[i], OrbitStatus::kOk) << i;
    EXPECT_EQ(b.m[i], 1) << i;
    EXPECT_GT(b.multiplier[i], 0.8) << i;
    const PeriodicOrbit r = ShootStroboscopic(ForcedBelt(BatchSeed(w.values[i])), b.start[2 * i],
                                              b.start[2 * i + 1], 1, fo);
    ASSERT_TRUE(r.ok());
    EXPECT_NEAR(std::abs(r.multipliers[0]), b.multiplier[i], 1e-9);
    EXPECT_NEAR(OrbitExtrema(r).x_max, b.hi[2 * i], 1e-12);
    EXPECT_EQ(r.sticks, b.sticks[i]);
  }
}

TEST(SystemBatch, CancelStopsTheRowsAndReportsProgress) {
  for (int threads : {1, 2}) {
    std::size_t last = 0;
    SystemBatchOptions o = BatchOptions(threads);
    o.cancelled = [&] { return last >= 64; };  // progress comes first
    o.progress = [&](std::size_t done) { last = done; };
    // 10^4 rows (~0.25 s on two threads): the pool polls the hook every
    // 20 ms, so most rows are still queued when it fires.
    const SystemBatch b = StroboscopicOrbits(ForcedBelt(Belt()), BatchGrid(40, 250), o);
    EXPECT_TRUE(b.cancelled) << threads;
    const auto cancelled = std::count(b.status.begin(), b.status.end(), OrbitStatus::kCancelled);
    EXPECT_GT(cancelled, 5000) << threads;
    EXPECT_GE(last, 64u) << threads;
    EXPECT_LT(last, b.rows()) << threads;
    for (std::size_t i = 0; i < b.rows(); ++i)
      if (b.status[i] == OrbitStatus::kCancelled) {
        EXPECT_EQ(b.period[i], 0.0);
      }
  }
  SystemBatchOptions o = BatchOptions(1);
  o.cancelled = [] { return true; };
  const SystemBatch b = StroboscopicOrbits(ForcedBelt(Belt()), BatchGrid(3, 3), o);
  EXPECT_TRUE(b.cancelled);
  EXPECT_EQ(b.found(), 0u);
}

void ExpectRefused(const std::vector<SystemColumn>& cols, const SystemBatchOptions& o,
                   const std::string& needle) {
  try {
    StroboscopicOrbits(ForcedBelt(Belt()), cols, o);
    ADD_FAILURE() << "accepted; expected " << needle;
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
  }
}

TEST(SystemBatch, BadColumnsAndOptionsAreRefusedBeforeAnyWork) {
  const SystemBatchOptions o = BatchOptions(1);
  const int mu = static_cast<int>(Parameter::kMuS);
  ExpectRefused({}, o, "no parameter column");
  ExpectRefused({{99, {1.0}}}, o, "parameter index 99");
  ExpectRefused({{mu, {0.4}}, {mu, {0.4}}}, o, "'mu_s' is given twice");
  ExpectRefused({{mu, {0.4, 0.4}}, {ForcedBelt::kOmegaIndex, {1.0}}}, o, "differ in length");
  ExpectRefused({{mu, {0.4, -1.0}}}, o, "row 1 (mu_s = -1): mu_s");
  ExpectRefused({{mu, {0.4, NAN}}}, o, "row 1: mu_s = nan");
  ExpectRefused({{ForcedBelt::kOmegaIndex, {1.0, 0.0}}}, o, "row 1 (omega = 0): omega");
  SystemBatchOptions bad = o;
  bad.max_m = 0;
  ExpectRefused({{mu, {0.4}}}, bad, "max_m = 0");
  bad = o, bad.transient = -1;
  ExpectRefused({{mu, {0.4}}}, bad, "transient = -1");
  bad = o, bad.recurrence = 1;
  ExpectRefused({{mu, {0.4}}}, bad, "recurrence = 1");
  bad = o, bad.start = Eigen::Vector2d(0, 0);
  ExpectRefused({{mu, {0.4}}}, bad, "the start has 2 components");
  bad = o, bad.threads = -1;
  ExpectRefused({{mu, {0.4}}}, bad, "threads = -1");
  EXPECT_EQ(StroboscopicOrbits(ForcedBelt(Belt()), {{mu, {}}}, o).rows(), 0u);
}

}  // namespace
}  // namespace stickslip
