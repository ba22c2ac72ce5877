// BranchContext::EvalG: dG/dp from the parameter column against the long-double
// reference integrator's return map, and when the column is used at all.
#include "continuation/branch_context.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "reference/reference_orbit.hpp"

namespace stickslip {
namespace {

// G(a) = (P(xbar + a) - xbar - a) / a of the reference (RKF78, long double).
long double ReferenceG(const Params& q, double a) {
  const reference::Model m(q);
  const long double xbar = m.law.Mu(m.v);  // steady sliding
  const reference::SectionReturn r = reference::ReturnToSection(m, xbar + a, 1e-18L, 200);
  EXPECT_TRUE(r.ok);
  return (r.x - xbar - a) / a;
}

// dG/dp at fixed a: central differences at h and h / 2, Richardson-extrapolated.
double ReferenceDGDp(const Params& base, const std::string& name, double a, double h) {
  auto G = [&](double dp) {
    Params q = base;
    SetParameter(q, name, GetParameter(base, name) + dp);
    return ReferenceG(q, a);
  };
  const long double d1 = (G(h) - G(-h)) / (2 * h), d2 = (G(h / 2) - G(-h / 2)) / h;
  return static_cast<double>((4 * d2 - d1) / 3);
}

struct Case {
  const char* law;
  Params p;
  double a_guess;  // near the pure-slip orbit at p
  std::vector<std::string> params;
};

std::vector<Case> Cases() {
  Params cubic;
  cubic.v = 0.42;   // between grazing (0.396) and Hopf (0.441): pure slip
  Params stribeck;  // the unstable branch of the subcritical Hopf point (1.007)
  stribeck.law = LawKind::kStribeck;
  stribeck.beta = 0.02;
  stribeck.v = 1.3;
  Params leine;  // beyond the subcritical Hopf point (3.749)
  leine.law = LawKind::kLeine;
  leine.beta = 0.01;
  leine.mu_s = 1;
  leine.v = 3.8;
  return {{"cubic", cubic, 0.3, {"v", "beta", "mu_s", "mu_m", "k5"}},
          {"stribeck", stribeck, 1.1, {"v", "beta", "mu_s", "mu_k"}},
          {"leine", leine, 0.6, {"v", "beta", "mu_s"}}};
}

ContinuationOptions Around(const std::string& name, double p, Integrator integrator) {
  ContinuationOptions o;
  o.param = ParameterAxis(name);
  o.from = p == 0 ? 0 : 0.95 * p;  // valid at both ends for every case here
  o.to = p == 0 ? 1 : 1.05 * p;
  o.orbit.flow.integrator = integrator;
  return o;
}

// On the pure-slip orbit of each law, for every parameter the column supports:
// dG/dp from the column agrees with the reference within 1e-10 (measured: see
// the printed errors), where the one-sided difference the tracer used before
// (step sqrt(rtol) x the p-scale) is printed beside it.
TEST(BranchContext, DGDpFromTheColumnMatchesTheReference) {
  double worst_column = 0, worst_quotient = 0;
  for (const Case& c : Cases()) {
    for (const std::string& name : c.params) {
      const double p = GetParameter(c.p, name);
      const ContinuationOptions o = Around(name, p, Integrator::kTaylor);
      BranchContext ctx(c.p, o);
      ASSERT_TRUE(ctx.column()) << c.law << " " << name;
      Orbit orbit;
      double a = 0;
      ASSERT_TRUE(ctx.PureSlipAtFixedP(p, c.a_guess, &orbit, &a)) << c.law << " " << name;
      double g = 0, ga = 0, gp = NAN, g_plain = 0, ga_plain = 0, g2 = 0;
      ReturnMap map;
      ASSERT_EQ(ctx.EvalG(a, p, &g, &ga, &map, &gp), OrbitStatus::kOk);
      ASSERT_TRUE(map.has_dpdp) << c.law << " " << name;
      // The tracer's former quotient (trace_pure_slip.cpp): forward step hp.
      const double hp = std::sqrt(o.orbit.flow.rtol) * std::max(ctx.LocalScale(p), std::abs(p));
      ASSERT_EQ(ctx.EvalG(a, p, &g_plain, &ga_plain, nullptr), OrbitStatus::kOk);
      ASSERT_EQ(ctx.EvalG(a, p + hp, &g2, nullptr, nullptr), OrbitStatus::kOk);
      const double quotient = (g2 - g_plain) / hp;
      const double ref = ReferenceDGDp(c.p, name, a, 2e-4);
      const double scale = std::max(1.0, std::abs(ref));
      EXPECT_NEAR(gp, ref, 1e-10 * scale) << c.law << " " << name << " a = " << a;
      worst_column = std::max(worst_column, std::abs(gp - ref) / scale);
      worst_quotient = std::max(worst_quotient, std::abs(quotient - ref) / scale);
      std::cout << c.law << " " << name << " a = " << a << " dG/dp = " << ref << "  column error "
                << gp - ref << "  quotient error " << quotient - ref << std::endl;
    }
  }
  std::cout << "worst error / max(1, |dG/dp|): column " << worst_column << ", quotient "
            << worst_quotient << std::endl;
  EXPECT_LT(worst_column, 1e-2 * worst_quotient);
}

// With dG/dp exact, the tracer's Newton converges quadratically: the pure-slip
// rows of the seed and stribeck studies lie on the reference's orbit at the
// same p within 1e-11 in amplitude (measured 1.5e-13, 5.9e-14 and 4.1e-13,
// printed; with the former quotient 2.9e-10, 7.6e-10 and 1.7e-10).
TEST(BranchContext, ExactDGDpPutsPureSlipRowsOnTheReferenceOrbit) {
  struct Study {
    const char* name;
    Params p;
    const char* param;
    double from, to;
  };
  Params stribeck;  // studies/stribeck.ini
  stribeck.law = LawKind::kStribeck;
  const Study studies[] = {{"seed", Params(), "v", 0.05, 0.5},
                           {"seed_beta", Params(), "beta", 0.01, 0.3},
                           {"stribeck", stribeck, "v", 0.3, 0.8}};
  for (const Study& st : studies) {
    ContinuationOptions o;
    o.param = ParameterAxis(st.param);
    o.from = st.from;
    o.to = st.to;
    const ContinuationResult r = Continue(st.p, o);
    ASSERT_EQ(r.status, ContinuationStatus::kOk) << r.message;
    double worst = 0;
    int rows = 0;
    for (const BranchPoint& pt : r.points) {
      if (pt.kind != PointKind::kPureSlip || pt.amplitude == 0) continue;
      Params q = st.p;
      SetParameter(q, st.param, pt.p);
      const long double xbar = reference::Model(q).law.Mu(q.v);
      const reference::PureSlipOrbit ref = reference::PureSlip(q, xbar + pt.amplitude);
      ASSERT_TRUE(ref.found) << st.name << " at " << pt.p;
      const double err = std::abs(static_cast<double>(ref.x_section - xbar) - pt.amplitude);
      EXPECT_LT(err, 1e-11) << st.name << " at " << pt.p;
      worst = std::max(worst, err);
      ++rows;
    }
    EXPECT_GT(rows, 10) << st.name;
    std::cout << st.name << ": " << rows << " pure-slip rows, worst amplitude error " << worst
              << std::endl;
  }
}

TEST(BranchContext, ColumnOnlyOnTaylorAndAffineParameters) {
  const Params cubic;
  EXPECT_TRUE(BranchContext(cubic, Around("v", 0.42, Integrator::kTaylor)).column());
  EXPECT_FALSE(BranchContext(cubic, Around("v", 0.42, Integrator::kCvode)).column());
  EXPECT_FALSE(BranchContext(cubic, Around("v_m", 0.5, Integrator::kTaylor)).column());
  Params stribeck;
  stribeck.law = LawKind::kStribeck;
  EXPECT_FALSE(BranchContext(stribeck, Around("v_s", 0.5, Integrator::kTaylor)).column());
  Params leine;
  leine.law = LawKind::kLeine;
  EXPECT_FALSE(BranchContext(leine, Around("delta", 3, Integrator::kTaylor)).column());
  // Without the column EvalG leaves dG/dp alone (the tracer's quotient then).
  BranchContext ctx(cubic, Around("v", 0.42, Integrator::kCvode));
  double g = 0, ga = 0, gp = 7;
  ReturnMap map;
  ASSERT_EQ(ctx.EvalG(0.2, 0.42, &g, &ga, &map, &gp), OrbitStatus::kOk);
  EXPECT_FALSE(map.has_dpdp);
  EXPECT_EQ(gp, 7);
}

}  // namespace
}  // namespace stickslip
