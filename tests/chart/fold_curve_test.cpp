// LP curves (fold_curve.hpp) through the chart driver: the fold curve of the
// quintic scene leaves the GH point and ends at the GR-LP point; its points
// against folds solved independently with the long-double reference
// integrator (reference/reference_orbit.hpp): at the point's beta,
// P(x) = x and P'(x) = 1 for the reference section map, by Newton in (x, v).
#include "chart/fold_curve.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "reference/reference_orbit.hpp"
#include "stickslip/chart/chart.hpp"

namespace stickslip {
namespace {

namespace ref = stickslip::reference;
using Real = long double;

Params FoldQuintic() {
  Params p;
  p.k5 = 0.24;
  return p;
}

const ChartResult& FoldQuinticChart() {
  static const ChartResult r = [] {
    ChartOptions o;
    o.plane = Plane{Parameter::kV, Parameter::kBeta, 0.05, 0.58, 0.0, 0.12};
    return Chart(FoldQuintic(), o);
  }();
  return r;
}

const Curve* FoldCurve(const ChartResult& r) {
  for (const Curve& c : r.curves)
    if (c.kind == CurveKind::kFold) return &c;
  return nullptr;
}

// (P(x) - x, P'(x) - 1) of the reference section map at (beta, v).
bool Residual(Params p, Real x, Real v, Real out[2]) {
  ref::Model m(p);
  m.v = v;
  const ref::SectionReturn r = ref::ReturnToSection(m, x, 1e-17L, 200);
  if (!r.ok) return false;
  out[0] = r.x - x;
  out[1] = r.dx - 1;
  return true;
}

// The reference fold at p.beta from (x, v): Newton with difference quotients.
bool ReferenceFold(const Params& p, Real& x, Real& v) {
  for (int it = 0; it < 30; ++it) {
    Real f[2], fx[2], fv[2];
    const Real hx = 1e-7L, hv = 1e-8L;
    if (!Residual(p, x, v, f) || !Residual(p, x + hx, v, fx) || !Residual(p, x, v + hv, fv))
      return false;
    const Real a = (fx[0] - f[0]) / hx, b = (fv[0] - f[0]) / hv;
    const Real c = (fx[1] - f[1]) / hx, d = (fv[1] - f[1]) / hv;
    const Real det = a * d - b * c;
    const Real dx = -(d * f[0] - b * f[1]) / det, dv = -(-c * f[0] + a * f[1]) / det;
    x += dx, v += dv;
    if (std::abs(dv) < 1e-16L && std::abs(dx) < 1e-12L) return true;
  }
  return false;
}

TEST(FoldCurve, QuinticFoldRunsFromGHToGRLP) {
  const ChartResult& r = FoldQuinticChart();
  const Curve* lp = FoldCurve(r);
  ASSERT_NE(lp, nullptr);
  EXPECT_EQ(lp->ends.Text(), "GH / GR-LP");
  const Codim2Point *gh = nullptr, *grlp = nullptr;
  for (const Codim2Point& c : r.codim2) (c.label == Codim2Label::kGeneralizedHopf ? gh : grlp) = &c;
  ASSERT_TRUE(gh && grlp);
  EXPECT_EQ(lp->points.front().p1, gh->p1);
  EXPECT_EQ(lp->points.front().p2, gh->p2);
  EXPECT_NEAR(lp->points.back().p1, grlp->p1, 1e-12);
  EXPECT_NEAR(lp->points.back().p2, grlp->p2, 1e-12);
  for (const CurvePoint& c : lp->points) EXPECT_NEAR(c.multiplier, 1.0, 1e-8);  // P' = 1
}

TEST(FoldCurve, PointsAgainstTheReference) {
  const Curve* lp = FoldCurve(FoldQuinticChart());
  ASSERT_NE(lp, nullptr);
  ASSERT_GT(lp->points.size(), 20u);
  for (double frac : {0.3, 0.6, 0.85}) {
    const CurvePoint& c = lp->points[static_cast<size_t>(frac * lp->points.size())];
    Params p = FoldQuintic();
    p.beta = c.p2;
    p.v = c.p1;
    // The section point from the chart's amplitude: x* ~ xbar + amplitude.
    Real v = c.p1, x = Friction(p).Mu(c.p1) + c.amplitude;
    ASSERT_TRUE(ReferenceFold(p, x, v)) << "beta = " << c.p2;
    EXPECT_NEAR(c.p1, static_cast<double>(v), 1e-10) << "beta = " << c.p2;
  }
}

// At the tightest tolerances the LP rows follow the integration error down
// (they stayed 3.3e-12 off at every tolerance: the corrector's fixed 1e-10
// stopping test). Every row but the GH and GR-LP end points, against the
// reference fold at its beta.
TEST(FoldCurve, PointsAtTheTightestToleranceWithin1e13) {
  ChartOptions o;
  o.plane = Plane{Parameter::kV, Parameter::kBeta, 0.05, 0.58, 0.0, 0.12};
  o.orbit.flow.rtol = 1e-14;
  o.orbit.flow.atol = 1e-16;
  o.hopf_curves = true;
  const ChartResult r = Chart(FoldQuintic(), o);
  const Curve* lp = FoldCurve(r);
  ASSERT_NE(lp, nullptr);
  ASSERT_GT(lp->points.size(), 20u);
  for (double frac : {0.2, 0.45, 0.7, 0.9}) {
    const CurvePoint& c = lp->points[static_cast<size_t>(frac * lp->points.size())];
    Params p = FoldQuintic();
    p.beta = c.p2;
    Real v = c.p1, x = Friction(p).Mu(c.p1) + c.amplitude;
    ASSERT_TRUE(ReferenceFold(p, x, v)) << "beta = " << c.p2;
    EXPECT_NEAR(c.p1, static_cast<double>(v), 1e-13) << "beta = " << c.p2;
  }
}

}  // namespace
}  // namespace stickslip
