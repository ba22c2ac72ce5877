// The estimate columns against an independent recomputation: r1 from its
// closed form 3v/2 - sqrt(D) (seed 3.17, corrected), a_ps from Thomsen &
// Fidlin's formula, x'_min from the long-double reference integrator.
#include "stickslip/estimates/comparison.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "reference/reference_orbit.hpp"

namespace stickslip {
namespace {

TEST(Comparison, ColumnsAgreeWithAnIndependentRecomputation) {
  const Params base;
  ContinuationOptions o;
  o.from = 0.05;
  o.to = 0.5;
  o.max_step = 0.05;
  const ContinuationResult r = Continue(base, o);
  ASSERT_EQ(r.status, ContinuationStatus::kOk) << r.message;
  const EstimateComparison c = CompareEstimates(base, r);
  ASSERT_TRUE(c.applies);
  const auto col = [&](const std::string& name) -> const std::vector<double>& {
    for (const auto& e : c.columns)
      if (e.name == name) return e.values;
    ADD_FAILURE() << "no column " << name;
    static const std::vector<double> none;
    return none;
  };
  const auto& r1 = col("r1");
  const auto& err_r1 = col("err_r1");
  const auto& a_ps = col("a_ps");
  const auto& err_a_ps = col("err_a_ps");
  ASSERT_EQ(r1.size(), r.points.size());
  const double k1 = base.k1(), k3 = base.k3(), b = base.beta;
  int checked = 0, checked_ps = 0;
  for (size_t i = 0; i < r.points.size(); ++i) {
    const BranchPoint& pt = r.points[i];
    const double v = pt.p;
    if (pt.kind == PointKind::kEquilibrium) {
      EXPECT_TRUE(std::isnan(r1[i]));
      continue;
    }
    const double d = 2.25 * v * v - (2 * b - k1 + 3 * k3 * v * v) / k3;
    if (d <= 0 || 1.5 * v - std::sqrt(d) >= 0) {      // roots r1 < 0 < r2 only below v_max
      EXPECT_TRUE(std::isnan(r1[i])) << "v = " << v;  // not applicable: no number
      continue;
    }
    EXPECT_NEAR(r1[i], 1.5 * v - std::sqrt(d), 1e-12) << "v = " << v;
    // The computed x'_min, independently.
    Params q = base;
    q.v = v;
    double xdot_min = 0;
    if (pt.kind == PointKind::kStickSlip && pt.t_stick > 0) {
      const reference::StickSlipOrbit ref = reference::StickSlip(q);
      ASSERT_TRUE(ref.found);
      xdot_min = static_cast<double>(ref.xdot_min);
    } else {
      continue;  // grazing rows and pure slip: checked through a_ps below
    }
    EXPECT_NEAR(err_r1[i], (1.5 * v - std::sqrt(d)) - xdot_min, 1e-8) << "v = " << v;
    ++checked;
  }
  for (size_t i = 0; i < r.points.size(); ++i) {
    const BranchPoint& pt = r.points[i];
    if (pt.kind != PointKind::kPureSlip || pt.amplitude < 0.05) continue;
    const double v = pt.p;
    const double amp = 2 * std::sqrt((k1 - 2 * b - 3 * k3 * v * v) / (3 * k3));
    EXPECT_NEAR(a_ps[i], amp, 1e-12);
    Params q = base;
    q.v = v;
    const reference::PureSlipOrbit ref = reference::PureSlip(q, 0.25L + pt.amplitude);
    ASSERT_TRUE(ref.found) << "v = " << v;
    EXPECT_NEAR(err_a_ps[i], -amp - static_cast<double>(ref.xdot_min), 1e-8) << "v = " << v;
    ++checked_ps;
  }
  EXPECT_GE(checked, 5);
  EXPECT_GE(checked_ps, 3);
  // Averaging is not applied to stick-slip orbits.
  for (size_t i = 0; i < r.points.size(); ++i) {
    if (r.points[i].kind == PointKind::kStickSlip) {
      EXPECT_TRUE(std::isnan(err_a_ps[i]));
    }
  }
  // GR and HB against their estimates.
  ASSERT_EQ(c.special.size(), 2u);
  EXPECT_NEAR(c.special[0].estimated, 2 * std::sqrt((k1 - 2 * b) / (15 * k3)), 1e-12);
  EXPECT_NEAR(c.special[1].estimated, std::sqrt((k1 - 2 * b) / (3 * k3)), 1e-12);
}

TEST(Comparison, OtherLawsSayWhy) {
  Params p;
  p.law = LawKind::kStribeck;
  ContinuationResult r;
  const EstimateComparison c = CompareEstimates(p, r);
  EXPECT_FALSE(c.applies);
  EXPECT_NE(c.reason.find("stribeck"), std::string::npos);
}

}  // namespace
}  // namespace stickslip
