// The batched settled stick-slip orbits of an autonomous System (the
// coulomb belt): each row against the closed-form slip phase (a damped
// linear oscillator, long double, no library code), rows equal to
// SettleOnStickSlip, thread counts, steady sliding, cancellation, misuse.
#include "stickslip/orbits/settled_batch.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <optional>

#include "stickslip/errors.hpp"
#include "stickslip/systems/belt/model.hpp"
#include "stickslip/systems/forced/forced.hpp"

namespace stickslip {
namespace {

using Real = long double;
constexpr double kBeta = 0.02, kMuK = 0.25;

Params SettledCoulombBelt() {
  Params p;
  p.law = LawKind::kCoulomb;
  p.mu_s = 0.4, p.mu_k = kMuK, p.beta = kBeta, p.v = 0.1;
  return p;
}

// v over [0.05, 0.25] by mu_s over [0.3, 0.45], v slowest.
std::vector<SystemColumn> SettledGrid(const Model& m, int nv, int nmu) {
  SystemColumn v{m.ParameterIndex("v"), {}}, mu{m.ParameterIndex("mu_s"), {}};
  for (int i = 0; i < nv; ++i)
    for (int j = 0; j < nmu; ++j) {
      v.values.push_back(0.05 + 0.2 * i / (nv - 1));
      mu.values.push_back(0.3 + 0.15 * j / (nmu - 1));
    }
  return {v, mu};
}

// The stick-slip orbit in closed form: from the stick exit x_e = mu_s -
// 2 beta v, x' = v, the slip x = mu_k + e^(-beta t)(A cos wt + B sin wt) runs
// until x' = v again at T_s (none: steady sliding follows), then sticks
// until x = x_e again. Period T_s + (x_e - x(T_s)) / v.
struct ClosedForm {
  Real x_e, period;
};
std::optional<ClosedForm> ClosedOrbit(Real mu_s, Real v) {
  const Real b = kBeta, w = std::sqrt(1 - b * b), x_e = mu_s - 2 * b * v, A = x_e - kMuK,
             B = (v + b * A) / w;
  auto x = [&](Real t) {
    return kMuK + std::exp(-b * t) * (A * std::cos(w * t) + B * std::sin(w * t));
  };
  auto gap = [&](Real t) {  // x'(t) - v
    return std::exp(-b * t) * (v * std::cos(w * t) - (b * B + w * A) * std::sin(w * t)) - v;
  };
  Real lo = 1e-3L, hi = 0;
  for (Real t = lo; t < 200 && hi == 0; t += 1e-3L) (gap(t) >= 0 ? hi : lo) = t;
  if (hi == 0) return std::nullopt;
  for (int k = 0; k < 200; ++k) {
    const Real mid = (lo + hi) / 2;
    (gap(mid) >= 0 ? hi : lo) = mid;
  }
  const Real x_a = x(hi);
  if (std::abs(x_a + 2 * b * v) > mu_s) return std::nullopt;  // slips on: not this scene
  return ClosedForm{x_e, hi + (x_e - x_a) / v};
}

SettledBatchOptions SettledOptions(int threads) {
  SettledBatchOptions o;
  o.threads = threads;
  o.start = Eigen::Vector2d(-0.5, 0);  // far enough from the belt to reach it
  o.settle.transient = 300;
  o.settle.shooting.flow.rtol = o.settle.shooting.flow.atol = 1e-13;
  return o;
}

TEST(SettledBatch, CoulombBeltRowsAreTheClosedFormOrbit) {
  const Model belt(SettledCoulombBelt());
  const auto cols = SettledGrid(belt, 9, 4);
  const SystemBatch b = SettledOrbits(belt, cols, SettledOptions(2));
  ASSERT_EQ(b.rows(), 36u);
  ASSERT_EQ(b.tangent, 2);
  EXPECT_TRUE(b.error.empty()) << b.error;
  int orbits = 0, sliding = 0;
  double worst = 0;
  for (std::size_t i = 0; i < b.rows(); ++i) {
    const Real v = cols[0].values[i], mu_s = cols[1].values[i];
    const std::optional<ClosedForm> ref = ClosedOrbit(mu_s, v);
    if (!ref) {  // the slip from the stick exit never meets the belt again
      EXPECT_EQ(b.status[i], OrbitStatus::kNoReturn) << "row " << i << " v " << v;
      EXPECT_EQ(b.period[i], 0);
      ++sliding;
      continue;
    }
    ASSERT_EQ(b.status[i], OrbitStatus::kOk) << "row " << i << " v " << v << " mu_s " << mu_s;
    ++orbits;
    const double T = static_cast<double>(ref->period);
    worst = std::max(worst, std::abs(b.period[i] - T) / T);
    EXPECT_NEAR(b.period[i], T, 1e-11 * T) << "row " << i;
    EXPECT_NEAR(b.start[2 * i], static_cast<double>(ref->x_e), 1e-12) << "row " << i;
    EXPECT_NEAR(b.start[2 * i + 1], static_cast<double>(v), 1e-12) << "row " << i;
    EXPECT_EQ(b.m[i], 1);
    EXPECT_EQ(b.contact[i], 0);
    EXPECT_EQ(b.sticks[i], 1);
    EXPECT_LT(b.multiplier[i], 1e-8) << "row " << i;  // a stick phase collapses the state
    EXPECT_EQ(b.stable[i], 1);
    EXPECT_NEAR(b.hi[2 * i + 1], static_cast<double>(v), 1e-12);  // x' never passes the belt
  }
  EXPECT_GT(orbits, 10);
  EXPECT_GT(sliding, 3);
  std::printf("[ measured ] %d stick-slip rows, %d steady sliding; period vs closed form %.2e\n",
              orbits, sliding, worst);
}

TEST(SettledBatch, RowsEqualSettleOnStickSlipForAnyThreadCount) {
  const Model belt(SettledCoulombBelt());
  const auto cols = SettledGrid(belt, 6, 3);
  const SettledBatchOptions o = SettledOptions(1);
  const SystemBatch one = SettledOrbits(belt, cols, o),
                    two = SettledOrbits(belt, cols, SettledOptions(2));
  Model row(SettledCoulombBelt());
  for (std::size_t i = 0; i < one.rows(); ++i) {
    for (const SystemColumn& c : cols) row.SetParameterValue(c.parameter, c.values[i]);
    const SettledOrbit s = SettleOnStickSlip(row, o.start, o.settle);
    EXPECT_EQ(s.found, one.status[i] == OrbitStatus::kOk) << "row " << i;
    if (s.found) {
      EXPECT_EQ(s.orbit.period, one.period[i]) << "row " << i;
    }
    EXPECT_EQ(one.status[i], two.status[i]);
    EXPECT_EQ(one.period[i], two.period[i]);
  }
  EXPECT_EQ(one.start, two.start);
  EXPECT_EQ(one.lo, two.lo);
  EXPECT_EQ(one.hi, two.hi);
  EXPECT_EQ(one.multiplier, two.multiplier);
}

TEST(SettledBatch, CancelledBeforeWorkLeavesEveryRowCancelled) {
  const Model belt(SettledCoulombBelt());
  SettledBatchOptions o = SettledOptions(2);
  o.cancelled = [] { return true; };
  const SystemBatch b = SettledOrbits(belt, SettledGrid(belt, 3, 2), o);
  EXPECT_TRUE(b.cancelled);
  for (OrbitStatus s : b.status) EXPECT_EQ(s, OrbitStatus::kCancelled);
}

TEST(SettledBatch, MisuseIsRefusedByName) {
  const Model belt(SettledCoulombBelt());
  const auto cols = SettledGrid(belt, 2, 2);
  SettledBatchOptions o = SettledOptions(1);
  o.start = Eigen::Vector3d::Zero();
  EXPECT_THROW(SettledOrbits(belt, cols, o), InvalidArgument);  // a start of 3
  o = SettledOptions(1);
  o.settle.transient = -1;
  EXPECT_THROW(SettledOrbits(belt, cols, o), InvalidArgument);
  ForcedBeltParams fp;
  fp.force = 0.1;
  try {
    SettledOrbits(ForcedBelt(fp), {{ForcedBelt::kOmegaIndex, {1.0}}}, SettledOptions(1));
    ADD_FAILURE() << "a clocked system was taken";
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find("StroboscopicOrbits"), std::string::npos) << e.what();
  }
  std::vector<SystemColumn> bad = cols;
  bad[1].values[1] = -0.3;  // mu_s < 0: row 1 is named
  try {
    SettledOrbits(belt, bad, SettledOptions(1));
    ADD_FAILURE() << "an invalid row was taken";
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find("row 1"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace stickslip
