// The smallest-disturbance columns of branch.tsv against the reference orbit's
// polygon (long-double integrator, brute-force distances).
#include "stickslip/basin/branch_disturbance.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "reference_curve.hpp"

namespace stickslip {
namespace {

TEST(BranchDisturbance, UnstablePureSlipRowsMatchTheReferenceOrbit) {
  Params base;
  base.law = LawKind::kStribeck;  // subcritical Hopf at v = 0.549, fold at GR 0.652
  ContinuationOptions o;
  o.from = 0.5;
  o.to = 0.66;
  o.max_step = 0.05;
  const ContinuationResult r = Continue(base, o);
  ASSERT_FALSE(r.partial()) << r.message;
  const std::vector<Disturbance> d = BranchDisturbances(base, r, o.orbit.flow);
  ASSERT_EQ(d.size(), r.points.size());
  int checked = 0, unstable = 0;
  for (size_t i = 0; i < r.points.size(); ++i) {
    const BranchPoint& pt = r.points[i];
    const bool applies = pt.kind == PointKind::kPureSlip && !pt.stable;
    EXPECT_EQ(std::isnan(d[i].x), !applies) << "row " << i;
    EXPECT_EQ(std::isnan(d[i].energy), !applies) << "row " << i;
    if (!applies || pt.amplitude < 0.05 || unstable++ % 3 != 0) continue;
    Params p = base;
    p.v = pt.p;
    const reference::Real xbar = reference::Law(p).Mu(p.v);
    const auto curve =
        testing_util::ReferenceCurve(p, static_cast<double>(xbar) + pt.amplitude, 400);
    ASSERT_FALSE(curve.empty());
    const auto [dx, dy, e] = testing_util::BruteDisturbance(curve, xbar);
    EXPECT_NEAR(d[i].x, static_cast<double>(dx), 1e-4) << "v = " << pt.p;
    EXPECT_NEAR(d[i].xdot, static_cast<double>(dy), 1e-4) << "v = " << pt.p;
    EXPECT_NEAR(d[i].energy, static_cast<double>(e), 1e-7) << "v = " << pt.p;
    ++checked;
  }
  EXPECT_GE(checked, 2);
}

}  // namespace
}  // namespace stickslip
