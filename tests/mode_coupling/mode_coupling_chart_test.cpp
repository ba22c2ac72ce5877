// The chart of the mode-coupling brake model (ChartSystem, system_chart.hpp)
// in (mu_k, beta): the HB curve against the closed flutter threshold
// (docs/theory.md, "Mode coupling"), and the LP curve against one-parameter
// runs of the branch driver, which locate their folds by bisection on the
// test function's sign along the branch, not by Newton on the bordered
// system.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "mode_coupling/mode_coupling.hpp"
#include "stickslip/chart/system_chart.hpp"
#include "stickslip/equilibria/steady_sliding.hpp"
#include "stickslip/errors.hpp"
#include "stickslip/orbits/settle.hpp"

namespace stickslip::mode_coupling {
namespace {

CouplingParams Brake() {
  CouplingParams p;
  p.law.law = LawKind::kCoulomb;
  p.law.mu_s = 0.8;
  p.law.mu_k = 0.52;
  return p;
}

SystemChartOptions BrakePlane(const System& s) {
  SystemChartOptions o;
  o.plane.p1 = s.ParameterIndex("mu_k");
  o.plane.p2 = s.ParameterIndex("beta");
  o.plane.from1 = 0.45, o.plane.to1 = 0.6, o.plane.from2 = 0.01, o.plane.to2 = 0.03;
  o.branch.shooting.flow.rtol = o.branch.shooting.flow.atol = 1e-12;
  return o;
}

const SystemChart& BrakeChart() {
  static const SystemChart chart = [] {
    const ModeCoupling s(Brake());
    return ChartSystem(s, BrakePlane(s));
  }();
  return chart;
}

const SystemCurve* Find(const SystemChart& c, CurveKind kind) {
  for (const SystemCurve& cv : c.curves)
    if (cv.kind == kind) return &cv;
  return nullptr;
}

TEST(ModeCouplingChart, HopfCurveIsTheFlutterThreshold) {
  const SystemChart& c = BrakeChart();
  EXPECT_EQ(c.status, ChartStatus::kOk) << c.message;
  const SystemCurve* hb = Find(c, CurveKind::kHopf);
  ASSERT_NE(hb, nullptr);
  EXPECT_EQ(hb->ends.Text(), "border / border");
  ASSERT_GT(hb->points.size(), 20u);
  double lo = 1, hi = 0;
  for (const SystemCurvePoint& p : hb->points) {
    CouplingParams q = Brake();
    q.beta = p.p2;
    EXPECT_NEAR(p.p1, FlutterMuK(q), 1e-12) << "beta " << p.p2;
    EXPECT_GT(p.orbit.period, 0);  // a complex pair: a Hopf point, no neutral saddle
    lo = std::min(lo, p.p2), hi = std::max(hi, p.p2);
  }
  EXPECT_DOUBLE_EQ(lo, 0.01);  // border to border in beta
  EXPECT_DOUBLE_EQ(hi, 0.03);
}

TEST(ModeCouplingChart, FoldCurveMeetsTheBranchFolds) {
  const SystemCurve* lp = Find(BrakeChart(), CurveKind::kFold);
  ASSERT_NE(lp, nullptr);
  ASSERT_GT(lp->points.size(), 20u);
  EXPECT_EQ(lp->ends.first.kind, CurveEndKind::kBorder);
  // Where the fold meets the contact's opening the curve ends, labelled; its
  // last orbit reaches y = 1 / gamma within the last step.
  EXPECT_EQ(lp->ends.last.kind, CurveEndKind::kContactLost) << lp->ends.Text();
  EXPECT_NEAR(lp->points.back().orbit.hi[2], 1, 1e-3);
  const ModeCoupling base(Brake());
  const int mu_k = base.ParameterIndex("mu_k"), beta = base.ParameterIndex("beta");
  // At three points of the curve, a one-parameter run in mu_k from an orbit
  // 0.002 below the fold locates its LP at the curve's mu_k.
  for (const std::size_t i :
       {lp->points.size() / 5, lp->points.size() / 2, lp->points.size() / 4}) {
    const SystemCurvePoint& p = lp->points[i];
    double nearest = 1e9;  // a multiplier at +1
    for (const auto& m : p.orbit.multipliers) nearest = std::min(nearest, std::abs(m - 1.0));
    EXPECT_LT(nearest, 1e-7) << "point " << i;
    std::unique_ptr<System> s = base.Clone();
    s->SetParameterValue(beta, p.p2);
    s->SetParameterValue(mu_k, p.p1 - 0.002);
    OrbitBranchOptions o(BrakePlane(base).branch.shooting.flow);
    o.palc.ds = o.palc.ds_max = 0.001;
    Shooting shoot(*s, o.shooting);
    const PeriodicOrbit start = shoot.Find(p.orbit.start, lp->section);
    ASSERT_TRUE(start.ok()) << start.message;
    const OrbitBranch b = ContinueOrbits(*s, mu_k, start.start, lp->section, p.p1 + 0.01, o);
    double found = 0;
    for (const OrbitRow& r : b.special)
      if (r.label == SpecialKind::kFold) found = r.p;
    EXPECT_NEAR(found, p.p1, 1e-9) << "beta " << p.p2;
  }
  // The study's fold at beta = 0.02 (docs/systems.md, "The mode-coupling study").
  double at = 0;
  for (const SystemCurvePoint& p : lp->points)
    if (std::abs(p.p2 - 0.02) < 1e-15) at = p.p1;
  EXPECT_NEAR(at, 0.5287726318563702, 1e-10);
}

// The LP curve's cusp: below its beta the branch in mu_k folds twice (an S),
// above it not at all; each fold lies on the curve.
TEST(ModeCouplingChart, CuspIsWhereTwoFoldsMerge) {
  const SystemChart& c = BrakeChart();
  const SystemCodim2* cp = nullptr;
  for (const SystemCodim2& p : c.codim2)
    if (p.label == Codim2Label::kCusp) cp = &p;
  ASSERT_NE(cp, nullptr);
  const SystemCurve* lp = Find(c, CurveKind::kFold);
  auto folds = [&](double beta) {
    CouplingParams q = Brake();
    q.beta = beta, q.law.mu_k = 0.525;
    const ModeCoupling s(q);
    SettleOptions so;
    so.shooting = BrakePlane(s).branch.shooting;
    Eigen::VectorXd z0 = SteadySliding(s).z;
    z0[0] += 0.5;
    const SettledOrbit st = SettleOnStickSlip(s, z0, so);
    EXPECT_TRUE(st.found) << st.message;
    OrbitBranchOptions o(so.shooting.flow);
    o.palc.ds = o.palc.ds_max = 0.002;
    const OrbitBranch b =
        ContinueOrbits(s, s.ParameterIndex("mu_k"), st.orbit.start, st.section, 0.6, o);
    std::vector<double> out;
    for (const OrbitRow& r : b.special)
      if (r.label == SpecialKind::kFold) out.push_back(r.p);
    return out;
  };
  const double below = cp->p2 - 2e-4;
  const std::vector<double> two = folds(below);
  ASSERT_EQ(two.size(), 2u);
  for (const double mu : two) {  // on the curve: between two of its points at beta = below
    double gap = 1;
    for (std::size_t i = 1; i < lp->points.size(); ++i) {
      const SystemCurvePoint &a = lp->points[i - 1], &b = lp->points[i];
      if ((a.p2 - below) * (b.p2 - below) > 0) continue;
      const double f = (below - a.p2) / (b.p2 - a.p2);
      gap = std::min(gap, std::abs(a.p1 + f * (b.p1 - a.p1) - mu));
    }
    EXPECT_LT(gap, 1e-6) << "fold at mu_k " << mu;
  }
  EXPECT_TRUE(folds(cp->p2 + 2e-4).empty());
}

TEST(ModeCouplingChart, RefusesBadPlanes) {
  const ModeCoupling s(Brake());
  SystemChartOptions o = BrakePlane(s);
  o.plane.p2 = o.plane.p1;
  EXPECT_THROW(ChartSystem(s, o), InvalidArgument);
  o = BrakePlane(s);
  o.plane.to1 = 0.9;  // mu_k > mu_s on the border
  EXPECT_NE(o.ValidationError(s).find("mu_k = 0.9"), std::string::npos) << o.ValidationError(s);
  o = BrakePlane(s);
  o.plane.from2 = o.plane.to2;
  EXPECT_NE(o.ValidationError(s).find("empty or inverted"), std::string::npos);
  o = BrakePlane(s);
  o.max_step = 0;
  EXPECT_NE(o.ValidationError(s).find("max_step"), std::string::npos);
}

}  // namespace
}  // namespace stickslip::mode_coupling
