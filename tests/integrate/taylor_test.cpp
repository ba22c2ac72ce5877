// The Taylor stepper (Integrator::kTaylor) against the long-double reference
// integrator, closed forms of the coulomb law at beta = 0, and CVODE.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <utility>

#include "reference/reference_orbit.hpp"
#include "stickslip/errors.hpp"
#include "stickslip/systems/belt/belt_flow.hpp"
#include "stickslip/systems/belt/params.hpp"

namespace stickslip {
namespace {

FlowOptions Taylor(double rtol = 1e-11) {
  FlowOptions o;
  o.integrator = Integrator::kTaylor;
  o.rtol = rtol;
  o.atol = rtol * 1e-2;
  return o;
}

FlowOptions Cvode(double rtol = 1e-11) {
  FlowOptions o = Taylor(rtol);
  o.integrator = Integrator::kCvode;
  return o;
}

// Slip from the exit point until the orbit enters stick: period and extremes.
FlowResult StickSlipRun(const Params& p, const FlowOptions& o, double* period) {
  const Model m(p);
  BeltFlow flow(m, o);
  StopRule stop;
  stop.at_stick = true;
  stop.t_max = 1e4;
  FlowResult r = flow.Run(0.0, m.ExitPoint(), Mode::kSlipBelow, stop, false);
  EXPECT_EQ(r.status, FlowStatus::kStick);
  *period = r.t + (m.ExitPoint()[0] - r.z[0]) / p.v;
  return r;
}

struct Case {
  const char* name;
  Params p;
};

std::vector<Case> EveryLaw() {
  std::vector<Case> cases;
  cases.push_back({"cubic (seed set)", Params()});
  Params q;
  q.k5 = 0.5;  // the quintic term -k5 s^5
  cases.push_back({"cubic with k5", q});
  Params c;
  c.law = LawKind::kCoulomb;
  c.mu_k = 0.25;
  c.v = 0.1;
  cases.push_back({"coulomb", c});
  Params s;
  s.law = LawKind::kStribeck;
  s.beta = 0.02;
  s.v = 0.1;
  cases.push_back({"stribeck", s});
  Params l;
  l.law = LawKind::kLeine;
  l.beta = 0;
  l.mu_s = 1;
  l.delta = 3;
  l.v = 0.2;
  cases.push_back({"leine (Leine et al. 1998)", l});
  return cases;
}

TEST(Taylor, StickSlipOrbitsMatchTheReferenceForEveryLaw) {
  for (const Case& c : EveryLaw()) {
    const reference::StickSlipOrbit ref = reference::StickSlip(c.p);
    ASSERT_TRUE(ref.found) << c.name;
    double period = 0;
    const FlowResult r = StickSlipRun(c.p, Taylor(1e-13), &period);
    const double T = static_cast<double>(ref.period);
    EXPECT_NEAR(period, T, 1e-12 * T) << c.name;
    EXPECT_NEAR(r.extrema.x_max, static_cast<double>(ref.x_max), 1e-12) << c.name;
    EXPECT_NEAR(r.extrema.x_min, static_cast<double>(ref.x_min), 1e-12) << c.name;
    EXPECT_NEAR(r.extrema.xdot_min, static_cast<double>(ref.xdot_min), 1e-12) << c.name;
    EXPECT_EQ(r.crossings, ref.crossings) << c.name;
  }
}

// Slip above the belt: from (x_s, v) below the stick interval both one-sided
// fields point up; one arc of slip above back to x' = v, against the
// reference's segment integration.
TEST(Taylor, SlipAboveTheBeltMatchesTheReference) {
  for (const Case& c : EveryLaw()) {
    const Model m(c.p);
    const double x_s = -c.p.mu_s - 2 * c.p.beta * c.p.v - 0.2;
    const reference::Model rm(c.p);
    reference::Real t = 0, xa = 0;
    reference::Extremes e;
    ASSERT_TRUE(reference::SlipSegment(rm, +1, x_s, 1e-17L, 100, t, xa, e)) << c.name;
    BeltFlow flow(m, Taylor(1e-13));
    StopRule stop;
    stop.at_stick = true;
    stop.t_max = 100;
    const FlowResult r = flow.Run(0.0, Vec2(x_s, c.p.v), Mode::kSlipAbove, stop, false);
    ASSERT_GE(r.modes.size(), 1u);
    EXPECT_EQ(r.modes[0], Mode::kSlipAbove) << c.name;
    if (r.crossings == 0) {  // the first arrival is the end
      EXPECT_EQ(r.status, FlowStatus::kStick) << c.name;
      EXPECT_NEAR(r.t, static_cast<double>(t), 1e-12 * r.t) << c.name;
      EXPECT_NEAR(r.z[0], static_cast<double>(xa), 1e-12) << c.name;
      EXPECT_NEAR(r.extrema.xdot_max, static_cast<double>(e.xdot_max), 1e-12) << c.name;
    } else {
      ADD_FAILURE() << c.name << ": crossed at x = " << static_cast<double>(xa);
    }
  }
}

TEST(Taylor, AgreesWithCvode) {
  for (const Case& c : EveryLaw()) {
    double tp = 0, cp = 0;
    const FlowResult t = StickSlipRun(c.p, Taylor(), &tp);
    const FlowResult v = StickSlipRun(c.p, Cvode(1e-12), &cp);
    EXPECT_NEAR(tp, cp, 1e-8 * cp) << c.name;
    EXPECT_NEAR(t.z[0], v.z[0], 1e-8) << c.name;
    EXPECT_EQ(t.crossings, v.crossings) << c.name;
  }
}

TEST(Taylor, CoulombBeta0PeriodMatchesTheClosedForm) {
  for (double v : {0.01, 0.05, 0.1, 0.25, 0.5}) {
    Params p;
    p.law = LawKind::kCoulomb;
    p.beta = 0;
    p.mu_s = 0.4;
    p.mu_k = 0.25;
    p.v = v;
    const double exact = static_cast<double>(reference::CoulombPeriodBeta0(0.4L, 0.25L, v));
    double period = 0;
    StickSlipRun(p, Taylor(1e-13), &period);
    EXPECT_NEAR(period, exact, 1e-13 * exact) << "v = " << v;
  }
}

// Coulomb law, beta = 0: slip below is the circle x - mu_k = -R cos(s),
// x' = R sin(s), s = t + s0. With R = v + eps the orbit rises above x' = v for
// s in pi/2 -+ acos(v / R) only, a touch much shorter than a step.
struct Touch {
  Params p;
  double R, s0;
  Vec2 Start() const { return Vec2(p.mu_k - R * std::cos(s0), R * std::sin(s0)); }
  double Arrival() const { return M_PI / 2 - std::acos(p.v / R) - s0; }
};

Touch MakeTouch(double eps) {
  Touch t;
  t.p.law = LawKind::kCoulomb;
  t.p.beta = 0;
  t.p.mu_s = 0.4;
  t.p.mu_k = 0.25;
  t.p.v = 0.25;
  t.R = t.p.v + eps;
  t.s0 = 0.5;
  return t;
}

FlowResult RunTouch(const Touch& t, const FlowOptions& o) {
  const Model m(t.p);
  BeltFlow flow(m, o);
  StopRule stop;
  stop.at_stick = true;
  stop.t_max = 3.0;  // past the top of the circle at t = pi/2 - s0
  return flow.Run(0.0, t.Start(), Mode::kSlipBelow, stop, false);
}

// Coulomb law, beta = 0, belt faster than the orbit: x - mu_k = -R cos(t + s0),
// x' = R sin(t + s0) never reaches v. From s0 = pi + 0.1 the stepper passes a
// minimum of x (x' rising through 0) and both extrema of x' inside its steps,
// records them, and stops at the next maximum of x (x' falling through 0) at
// t = 2 pi - 0.1.
TEST(Taylor, PassesExtremaAndStopsAtTheSectionOnTheClosedForm) {
  Params p;
  p.law = LawKind::kCoulomb;
  p.beta = 0;
  p.mu_s = 0.4;
  p.mu_k = 0.25;
  p.v = 1;
  const double R = 0.5, s0 = M_PI + 0.1;
  // Steps measured: 16 at 1e-6, 9 at 1e-12; stopping at each of the three
  // extrema passed would cost about three more.
  for (auto [rtol, max_steps] : {std::pair{1e-6, 17L}, std::pair{1e-12, 10L}}) {
    const Model m(p);
    BeltFlow flow(m, Taylor(rtol));
    StopRule stop;
    stop.at_section = true;
    stop.t_max = 20;
    const Vec2 start(p.mu_k - R * std::cos(s0), R * std::sin(s0));
    const FlowResult r = flow.Run(0.0, start, Mode::kSlipBelow, stop, false);
    ASSERT_EQ(r.status, FlowStatus::kSection) << r.message;
    const double tol = 100 * rtol;
    EXPECT_NEAR(r.t, 2 * M_PI - 0.1, tol) << "rtol " << rtol;
    EXPECT_NEAR(r.extrema.x_min, p.mu_k - R, tol) << "rtol " << rtol;
    EXPECT_NEAR(r.extrema.x_max, p.mu_k + R, tol) << "rtol " << rtol;
    EXPECT_NEAR(r.extrema.xdot_min, -R, tol) << "rtol " << rtol;
    EXPECT_NEAR(r.extrema.xdot_max, R, tol) << "rtol " << rtol;
    EXPECT_LE(flow.total_steps(), max_steps) << "rtol " << rtol;
  }
}

// The arrival time of a touch 1e-6 high is conditioned like 1 / x'' ~ 1e3
// times the error in x'; the Taylor steps here are about 1 long.
TEST(Taylor, FindsATouchShorterThanAStep) {
  const Touch t = MakeTouch(1e-6);  // above x' = v for 5.7e-3 in time
  for (const FlowOptions& o : {Taylor(), Cvode()}) {
    const double tol = o.integrator == Integrator::kTaylor ? 1e-11 : 1e-7;
    const FlowResult r = RunTouch(t, o);
    ASSERT_EQ(r.status, FlowStatus::kStick) << Name(o.integrator);
    EXPECT_NEAR(r.t, t.Arrival(), tol) << Name(o.integrator);
    EXPECT_NEAR(r.z[0], t.p.mu_k - t.R * std::cos(t.s0 + t.Arrival()), tol);
  }
}

// A touch 1e-14 above x' = v sticks, one 1e-14 below passes under. Near the
// top x' - v ~ eps - (t - t_top)^2 R / 2, so the arrival time is only
// determined to ~ rounding / sqrt(2 eps R) ~ 1e-8.
TEST(Taylor, ResolvesAGrazingWithin1e14) {
  const Touch over = MakeTouch(1e-14), under = MakeTouch(-1e-14);
  const FlowResult r = RunTouch(over, Taylor());
  ASSERT_EQ(r.status, FlowStatus::kStick);
  EXPECT_NEAR(r.t, over.Arrival(), 1e-7);
  const FlowResult q = RunTouch(under, Taylor());
  EXPECT_EQ(q.status, FlowStatus::kTimeLimit);  // passes under x' = v
  EXPECT_NEAR(q.extrema.xdot_max, under.R, 1e-13);
}

TEST(Taylor, ErrorIsProportionalToTheTolerance) {
  // The seed orbit's period against the reference: log10(error) against
  // log10(rtol) over 1e-4 .. 1e-9 (below, the error is at rounding) has a
  // slope near 1 (least squares), and the error stays below rtol.
  const Params p;
  const double exact = static_cast<double>(reference::StickSlip(p).period);
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  int n = 0;
  for (double e = -4; e >= -9; e -= 0.5) {
    double period = 0;
    StickSlipRun(p, Taylor(std::pow(10.0, e)), &period);
    const double err = std::max(std::abs(period - exact) / exact, 1e-16);
    EXPECT_LT(err, std::pow(10.0, e)) << "rtol 1e" << e;
    const double y = std::log10(err);
    sx += e, sy += y, sxx += e * e, sxy += e * y, ++n;
  }
  const double slope = (n * sxy - sx * sy) / (n * sxx - sx * sx);
  EXPECT_GT(slope, 0.8);
  EXPECT_LT(slope, 1.5);
  RecordProperty("slope", std::to_string(slope));
  std::cout << "taylor: slope of log10(period error) against log10(rtol) on [1e-9, 1e-4]: " << slope
            << std::endl;
}

// dP/dp of the section return x' = 0 from (x, 0) by the reference integrator:
// central differences at h and h / 2, Richardson-extrapolated (error O(h^4)),
// measured 2e-12 or better against the column at rtol 1e-13.
double ReferenceDPDp(const Params& base, const std::string& name, double x, double h) {
  auto P = [&](double dp) {
    Params q = base;
    SetParameter(q, name, GetParameter(base, name) + dp);
    const reference::SectionReturn r =
        reference::ReturnToSection(reference::Model(q), x, 1e-18L, 200);
    EXPECT_TRUE(r.ok) << name;
    return static_cast<double>(r.x);
  };
  const double d1 = (P(h) - P(-h)) / (2 * h), d2 = (P(h / 2) - P(-h / 2)) / h;
  return (4 * d2 - d1) / 3;
}

struct ColumnCase {
  const char* name;
  Params p;
  double a;  // section start xbar + a
  std::vector<std::string> params;
};

TEST(Taylor, ParameterColumnMatchesTheReferenceReturnMap) {
  Params cubic;
  cubic.v = 0.42;  // between grazing and Hopf: pure slip
  Params stribeck;
  stribeck.law = LawKind::kStribeck;
  stribeck.beta = 0.02;
  stribeck.v = 0.2;
  Params leine;
  leine.law = LawKind::kLeine;
  leine.beta = 0.01;
  leine.mu_s = 1;
  leine.delta = 3;
  leine.v = 0.4;
  const ColumnCase cases[] = {{"cubic", cubic, 0.05, {"beta", "v", "mu_s", "mu_m", "k5"}},
                              {"stribeck", stribeck, 0.02, {"beta", "v", "mu_s", "mu_k"}},
                              {"leine", leine, 0.02, {"beta", "v", "mu_s"}}};
  for (const ColumnCase& c : cases) {
    const Model m(c.p);
    const double x = m.SteadySliding().x + c.a;
    for (const std::string& name : c.params) {
      BeltFlow flow(m, Taylor(1e-13));
      flow.set_parameter_column(ParameterAxis(name));
      StopRule stop;
      stop.at_section = true;
      stop.switching = false;
      stop.t_max = 200;
      const FlowResult r = flow.Run(0.0, Vec2(x, 0.0), Mode::kSlipBelow, stop, true);
      ASSERT_EQ(r.status, FlowStatus::kSection) << c.name << " " << name;
      ASSERT_TRUE(r.has_dzdp) << c.name << " " << name;
      const double ref = ReferenceDPDp(c.p, name, x, 2e-4);
      EXPECT_NEAR(r.dzdp[0], ref, 1e-11 * std::max(1.0, std::abs(ref))) << c.name << " " << name;
    }
  }
}

// The column's values through switches: tests/flow/parameter_column_test.cpp.
TEST(Taylor, ParameterColumnThroughSwitchesOnTaylorOnly) {
  const Model m{Params()};  // seed set: the stick-slip orbit switches twice
  BeltFlow flow(m, Taylor());
  flow.set_parameter_column(Parameter::kV);
  StopRule stop;
  stop.t_max = 1;
  FlowResult r = flow.Run(0.0, m.ExitPoint(), Mode::kSlipBelow, stop, true);
  EXPECT_TRUE(r.has_dzdp);  // before the first arrival at the belt
  stop.t_max = 30;
  r = flow.Run(0.0, m.ExitPoint(), Mode::kSlipBelow, stop, true);
  EXPECT_GT(r.switches, 0);
  EXPECT_TRUE(r.has_dzdp);  // saltations carry it (System::ContactParameterDerivative)
  EXPECT_THROW(flow.set_parameter_column(ParameterAxis("not_a_parameter")), InvalidArgument);
  Params s;
  s.law = LawKind::kStribeck;
  BeltFlow fs{Model(s), Taylor()};
  EXPECT_THROW(fs.set_parameter_column(Parameter::kVS), InvalidArgument);
  BeltFlow fc{Model(Params()), Cvode()};
  fc.set_parameter_column(Parameter::kV);
  EXPECT_FALSE(fc.Run(0.0, m.ExitPoint(), Mode::kSlipBelow, stop, true).has_dzdp);
}

}  // namespace
}  // namespace stickslip
