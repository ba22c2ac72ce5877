// Branches and special points against closed forms and the reference integrator.
#include "stickslip/continuation/continuation.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "coulomb_damped.hpp"
#include "reference/reference_orbit.hpp"
#include "stickslip/errors.hpp"

namespace stickslip {
namespace {

std::vector<SpecialPoint> Labelled(const ContinuationResult& r, SpecialKind k) {
  std::vector<SpecialPoint> out;
  for (const auto& s : r.special)
    if (s.kind == k) out.push_back(s);
  return out;
}

ContinuationResult Trace(const Params& p, const std::string& param, double from, double to) {
  ContinuationOptions o;
  o.param = ParameterAxis(param);
  o.from = from;
  o.to = to;
  return Continue(p, o);
}

TEST(Continuation, SeedBranchHasOneGrazingAndOneHopfPoint) {
  const Params p;
  const ContinuationResult r = Trace(p, "v", 0.05, 0.5);
  ASSERT_EQ(r.status, ContinuationStatus::kOk) << r.message;
  const auto hb = Labelled(r, SpecialKind::kHopf);
  const auto gr = Labelled(r, SpecialKind::kGrazing);
  ASSERT_EQ(hb.size(), 1u);
  ASSERT_EQ(gr.size(), 1u);
  const double v_max = std::sqrt((p.k1() - 2 * p.beta) / (3 * p.k3()));  // seed (3.16)
  EXPECT_NEAR(hb[0].p, v_max, 1e-7);
  EXPECT_GT(gr[0].p, 0.39);
  EXPECT_LT(gr[0].p, 0.40);
  // GR against the independent long-double integrator.
  EXPECT_NEAR(gr[0].p, static_cast<double>(reference::GrazingSpeed(p, 0.39L, 0.40L)), 1e-9);
  EXPECT_EQ(gr[0].multiplier_before, 0.0);
  EXPECT_GT(gr[0].multiplier_after, 0.3);  // the jump of a discontinuous bifurcation
  EXPECT_TRUE(Labelled(r, SpecialKind::kFold).empty());

  EXPECT_GE(r.points.size(), 100u);
  EXPECT_EQ(r.points.front().p, 0.05);
  EXPECT_EQ(r.points.front().kind, PointKind::kStickSlip);
  for (const auto& pt : r.points) {
    ASSERT_TRUE(std::isfinite(pt.extrema.x_max));
    switch (pt.kind) {
      case PointKind::kStickSlip:
        EXPECT_LE(pt.p, gr[0].p + 1e-12);
        EXPECT_TRUE(pt.stable);
        break;
      case PointKind::kPureSlip:
        EXPECT_GE(pt.p, gr[0].p - 1e-12);
        EXPECT_LE(pt.p, hb[0].p + 1e-12);
        EXPECT_TRUE(pt.stable);
        EXPECT_EQ(pt.t_stick, 0.0);
        break;
      case PointKind::kEquilibrium:
        EXPECT_EQ(pt.stable, pt.p > hb[0].p) << "v = " << pt.p;
        break;
    }
  }
  // x ranges continuous through GR, amplitude to zero at HB.
  const BranchPoint* last_ss = nullptr;
  const BranchPoint* first_ps = nullptr;
  const BranchPoint* last_ps = nullptr;
  for (const auto& pt : r.points) {
    if (pt.kind == PointKind::kStickSlip) last_ss = &pt;
    if (pt.kind == PointKind::kPureSlip && !first_ps) first_ps = &pt;
    if (pt.kind == PointKind::kPureSlip) last_ps = &pt;
  }
  ASSERT_TRUE(last_ss && first_ps && last_ps);
  EXPECT_NEAR(last_ss->extrema.x_max, first_ps->extrema.x_max, 0.02);
  EXPECT_NEAR(last_ss->extrema.x_min, first_ps->extrema.x_min, 0.02);
  EXPECT_NEAR(last_ps->p, hb[0].p, 1e-12);
  EXPECT_EQ(last_ps->extrema.x_max - last_ps->extrema.x_min, 0.0);
  EXPECT_NEAR(last_ps->period, 2 * M_PI, 1e-12);
}

TEST(Continuation, BackwardsGivesTheSameSpecialPoints) {
  const Params p;
  const ContinuationResult f = Trace(p, "v", 0.05, 0.5);
  const ContinuationResult b = Trace(p, "v", 0.5, 0.05);
  ASSERT_EQ(b.status, ContinuationStatus::kOk) << b.message;
  ASSERT_EQ(f.special.size(), b.special.size());
  EXPECT_EQ(b.points.front().p, 0.5);
  for (size_t i = 0; i < f.special.size(); ++i) {
    const SpecialPoint& sf = f.special[i];
    const SpecialPoint& sb = b.special[f.special.size() - 1 - i];
    EXPECT_EQ(sf.kind, sb.kind);
    EXPECT_NEAR(sf.p, sb.p, 1e-9);
  }
}

TEST(Continuation, BetaContinuationHopfAtClosedForm) {
  const Params p;  // v = 0.25
  const ContinuationResult r = Trace(p, "beta", 0.01, 0.3);
  ASSERT_EQ(r.status, ContinuationStatus::kOk) << r.message;
  const auto hb = Labelled(r, SpecialKind::kHopf);
  ASSERT_EQ(hb.size(), 1u);
  EXPECT_NEAR(hb[0].p, (p.k1() - 3 * p.k3() * p.v * p.v) / 2, 1e-9);
  EXPECT_EQ(Labelled(r, SpecialKind::kGrazing).size(), 1u);
}

// Issue 15, item 19: a narrow range just below the Hopf point; the pure-slip
// branch shrinks onto HB 1.2e-4 away, more than 5 % of the range.
TEST(Continuation, NarrowRangeBelowTheHopfPointEndsOnIt) {
  const Params p;
  const double v_max = std::sqrt((p.k1() - 2 * p.beta) / (3 * p.k3()));  // seed (3.16)
  for (double to : {0.441, 0.442}) {
    const ContinuationResult r = Trace(p, "v", 0.44, to);
    ASSERT_EQ(r.status, ContinuationStatus::kOk) << "to " << to << ": " << r.message;
    const auto hb = Labelled(r, SpecialKind::kHopf);
    ASSERT_EQ(hb.size(), 1u);
    EXPECT_NEAR(hb[0].p, v_max, 1e-9);
    bool ends_on_hb = false;
    for (const auto& pt : r.points)
      if (pt.kind == PointKind::kPureSlip && pt.amplitude == 0) ends_on_hb = pt.p == hb[0].p;
    EXPECT_TRUE(ends_on_hb) << "to " << to;
  }
}

// Issue 15, item 19: a range of 1e-10 across HB: the pure-slip branch leaves
// it at amplitudes too small to resolve, so HB alone stands for it.
TEST(Continuation, TinyRangeAcrossTheHopfPoint) {
  const Params p;
  const double v_max = std::sqrt((p.k1() - 2 * p.beta) / (3 * p.k3()));  // seed (3.16)
  const ContinuationResult r = Trace(p, "v", 0.4409585518, 0.4409585519);
  ASSERT_EQ(r.status, ContinuationStatus::kOk) << r.message;
  const auto hb = Labelled(r, SpecialKind::kHopf);
  ASSERT_EQ(hb.size(), 1u);
  EXPECT_NEAR(hb[0].p, v_max, 1e-11);
  for (const auto& pt : r.points) {
    EXPECT_GE(pt.p, 0.4409585518);
    EXPECT_LE(pt.p, 0.4409585519);
  }
}

// One HB at the closed form (seed 3.16) and one GR at the reference's grazing speed.
void ExpectSeedStructure(const Params& p, const ContinuationResult& r) {
  ASSERT_EQ(r.status, ContinuationStatus::kOk) << r.message;
  const auto hb = Labelled(r, SpecialKind::kHopf);
  const auto gr = Labelled(r, SpecialKind::kGrazing);
  ASSERT_EQ(hb.size(), 1u);
  ASSERT_EQ(gr.size(), 1u);
  EXPECT_NEAR(hb[0].p, std::sqrt((p.k1() - 2 * p.beta) / (3 * p.k3())), 1e-9);
  EXPECT_NEAR(gr[0].p, static_cast<double>(reference::GrazingSpeed(p, 0.39L, 0.40L)), 1e-9);
}

// Issue 15, item 18: the largest step allowed still ends the branch on HB,
// with the same special points as the default step.
TEST(Continuation, LargestStepKeepsTheSeedStructure) {
  const Params p;
  ContinuationOptions o;
  o.max_step = 0.25;
  const ContinuationResult r = Continue(p, o);
  ExpectSeedStructure(p, r);
}

// Issue 15, item 19: a range far wider than the branch (--to 1e6) does not
// set the probes and steps beside GR: the same special points as over 0.05..0.5.
// On the default integrator (Taylor): its grid scan at v >= 1e4 once looped
// for ever at the stick exit (Flow.EventsRepeatingAtOneTimeFailInsteadOfLooping).
TEST(Continuation, VeryWideRangeKeepsTheSeedStructure) {
  const Params p;
  ContinuationOptions o;
  o.param = ParameterAxis("v");
  o.from = 0.05;
  o.to = 1e6;
  ExpectSeedStructure(p, Continue(p, o));
}

// Issue 15, item 18: a tolerance looser than the tested range is flagged.
TEST(Continuation, LooseToleranceIsWarned) {
  const Params p;
  ContinuationOptions o;
  o.orbit.flow.rtol = 1e-2;
  o.orbit.flow.atol = 1e-4;
  o.max_step = 0.1;
  const ContinuationResult loose = Continue(p, o);
  ASSERT_EQ(loose.warnings.size(), 1u);
  EXPECT_NE(loose.warnings[0].find("rtol = 0.01"), std::string::npos) << loose.warnings[0];
  o.orbit.flow.rtol = 1e-4;
  o.orbit.flow.atol = 1e-6;
  EXPECT_TRUE(Continue(p, o).warnings.empty());
}

TEST(Continuation, StribeckSubcriticalHopfUnstableBranchAndFold) {
  Params p;
  p.law = LawKind::kStribeck;
  p.mu_k = 0.25;
  p.v_s = 0.5;
  const ContinuationResult r = Trace(p, "v", 0.3, 0.8);
  ASSERT_EQ(r.status, ContinuationStatus::kOk) << r.message;
  const auto hb = Labelled(r, SpecialKind::kHopf);
  const auto lp = Labelled(r, SpecialKind::kFold);
  const auto gr = Labelled(r, SpecialKind::kGrazing);
  ASSERT_EQ(hb.size(), 1u);
  ASSERT_EQ(lp.size(), 1u);
  ASSERT_EQ(gr.size(), 1u);
  EXPECT_NEAR(hb[0].p, -p.v_s * std::log(2 * p.beta * p.v_s / (p.mu_s - p.mu_k)), 1e-9);
  EXPECT_NE(hb[0].description.find("subcritical"), std::string::npos);
  EXPECT_NEAR(lp[0].p, gr[0].p, 1e-9);  // the fold is the grazing point
  EXPECT_GT(lp[0].p, hb[0].p);
  // Between HB and LP: stable stick-slip, unstable pure slip, stable equilibrium.
  const double mid = 0.5 * (hb[0].p + lp[0].p);
  bool ss = false, ps = false, eq = false;
  for (const auto& pt : r.points) {
    if (std::abs(pt.p - mid) > 0.03) continue;
    if (pt.kind == PointKind::kStickSlip) ss = ss || pt.stable;
    if (pt.kind == PointKind::kPureSlip) {
      EXPECT_FALSE(pt.stable) << "v = " << pt.p;
      EXPECT_GT(pt.multiplier, 1.0);
      ps = true;
    }
    if (pt.kind == PointKind::kEquilibrium) eq = eq || pt.stable;
  }
  EXPECT_TRUE(ss && ps && eq);
  // Backwards: same points.
  const ContinuationResult b = Trace(p, "v", 0.8, 0.3);
  ASSERT_EQ(b.status, ContinuationStatus::kOk) << b.message;
  ASSERT_EQ(b.special.size(), r.special.size());
  for (const auto& s : b.special)
    EXPECT_NEAR(s.p, s.kind == SpecialKind::kHopf ? hb[0].p : gr[0].p, 1e-9);
}

TEST(Continuation, CancellationKeepsThePointsSoFar) {
  ContinuationOptions o;
  int calls = 0;
  o.progress = [&](const BranchPoint&) { ++calls; };
  o.cancelled = [&] { return calls >= 10; };
  const ContinuationResult r = Continue(Params(), o);
  EXPECT_EQ(r.status, ContinuationStatus::kCancelled);
  EXPECT_TRUE(r.partial());
  int periodic = 0;
  for (const auto& pt : r.points) periodic += pt.kind != PointKind::kEquilibrium;
  EXPECT_GE(periodic, 9);
  EXPECT_LT(periodic, 20);
}

TEST(Continuation, InvalidOptionsThrowNamingTheValue) {
  ContinuationOptions o;
  EXPECT_THROW(ParameterAxis("gamma"), InvalidArgument);  // a name is parsed once
  o.param = ParameterAxis("v");
  o.from = o.to = 0.3;
  EXPECT_THROW(Continue(Params(), o), InvalidArgument);
  o.from = -0.1;
  try {
    Continue(Params(), o);
    FAIL();
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find("v = -0.1"), std::string::npos) << e.what();
  }
  o.param = ParameterAxis("delta");  // not a cubic-law parameter
  o.from = 1;
  o.to = 2;
  EXPECT_THROW(Continue(Params(), o), InvalidArgument);
}

}  // namespace
}  // namespace stickslip

namespace stickslip {
namespace {

// The branch keeps its structure (one GR, one HB, stick-slip then pure slip)
// from rtol 1e-3 to 1e-12, Taylor, Adams and BDF: grazing touches where x' = v to
// rounding once broke GR location at 1e-6 .. 1e-8.
TEST(Continuation, SameStructureAtEveryTolerance) {
  const Params p;
  const double v_gr = static_cast<double>(reference::GrazingSpeed(p, 0.39L, 0.40L));
  // Taylor (the default), then CVODE with Adams and BDF.
  const std::pair<Integrator, Method> solvers[] = {{Integrator::kTaylor, Method::kAdams},
                                                   {Integrator::kCvode, Method::kAdams},
                                                   {Integrator::kCvode, Method::kBdf}};
  for (const auto& [in, m] : solvers) {
    for (double rtol = 1e-3; rtol > 1e-12 * 0.5; rtol *= 0.1) {
      ContinuationOptions o;
      o.orbit.flow.integrator = in;
      o.orbit.flow.method = m;
      o.orbit.flow.rtol = rtol;
      o.orbit.flow.atol = rtol * 1e-2;
      const ContinuationResult r = Continue(p, o);
      const std::string at =
          std::string(Name(in)) + " " + Name(m) + " rtol " + std::to_string(rtol);
      ASSERT_EQ(r.status, ContinuationStatus::kOk) << at << ": " << r.message;
      const auto gr = Labelled(r, SpecialKind::kGrazing);
      ASSERT_EQ(gr.size(), 1u) << at;
      EXPECT_EQ(Labelled(r, SpecialKind::kHopf).size(), 1u) << at;
      EXPECT_TRUE(Labelled(r, SpecialKind::kFold).empty()) << at;
      EXPECT_NEAR(gr[0].p, v_gr, 1000 * rtol) << at;
      int pure = 0;
      for (const auto& pt : r.points) pure += pt.kind == PointKind::kPureSlip;
      EXPECT_GE(pure, 10) << at;
    }
  }
}

// The stribeck study's subcritical branch (studies/stribeck.ini) keeps HB, GR,
// LP in that order at loose tolerances: the unstable pure-slip branch from HB
// grows to GR (the reference integrator's grazing speed) and folds back there
// as stick slip. HB: 2 beta + mu'(v) = 0, v = v_s ln 3. At rtol 1e-4 and 1e-6
// the fixed-p shooting beside GR once took a point that sticks for an orbit
// (Taylor), and at 1e-4 (CVODE) GR was taken for a touch inside the stick band.
TEST(Continuation, SubcriticalStribeckKeepsItsFoldAtLooseTolerances) {
  Params p;
  p.law = LawKind::kStribeck;
  p.mu_k = 0.25;
  p.v_s = 0.5;
  const double v_hb = p.v_s * std::log(3.0);
  const double v_gr = static_cast<double>(reference::GrazingSpeed(p, 0.65L, 0.655L, 1e-11L));
  for (Integrator in : {Integrator::kTaylor, Integrator::kCvode}) {
    for (double rtol : {1e-4, 1e-6, 1e-8}) {
      ContinuationOptions o;
      o.from = 0.3;
      o.to = 0.8;
      o.orbit.flow.integrator = in;
      o.orbit.flow.rtol = rtol;
      o.orbit.flow.atol = rtol * 1e-2;
      const ContinuationResult r = Continue(p, o);
      const std::string at = std::string(Name(in)) + " rtol " + std::to_string(rtol);
      ASSERT_EQ(r.status, ContinuationStatus::kOk) << at << ": " << r.message;
      ASSERT_EQ(r.special.size(), 3u) << at;
      EXPECT_EQ(r.special[0].kind, SpecialKind::kHopf) << at;
      EXPECT_EQ(r.special[1].kind, SpecialKind::kGrazing) << at;
      EXPECT_EQ(r.special[2].kind, SpecialKind::kFold) << at;
      EXPECT_NEAR(r.special[0].p, v_hb, 1e-9) << at;
      EXPECT_NEAR(r.special[1].p, v_gr, 10 * rtol) << at;
      EXPECT_EQ(r.special[2].p, r.special[1].p) << at;
      // The pure-slip branch lies between HB and GR (to the tolerance), below the belt.
      int pure = 0;
      for (const auto& pt : r.points) {
        if (pt.kind != PointKind::kPureSlip) continue;
        ++pure;
        EXPECT_GE(pt.p, v_hb - 10 * rtol) << at;
        EXPECT_LE(pt.p, r.special[1].p) << at;
        EXPECT_LT(pt.extrema.xdot_max, pt.p) << at;
      }
      EXPECT_GE(pure, 10) << at;
    }
  }
}

}  // namespace
}  // namespace stickslip

namespace stickslip {
namespace {

// A stick-slip branch that touches neither `from` nor a Hopf point: found by the
// first-return check on the grid, followed both ways to its two grazing
// points, which an unstable pure-slip branch joins (a loop, traced once).
TEST(Continuation, FindsBranchesAwayFromTheStartAndTheHopfPoints) {
  Params p;
  p.law = LawKind::kStribeck;
  p.mu_k = 0.25;
  p.v_s = 0.5;
  p.v = 0.6;
  const ContinuationResult r = Trace(p, "v_s", 0.1, 1.5);
  ASSERT_EQ(r.status, ContinuationStatus::kOk) << r.message;
  const auto gr = Labelled(r, SpecialKind::kGrazing);
  ASSERT_EQ(gr.size(), 2u);
  EXPECT_EQ(Labelled(r, SpecialKind::kFold).size(), 2u);
  int ss = 0, ps = 0;
  for (const auto& pt : r.points) {
    if (pt.kind == PointKind::kStickSlip) {
      ++ss;
      EXPECT_GE(pt.p, gr[0].p - 1e-9);
      EXPECT_LE(pt.p, gr[1].p + 1e-9);
    }
    if (pt.kind == PointKind::kPureSlip) {
      ++ps;
      EXPECT_FALSE(pt.stable);
    }
  }
  EXPECT_GT(ss, 20);
  EXPECT_GT(ps, 5);
  // Each grazing point against the stick-slip orbit just inside it.
  for (const auto& g : gr) {
    const double inside = g.p + (g.p < 0.5 ? 1e-4 : -1e-4);
    Params q = p;
    q.v_s = inside;
    OrbitFinder f{Model(q), OrbitOptions()};
    const OrbitResult o = f.StickSlip();
    ASSERT_TRUE(o.ok()) << "v_s = " << inside << ": " << o.message;
    EXPECT_LT(o.orbit.t_stick, 0.05);
  }
}

}  // namespace
}  // namespace stickslip

namespace stickslip {
namespace {

// The coulomb scene, beta = 0: every point of the branch against the exact period
// pi + 2 atan(v/(mu_s - mu_k)) + 2 (mu_s - mu_k)/v.
TEST(Continuation, CoulombBranchPeriodsAreExact) {
  Params p;
  p.law = LawKind::kCoulomb;
  p.beta = 0;
  p.mu_k = 0.25;
  const ContinuationResult r = Trace(p, "v", 0.02, 1.0);
  ASSERT_EQ(r.status, ContinuationStatus::kOk) << r.message;
  int n = 0;
  for (const auto& pt : r.points) {
    if (pt.kind != PointKind::kStickSlip) continue;
    ++n;
    const double d = p.mu_s - p.mu_k;
    EXPECT_NEAR(pt.period, M_PI + 2 * std::atan(pt.p / d) + 2 * d / pt.p, 1e-8) << "v = " << pt.p;
  }
  EXPECT_GE(n, 100);
}

}  // namespace
}  // namespace stickslip

namespace stickslip {
namespace {

int CountKind(const ContinuationResult& r, PointKind k) {
  int n = 0;
  for (const auto& pt : r.points) n += pt.kind == k;
  return n;
}

// Inside a bistable band a start finds the unstable pure-slip orbit too (by
// the scan of the section), whichever way the range runs; its rows at the
// range ends against the reference integrator's orbit.
TEST(Continuation, StartsABranchFromEveryOrbitAtTheStartInEitherDirection) {
  struct Case {
    LawKind law;
    double beta, mu_s, lo, hi;
  };
  for (const Case& c : {Case{LawKind::kStribeck, 0.02, 0.4, 1.3, 1.31},
                        Case{LawKind::kLeine, 0.05, 1.0, 2.0, 2.01}}) {
    Params p;
    p.law = c.law;
    p.beta = c.beta;
    p.mu_s = c.mu_s;
    for (bool forward : {true, false}) {
      SCOPED_TRACE(std::string(Name(c.law)) + (forward ? " forward" : " backward"));
      const ContinuationResult r = forward ? Trace(p, "v", c.lo, c.hi) : Trace(p, "v", c.hi, c.lo);
      ASSERT_EQ(r.status, ContinuationStatus::kOk) << r.message;
      EXPECT_GT(CountKind(r, PointKind::kStickSlip), 10);
      ASSERT_GT(CountKind(r, PointKind::kPureSlip), 10);
      for (const auto& pt : r.points) {
        if (pt.kind != PointKind::kPureSlip) continue;
        EXPECT_FALSE(pt.stable) << "v = " << pt.p;
        if (pt.p != c.lo && pt.p != c.hi) continue;
        Params q = p;
        q.v = pt.p;
        const reference::Real xbar = reference::Law(q).Mu(q.v);
        const reference::PureSlipOrbit ref = reference::PureSlip(q, xbar + pt.amplitude);
        ASSERT_TRUE(ref.found);
        EXPECT_NEAR(pt.amplitude, static_cast<double>(ref.x_section - xbar), 1e-8);
        EXPECT_NEAR(pt.period, static_cast<double>(ref.period), 1e-8);
        EXPECT_NEAR(pt.multiplier, static_cast<double>(ref.multiplier), 1e-7);
      }
    }
  }
}

// Coulomb law with damping: the stick-slip branch ends where the orbit
// disappears (closed form of the damped oscillator, coulomb_damped.hpp); the
// end row is the stick-slip orbit it is, with its stick; no pure-slip row;
// forward and backward runs agree.
TEST(Continuation, CoulombWithDampingEndsWhereTheOrbitDisappears) {
  Params p;
  p.law = LawKind::kCoulomb;
  p.beta = 0.05;
  const double v_end = static_cast<double>(coulomb_damped::EndSpeed(p.mu_s, p.mu_k, p.beta));
  const double t_end = static_cast<double>(coulomb_damped::EndPeriod(p.mu_s, p.mu_k, p.beta));
  std::vector<BranchPoint> ends;
  for (bool forward : {true, false}) {
    SCOPED_TRACE(forward ? "forward" : "backward");
    const ContinuationResult r = forward ? Trace(p, "v", 0.05, 0.5) : Trace(p, "v", 0.5, 0.05);
    ASSERT_EQ(r.status, ContinuationStatus::kOk) << r.message;
    EXPECT_EQ(CountKind(r, PointKind::kPureSlip), 0);
    const auto gr = Labelled(r, SpecialKind::kGrazing);
    ASSERT_EQ(gr.size(), 1u);
    EXPECT_TRUE(Labelled(r, SpecialKind::kFold).empty());
    EXPECT_NEAR(gr[0].p, v_end, 1e-9);
    EXPECT_NE(gr[0].description.find("disappears"), std::string::npos) << gr[0].description;
    EXPECT_NEAR(gr[0].period, t_end, 1e-7);
    const BranchPoint* end = nullptr;
    for (const auto& pt : r.points) {
      if (pt.kind == PointKind::kStickSlip && std::abs(pt.p - gr[0].p) < 1e-12) end = &pt;
    }
    ASSERT_NE(end, nullptr);
    EXPECT_NEAR(end->period, t_end, 1e-7);
    EXPECT_NEAR(end->t_stick, (p.mu_s - p.mu_k) / v_end, 1e-7);  // stick from mu_k - 2 beta v
    for (const auto& pt : r.points) {
      if (pt.kind == PointKind::kStickSlip) {
        EXPECT_LE(pt.p, gr[0].p + 1e-12);
      }
    }
    ends.push_back(*end);
  }
  EXPECT_NEAR(ends[0].p, ends[1].p, 1e-10);
  EXPECT_NEAR(ends[0].extrema.x_max, ends[1].extrema.x_max, 1e-9);
  EXPECT_NEAR(ends[0].extrema.x_min, ends[1].extrema.x_min, 1e-9);
}

// The grazing point's row and description do not depend on which way the
// continuation crosses it.
TEST(Continuation, GrazingLabelsDoNotDependOnTheDirection) {
  Params p;
  p.law = LawKind::kStribeck;
  const ContinuationResult f = Trace(p, "v", 0.3, 0.8), b = Trace(p, "v", 0.8, 0.3);
  ASSERT_EQ(f.status, ContinuationStatus::kOk) << f.message;
  ASSERT_EQ(b.status, ContinuationStatus::kOk) << b.message;
  for (SpecialKind k : {SpecialKind::kGrazing, SpecialKind::kFold}) {
    const auto sf = Labelled(f, k), sb = Labelled(b, k);
    ASSERT_EQ(sf.size(), 1u);
    ASSERT_EQ(sb.size(), 1u);
    EXPECT_NEAR(sf[0].p, sb[0].p, 1e-10);
    EXPECT_EQ(sf[0].description, sb[0].description);
    EXPECT_EQ(sf[0].multiplier_before, sb[0].multiplier_before);
    EXPECT_NEAR(sf[0].multiplier_after, sb[0].multiplier_after, 1e-8);
  }
  auto gr_row = [](const ContinuationResult& r, double p_gr) {
    for (const auto& pt : r.points)
      if (std::abs(pt.p - p_gr) < 1e-12 && pt.kind != PointKind::kEquilibrium) return pt;
    return BranchPoint{};
  };
  const BranchPoint rf = gr_row(f, Labelled(f, SpecialKind::kGrazing)[0].p);
  const BranchPoint rb = gr_row(b, Labelled(b, SpecialKind::kGrazing)[0].p);
  EXPECT_EQ(rf.kind, PointKind::kStickSlip);
  EXPECT_EQ(rb.kind, PointKind::kStickSlip);
  EXPECT_EQ(rf.multiplier, rb.multiplier);
  EXPECT_NEAR(rf.period, rb.period, 1e-8);
}

// Stick-slip rows at the default options, against the reference's orbit at
// each row's p: period and x range within 1e-12 relative (to the period, to
// max |x| on the orbit). Leine et al.'s scene at small v is the worst found
// over the shipped studies (ss_accuracy, docs/validation.md).
TEST(Continuation, StickSlipRowsAtTheDefaultsMatchTheReferenceTo1e12) {
  Params seed, stribeck, leine;
  stribeck.law = LawKind::kStribeck;
  leine.law = LawKind::kLeine, leine.beta = 0, leine.mu_s = 1;
  const struct {
    Params p;
    double from, to;
  } cases[] = {{seed, 0.2, 0.3}, {stribeck, 0.3, 0.4}, {leine, 0.07, 0.1}};
  for (const auto& c : cases) {
    SCOPED_TRACE(Name(c.p.law));
    const ContinuationResult r = Trace(c.p, "v", c.from, c.to);
    ASSERT_EQ(r.status, ContinuationStatus::kOk) << r.message;
    int rows = 0;
    for (const auto& pt : r.points) {
      if (pt.kind != PointKind::kStickSlip) continue;
      ++rows;
      Params q = c.p;
      q.v = pt.p;
      const reference::StickSlipOrbit ref = reference::StickSlip(q);
      ASSERT_TRUE(ref.found) << "v = " << pt.p;
      const double T = static_cast<double>(ref.period);
      const double scale = static_cast<double>(std::max(std::abs(ref.x_min), std::abs(ref.x_max)));
      EXPECT_NEAR(pt.period, T, 1e-12 * T) << "v = " << pt.p;
      EXPECT_NEAR(pt.extrema.x_min, static_cast<double>(ref.x_min), 1e-12 * scale)
          << "v = " << pt.p;
      EXPECT_NEAR(pt.extrema.x_max, static_cast<double>(ref.x_max), 1e-12 * scale)
          << "v = " << pt.p;
    }
    EXPECT_GT(rows, 40);
  }
}

// Pure-slip rows next to a Hopf point at the default options, against the
// reference's fixed point: the amplitude at the row's p is ill-conditioned
// there (da/dp ~ 1 / a), so a corrector that stops on its step norm in (a, p)
// left it 3e-11 .. 1e-9 off; each row is polished at fixed p.
TEST(Continuation, PureSlipRowsNextToAHopfPointMatchTheReference) {
  struct Case {
    LawKind law;
    double beta, mu_s;
    const char* param;
    double from, to;
  };
  for (const Case& c : {Case{LawKind::kCubic, 0.05, 0.4, "beta", 0.17, 0.16},
                        Case{LawKind::kStribeck, 0.05, 0.4, "v", 0.549, 0.555},
                        Case{LawKind::kLeine, 0.05, 1.0, "v", 1.5, 1.49}}) {
    SCOPED_TRACE(Name(c.law));
    Params p;
    p.law = c.law, p.beta = c.beta, p.mu_s = c.mu_s;
    const ContinuationResult r = Trace(p, c.param, c.from, c.to);
    ASSERT_EQ(r.status, ContinuationStatus::kOk) << r.message;
    int rows = 0;
    for (const auto& pt : r.points) {
      if (pt.kind != PointKind::kPureSlip || pt.amplitude == 0) continue;
      ++rows;
      Params q = p;
      SetParameter(q, c.param, pt.p);
      const reference::Real xbar = reference::Law(q).Mu(q.v);
      const reference::PureSlipOrbit ref = reference::PureSlip(q, xbar + pt.amplitude);
      ASSERT_TRUE(ref.found) << c.param << " = " << pt.p;
      EXPECT_NEAR(pt.amplitude, static_cast<double>(ref.x_section - xbar), 1e-11)
          << c.param << " = " << pt.p << ", a = " << pt.amplitude;
      EXPECT_NEAR(pt.period, static_cast<double>(ref.period), 1e-12 * pt.period)
          << c.param << " = " << pt.p;
    }
    EXPECT_GT(rows, 3);
  }
}

}  // namespace
}  // namespace stickslip
