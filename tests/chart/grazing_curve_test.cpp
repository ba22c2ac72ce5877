// GR curves and GR-LP points (grazing_curve.hpp) through the chart driver,
// against the independent long-double reference integrator
// (reference/reference_orbit.hpp): the grazing speed at the curve
// point's beta by bisection on the reference's first-return maximum of x', and
// the pure-slip multiplier of the reference's grazing orbit.
#include "chart/grazing_curve.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "reference/reference_orbit.hpp"
#include "stickslip/chart/chart.hpp"

namespace stickslip {
namespace {

namespace ref = stickslip::reference;

Params Quintic() {
  Params p;
  p.k5 = 0.24;
  return p;
}

ChartResult GrazingChart(const Params& base, const Plane& plane) {
  ChartOptions o;
  o.plane = plane;
  o.hopf_curves = false;
  o.fold_curves = false;
  return Chart(base, o);
}

const ChartResult& SeedChart() {
  static const ChartResult r = GrazingChart(Params{}, Plane{Parameter::kV, Parameter::kBeta, 0.02, 0.6, 0.0, 0.25});
  return r;
}

const ChartResult& QuinticChart() {
  static const ChartResult r = GrazingChart(Quintic(), Plane{Parameter::kV, Parameter::kBeta, 0.05, 0.58, 0.0, 0.12});
  return r;
}

// The reference grazing speed at the point's beta, bracketed within 1e-6 of its v.
long double ReferenceGrazingSpeed(Params p, const CurvePoint& c) {
  p.beta = c.p2;
  return ref::GrazingSpeed(p, c.p1 - 1e-6L, c.p1 + 1e-6L, 1e-14L);
}

void ExpectOnReferenceGrazingCurve(const Params& base, const Curve& c, int samples) {
  ASSERT_GT(c.points.size(), 20u);
  for (int k = 0; k < samples; ++k) {
    const CurvePoint& pt = c.points[(k + 1) * c.points.size() / (samples + 1)];
    const long double v = ReferenceGrazingSpeed(base, pt);
    ASSERT_TRUE(std::isfinite(static_cast<double>(v))) << "beta = " << pt.p2;
    EXPECT_NEAR(pt.p1, static_cast<double>(v), 1e-10) << "beta = " << pt.p2;
  }
}

TEST(GrazingCurve, SeedCurveOnTheReferenceGrazingCurve) {
  const ChartResult& r = SeedChart();
  ASSERT_EQ(r.curves.size(), 1u);
  EXPECT_EQ(r.curves[0].kind, CurveKind::kGrazing);
  ExpectOnReferenceGrazingCurve(Params{}, r.curves[0], 4);
  // Supercritical everywhere: stick-slip hands over to a stable pure-slip orbit.
  for (const CurvePoint& p : r.curves[0].points) {
    EXPECT_LT(p.multiplier, 1.0);
    EXPECT_EQ(p.type, CurvePointType::kPersistence);
  }
  EXPECT_TRUE(r.codim2.empty());
}

// beta is a damping ratio: every beta >= 0 is a model, and the GR curve runs
// into the rectangle's beta = 0 edge (it once stopped at beta = 1e-6, where a
// lower scale bound refused the next step).
TEST(GrazingCurve, SeedCurveReachesBetaZero) {
  const ChartResult& r = SeedChart();
  ASSERT_EQ(r.curves.size(), 1u);
  EXPECT_EQ(r.status, ChartStatus::kOk) << r.message;
  const Curve& c = r.curves[0];
  EXPECT_EQ(c.ends.Text(), "border / border");
  const CurvePoint& end =
      c.points.front().p2 < c.points.back().p2 ? c.points.front() : c.points.back();
  ASSERT_EQ(end.p2, 0.0) << c.ends.Text();
  Params p;
  p.beta = 0;
  const long double v = ref::GrazingSpeed(p, end.p1 - 1e-4L, end.p1 + 1e-4L, 1e-15L);
  EXPECT_NEAR(end.p1, static_cast<double>(v), 1e-10);
}

TEST(GrazingCurve, SeedGrazingAtBeta005AsTheOneParameterBranch) {
  // The averaging estimate 2 sqrt((k1 - 2 beta) / (15 k3)) = 0.3944 is near; the
  // one-parameter run (ss_continue) finds v_g a little under 0.40 at beta = 0.05.
  Params p;
  p.beta = 0.05;
  const long double v = ref::GrazingSpeed(p, 0.38L, 0.41L, 1e-13L);
  double best = HUGE_VAL;
  for (const CurvePoint& c : SeedChart().curves[0].points)
    best = std::min(best, std::abs(c.p2 - 0.05) + std::abs(c.p1 - static_cast<double>(v)));
  EXPECT_LT(best, 0.01);  // a curve point within one step of it
}

TEST(GrazingCurve, QuinticCurveOnTheReferenceGrazingCurve) {
  const ChartResult& r = QuinticChart();
  ASSERT_EQ(r.curves.size(), 1u);
  ExpectOnReferenceGrazingCurve(Quintic(), r.curves[0], 4);
}

// exp(oint tr J dt) over the reference's first return from the exit point (x0, v) of the
// slip-below field to the next maximum of x' (as ref::FirstReturnMaxXdot, with the trace).
long double FirstReturnMultiplier(const ref::Model& m, long double tol) {
  ref::Stepper<5> st(ref::SlipField<5>{&m, -1}, tol);
  const auto& f = st.field();
  ref::State<5> s{m.StickHigh(), m.v, 0, 1, 0};
  long double t = 0;
  bool seen_min = false;
  for (bool first = true; t < 200; first = false) {
    const ref::State<5> s0 = s;
    const long double t0 = t;
    if (st.Step(s, t) <= 0) break;
    const bool p0 = first ? false : f(s0)[1] > 0, p1 = f(s)[1] > 0;
    if (!p0 && p1) seen_min = true;
    if (seen_min && p0 && !p1) {
      const long double hm = ref::Bisect(
          [&](long double hh) { return f(st.From(s0, t0, hh))[1] > 0; }, 0, t - t0, true, t0);
      return std::exp(st.From(s0, t0, hm)[2]);
    }
  }
  return NAN;
}

// The reference multiplier of the grazing orbit at beta: the reference grazing speed, then
// the trace integral along its first return, which is the grazing orbit.
long double ReferenceGrazingMultiplier(Params p, long double beta, long double v_guess) {
  p.beta = static_cast<double>(beta);
  const long double v = ref::GrazingSpeed(p, v_guess - 1e-4L, v_guess + 1e-4L, 1e-15L);
  ref::Model m(p);
  m.v = v;
  m.beta = beta;
  return FirstReturnMultiplier(m, 1e-17L);
}

TEST(GrazingCurve, GrazingFoldPointAgainstTheReference) {
  const ChartResult& r = QuinticChart();
  ASSERT_EQ(r.codim2.size(), 1u);
  const Codim2Point& lp = r.codim2[0];
  EXPECT_EQ(lp.label, Codim2Label::kGrazingFold);
  // The type changes there: persistence on the supercritical side, fold past it.
  const auto& pts = r.curves[0].points;
  bool persistence = false, fold = false;
  for (const CurvePoint& p : pts) {
    persistence = persistence || (p.type == CurvePointType::kPersistence && p.p2 > lp.p2);
    fold = fold || (p.type == CurvePointType::kNonsmoothFold && p.p2 < lp.p2);
  }
  EXPECT_TRUE(persistence && fold);
  // On the reference grazing curve ...
  Params p = Quintic();
  p.beta = lp.p2;
  EXPECT_NEAR(lp.p1, static_cast<double>(ref::GrazingSpeed(p, lp.p1 - 1e-6, lp.p1 + 1e-6, 1e-14L)),
              1e-10);
  // ... where the reference multiplier crosses 1: secant in beta.
  long double b0 = lp.p2 - 1e-5L, b1 = lp.p2 + 1e-5L;
  long double f0 = ReferenceGrazingMultiplier(Quintic(), b0, lp.p1) - 1;
  long double f1 = ReferenceGrazingMultiplier(Quintic(), b1, lp.p1) - 1;
  ASSERT_LT(f0 * f1, 0) << "no sign change of lambda - 1 around the GR-LP point";
  for (int i = 0; i < 8 && std::abs(b1 - b0) > 1e-14L; ++i) {
    const long double b2 = b1 - f1 * (b1 - b0) / (f1 - f0);
    b0 = b1, f0 = f1;
    b1 = b2, f1 = ReferenceGrazingMultiplier(Quintic(), b1, lp.p1) - 1;
  }
  EXPECT_NEAR(lp.p2, static_cast<double>(b1), 1e-10);
}

}  // namespace
}  // namespace stickslip
