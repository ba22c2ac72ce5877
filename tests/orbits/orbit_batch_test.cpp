// The batched stick-slip orbits against one OrbitFinder per point (bit for
// bit), the undamped Coulomb closed form, the damped Coulomb end speed, thread
// counts, cancellation and bad columns.
#include "stickslip/orbits/orbit_batch.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <thread>

#include "coulomb_damped.hpp"
#include "parallel/pool.hpp"
#include "stickslip/errors.hpp"
#include "stickslip/systems/belt/model.hpp"

namespace stickslip {
namespace {

// v over the seed's range (the stick-slip orbit ends near v = 0.44) by mu_s.
std::vector<ParameterColumn> Grid(int nv, int nmu) {
  ParameterColumn v{Parameter::kV, {}}, mu_s{Parameter::kMuS, {}};
  for (int i = 0; i < nv; ++i)
    for (int j = 0; j < nmu; ++j) {
      v.values.push_back(0.05 + 0.42 * i / (nv - 1));
      mu_s.values.push_back(0.36 + 0.08 * j / (nmu - 1));
    }
  return {v, mu_s};
}

OrbitBatchOptions Options(int threads, bool floquet = false) {
  OrbitBatchOptions o;
  o.threads = threads;
  o.orbit.floquet = floquet;
  return o;
}

// Every column of row i equals a fresh finder's StickSlip(true) at that point.
void ExpectRowIsOneFinder(const OrbitBatch& b, std::size_t i, const Params& p,
                          const OrbitOptions& options) {
  OrbitFinder finder(Model(p), options);
  const OrbitResult r = finder.StickSlip(true);
  ASSERT_EQ(b.status[i], r.status) << "row " << i;
  const Orbit& o = r.orbit;
  const bool ok = r.ok();
  EXPECT_EQ(b.period[i], ok ? o.period : 0.0) << "row " << i;
  EXPECT_EQ(b.t_stick[i], ok ? o.t_stick : 0.0) << "row " << i;
  EXPECT_EQ(b.x_min[i], ok ? o.extrema.x_min : 0.0) << "row " << i;
  EXPECT_EQ(b.x_max[i], ok ? o.extrema.x_max : 0.0) << "row " << i;
  EXPECT_EQ(b.xdot_min[i], ok ? o.extrema.xdot_min : 0.0) << "row " << i;
  EXPECT_EQ(b.xdot_max[i], ok ? o.extrema.xdot_max : 0.0) << "row " << i;
  EXPECT_EQ(b.multiplier[i], ok ? o.multiplier : 0.0) << "row " << i;
  EXPECT_EQ(b.stable[i], ok && o.stable ? 1 : 0) << "row " << i;
}

Params Row(const std::vector<ParameterColumn>& cols, std::size_t i) {
  Params p;
  for (const ParameterColumn& c : cols) c.parameter.Set(p, c.values[i]);
  return p;
}

TEST(OrbitBatch, RowsEqualOneFinderPerPointBitForBit) {
  for (bool floquet : {false, true}) {
    const auto cols = Grid(15, 6);
    const OrbitBatch b = StickSlipOrbits(Params(), cols, Options(2, floquet));
    ASSERT_EQ(b.rows(), 90u);
    EXPECT_TRUE(b.error.empty()) << b.error;
    EXPECT_FALSE(b.cancelled);
    for (std::size_t i = 0; i < b.rows(); ++i)
      ExpectRowIsOneFinder(b, i, Row(cols, i), Options(1, floquet).orbit);
    // Both outcomes occur: orbits, and high speeds whose slip misses Omega.
    EXPECT_GT(b.found(), 60u);
    EXPECT_LT(b.found(), b.rows());
  }
}

TEST(OrbitBatch, OneAndTwoThreadsGiveTheSameColumns) {
  const auto cols = Grid(40, 30);
  const OrbitBatch one = StickSlipOrbits(Params(), cols, Options(1));
  const OrbitBatch two = StickSlipOrbits(Params(), cols, Options(2));
  EXPECT_EQ(one.threads, 1);
  EXPECT_EQ(two.threads, std::min(2, HardwareThreads()));
  EXPECT_EQ(one.status, two.status);
  EXPECT_EQ(one.period, two.period);
  EXPECT_EQ(one.t_stick, two.t_stick);
  EXPECT_EQ(one.x_min, two.x_min);
  EXPECT_EQ(one.x_max, two.x_max);
  EXPECT_EQ(one.xdot_min, two.xdot_min);
  EXPECT_EQ(one.xdot_max, two.xdot_max);
  EXPECT_EQ(one.stable, two.stable);
}

// Coulomb without damping: slip is u'' + u = 0, u = x - mu_k, from the exit
// point (u, u') = (Delta, v), Delta = mu_s - mu_k, on the circle of radius
// R = sqrt(Delta^2 + v^2); it meets x' = v again at u = -Delta after
// 2 pi - 2 atan(Delta / v) (tan(t/2) = -Delta / v), inside the stick band,
// and sticks for 2 Delta / v (seed eq. 3.6).
TEST(OrbitBatch, UndampedCoulombMatchesTheClosedForm) {
  Params base;
  base.law = LawKind::kCoulomb;
  base.beta = 0;
  base.mu_s = 0.4;
  ParameterColumn v{Parameter::kV, {0.05, 0.1, 0.25, 0.5, 1.0}};
  ParameterColumn mu_k{Parameter::kMuK, {0.1, 0.2, 0.25, 0.3, 0.35}};
  OrbitBatchOptions o = Options(2);
  o.orbit.flow.rtol = 1e-12;
  o.orbit.flow.atol = 1e-14;
  const OrbitBatch b = StickSlipOrbits(base, {v, mu_k}, o);
  const double pi = std::acos(-1.0);
  for (std::size_t i = 0; i < b.rows(); ++i) {
    ASSERT_EQ(b.status[i], OrbitStatus::kOk) << "row " << i;
    const double vi = v.values[i], delta = base.mu_s - mu_k.values[i];
    const double r = std::hypot(delta, vi);
    EXPECT_NEAR(b.period[i], 2 * pi - 2 * std::atan(delta / vi) + 2 * delta / vi, 1e-9);
    EXPECT_NEAR(b.t_stick[i], 2 * delta / vi, 1e-9);
    EXPECT_NEAR(b.x_max[i], mu_k.values[i] + r, 1e-10);
    EXPECT_NEAR(b.x_min[i], mu_k.values[i] - r, 1e-10);
    EXPECT_NEAR(b.xdot_min[i], -r, 1e-10);
  }
}

// Damped Coulomb: the orbit exists below the closed-form end speed and the
// first return misses Omega above it (coulomb_damped.hpp); missed rows hold zeros.
TEST(OrbitBatch, NoOrbitAboveTheDampedCoulombEndSpeedIsAMissedRowOfZeros) {
  Params base;
  base.law = LawKind::kCoulomb;
  base.beta = 0.05;
  const double v_end =
      static_cast<double>(coulomb_damped::EndSpeed(base.mu_s, base.mu_k, base.beta));
  ParameterColumn v{Parameter::kV,
                    {0.5 * v_end, v_end * (1 - 1e-6), v_end * (1 + 1e-6), 2 * v_end}};
  const OrbitBatch b = StickSlipOrbits(base, {v}, Options(1));
  const OrbitStatus want[] = {OrbitStatus::kOk, OrbitStatus::kOk, OrbitStatus::kMissed,
                              OrbitStatus::kMissed};
  for (std::size_t i = 0; i < 4; ++i) {
    EXPECT_EQ(b.status[i], want[i]) << "row " << i;
    if (i < 2) continue;
    for (const auto* col :
         {&b.period, &b.t_stick, &b.x_min, &b.x_max, &b.xdot_min, &b.xdot_max, &b.multiplier})
      EXPECT_EQ((*col)[i], 0.0);
    EXPECT_EQ(b.stable[i], 0);
  }
}

// The hook runs on the calling thread only; once it fires, every row is either
// computed (equal to one finder) or kCancelled.
TEST(OrbitBatch, CancelStopsTheWorkersAndMarksTheRowsLeft) {
  const auto cols = Grid(500, 100);  // 50000 rows: about 0.2 s, far past the first 20 ms poll
  const std::thread::id caller = std::this_thread::get_id();
  std::atomic<int> calls{0};
  bool other_thread = false;
  OrbitBatchOptions o = Options(2);
  o.cancelled = [&] {
    other_thread |= std::this_thread::get_id() != caller;
    return ++calls > 1;  // the check before any work passes, the first poll fires
  };
  const OrbitBatch b = StickSlipOrbits(Params(), cols, o);
  EXPECT_TRUE(b.cancelled);
  EXPECT_FALSE(other_thread);
  std::size_t cancelled = 0;
  for (std::size_t i = 0; i < b.rows(); ++i) {
    if (b.status[i] == OrbitStatus::kCancelled) {
      ++cancelled;
      EXPECT_EQ(b.period[i], 0.0);
    } else if (i % 97 == 0) {
      ExpectRowIsOneFinder(b, i, Row(cols, i), o.orbit);
    }
  }
  EXPECT_GT(cancelled, 0u);
  EXPECT_LT(cancelled, b.rows());
  // Cancelled before it starts: no row computed, no thread started.
  o.cancelled = [] { return true; };
  const OrbitBatch none = StickSlipOrbits(Params(), Grid(10, 10), o);
  EXPECT_TRUE(none.cancelled);
  EXPECT_EQ(none.threads, 0);
  for (OrbitStatus s : none.status) EXPECT_EQ(s, OrbitStatus::kCancelled);
}

// One thread: the rows run on the calling thread, which polls the hook before
// every row and at every step; here it fires at its 200th call.
TEST(OrbitBatch, OneThreadRunsOnTheCallerAndPollsTheHookPerRow) {
  const auto cols = Grid(100, 10);
  const std::thread::id caller = std::this_thread::get_id();
  int calls = 0;
  bool other_thread = false;
  OrbitBatchOptions o = Options(1);
  o.cancelled = [&] {
    other_thread |= std::this_thread::get_id() != caller;
    return ++calls >= 200;
  };
  const OrbitBatch b = StickSlipOrbits(Params(), cols, o);
  EXPECT_TRUE(b.cancelled);
  EXPECT_FALSE(other_thread);
  EXPECT_EQ(calls, 200);  // never called again once it fired
  std::size_t first_cancelled = b.rows();
  for (std::size_t i = 0; i < b.rows(); ++i)
    if (b.status[i] == OrbitStatus::kCancelled) {
      first_cancelled = std::min(first_cancelled, i);
    } else {
      EXPECT_LT(i, first_cancelled);  // rows run in order: none after the first cancelled
      ExpectRowIsOneFinder(b, i, Row(cols, i), o.orbit);
    }
  EXPECT_GT(first_cancelled, 0u);
  EXPECT_LT(first_cancelled, 200u);  // at least one call per row
}

// Bad columns are the caller's error: InvalidArgument before any work (the
// cancel hook is never called), naming the column, row and value. A row status
// is kept for numerical outcomes only (OrbitStatus).
TEST(OrbitBatch, BadColumnsThrowBeforeAnyWork) {
  int calls = 0;
  OrbitBatchOptions o = Options(2);
  o.cancelled = [&] { return ++calls < 0; };
  auto message = [&](const std::vector<ParameterColumn>& cols, const Params& base = Params()) {
    try {
      StickSlipOrbits(base, cols, o);
    } catch (const InvalidArgument& e) {
      return std::string(e.what());
    }
    return std::string("no exception");
  };
  const ParameterColumn v{Parameter::kV, {0.1, 0.2, 0.3}};
  EXPECT_EQ(message({}), "no parameter column: give at least one");
  EXPECT_EQ(message({v, {Parameter::kMuS, {0.4, 0.5}}}), "columns differ in length: v 3, mu_s 2");
  EXPECT_EQ(message({v, v}), "column 'v' is given twice");
  EXPECT_EQ(message({v, {Parameter::kMuK, {0.1, 0.2, 0.3}}}),
            "column 'mu_k': not a parameter of the cubic law");
  EXPECT_EQ(message({{Parameter::kV, {0.1, -0.2, 0.3}}}), "row 1: v = -0.2 must be > 0");
  EXPECT_EQ(message({{Parameter::kMuS, {0.4, 0.2, NAN}}}),
            "row 1: mu_m = 0.25 must be < mu_s = 0.2");
  EXPECT_EQ(message({{Parameter::kMuS, {0.4, 0.5, NAN}}}),
            "row 2: mu_s = nan is not a finite number");
  EXPECT_THROW(ParameterAxis("nope"), InvalidArgument);  // names are resolved at the edge
  o.threads = -1;
  EXPECT_EQ(message({v}), "threads = -1 must be >= 0");
  EXPECT_EQ(calls, 0);
  // Zero rows: an empty result.
  o.threads = 1;
  EXPECT_EQ(StickSlipOrbits(Params(), {{Parameter::kV, {}}}, o).rows(), 0u);
}

}  // namespace
}  // namespace stickslip
