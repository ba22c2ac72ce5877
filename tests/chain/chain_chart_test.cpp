// The chart of two unequal blocks (m2 = 1.3, studies/chain2.ini otherwise)
// in (v, kc) (ChartSystem, system_chart.hpp): steady sliding's HB where the
// blocks' damping c + mu'(v) vanishes (closed form), and an NS curve of the
// stick-slip orbit checked against one-parameter runs of the branch driver,
// which locate NS by bisection on the sign of its test along the branch.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>
#include <vector>

#include "chain/chain.hpp"
#include "stickslip/chart/response_grid.hpp"
#include "stickslip/chart/system_chart.hpp"
#include "stickslip/equilibria/steady_branch.hpp"
#include "stickslip/equilibria/steady_sliding.hpp"
#include "stickslip/orbits/settle.hpp"
#include "stickslip/systems/belt/model.hpp"

namespace stickslip::chain {
namespace {

Chain Unequal(double v, double kc) {
  Params p;  // the seed's cubic law, beta 0.05
  p.v = v;
  ChainParams c = Uniform(2, p, kc);
  c.blocks[1].m = 1.3;
  return Chain(c);
}

SystemChartOptions Plane(const System& s) {
  SystemChartOptions o;
  o.plane.p1 = s.ParameterIndex("v"), o.plane.p2 = s.ParameterIndex("kc");
  o.plane.from1 = 0.1, o.plane.to1 = 0.5, o.plane.from2 = 0.1, o.plane.to2 = 1;
  return o;
}

// The NS point of the branch in kc at v from the attractor at kc = 0.55.
OrbitRow TorusPoint(double v, PoincareSection* section) {
  const Chain s = Unequal(v, 0.55);
  SettleOptions so;
  so.shooting = Plane(s).branch.shooting;
  Eigen::VectorXd z0 = SteadySliding(s).z;
  z0[0] += 0.5;
  const SettledOrbit st = SettleOnStickSlip(s, z0, so);
  EXPECT_TRUE(st.found) << st.message;
  OrbitBranchOptions o(so.shooting.flow);
  o.palc.ds = o.palc.ds_max = 0.01;
  const OrbitBranch b =
      ContinueOrbits(s, s.ParameterIndex("kc"), st.orbit.start, st.section, 0.1, o);
  *section = b.section;
  for (const OrbitRow& r : b.special)
    if (r.label == SpecialKind::kTorus) return r;
  ADD_FAILURE() << "no NS in kc at v = " << v;
  return {};
}

// With unequal damping too (c2 = 0.15) the HB curve is where the Hurwitz
// determinant of det(M l^2 + D l + K) vanishes (Routh-Hurwitz, the quartic
// a4 l^4 + ... + a0: a1 a2 a3 - a0 a3^2 - a4 a1^2 = 0), D = diag(c_i + mu'(v)).
TEST(ChainChart, HopfCurveIsTheHurwitzDeterminantsZero) {
  ChainParams c = Unequal(0.3, 0.5).params();
  c.blocks[1].c = 0.15;
  const Chain s(c);
  SteadyBranchOptions so;
  so.points = 201;
  const SteadyBranch line = ContinueSteadySliding(s, s.ParameterIndex("v"), 0.6, so);
  ASSERT_FALSE(line.special.empty());
  SystemChartOptions o = Plane(s);
  const SystemCurve hb = TraceHopfCurve(s, o, line.special[0].p, 0.5, 1);
  EXPECT_EQ(hb.ends.Text(), "border / border");
  ASSERT_GT(hb.points.size(), 20u);
  auto hurwitz = [](double v, double kc) {
    const double mu1 = -0.45 + 1.8 * v * v;  // mu'(v), the cubic law
    const double m1 = 1, m2 = 1.3, d1 = 0.1 + mu1, d2 = 0.15 + mu1, k11 = 1 + kc, k22 = 1 + kc;
    const double a4 = m1 * m2, a3 = m1 * d2 + m2 * d1, a2 = m1 * k22 + m2 * k11 + d1 * d2,
                 a1 = d1 * k22 + d2 * k11, a0 = k11 * k22 - kc * kc;
    return a1 * a2 * a3 - a0 * a3 * a3 - a4 * a1 * a1;
  };
  for (const SystemCurvePoint& p : hb.points) {  // the root in v at the point's kc, by bisection
    double lo = p.p1 - 1e-6, hi = p.p1 + 1e-6;
    ASSERT_LT(hurwitz(lo, p.p2) * hurwitz(hi, p.p2), 0) << "kc " << p.p2;
    for (int i = 0; i < 60; ++i)
      (hurwitz(lo, p.p2) * hurwitz((lo + hi) / 2, p.p2) <= 0 ? hi : lo) = (lo + hi) / 2;
    EXPECT_NEAR(p.p1, (lo + hi) / 2, 1e-12) << "kc " << p.p2;
    EXPECT_GT(p.orbit.period, 0) << "a complex pair";
  }
}

// A curve cut short by the cancel hook says so at both ends (the way followed
// and the way back not taken); it read "border / border".
TEST(ChainChart, ACancelledCurveEndsCancelled) {
  const Chain s = Unequal(0.3, 0.5);
  SteadyBranchOptions so;
  so.points = 201;
  const SteadyBranch line = ContinueSteadySliding(s, s.ParameterIndex("v"), 0.6, so);
  ASSERT_FALSE(line.special.empty());
  SystemChartOptions o = Plane(s);
  int polls = 0;
  o.cancelled = [&polls] { return ++polls > 300; };
  o.branch.palc.cancelled = o.cancelled;
  const SystemCurve hb = TraceHopfCurve(s, o, line.special[0].p, 0.5, 1);
  // Cut while its points were sampled (296 polls in): 96 of its 102 points.
  EXPECT_EQ(hb.ends.last.kind, CurveEndKind::kCancelled) << hb.ends.Text();
  EXPECT_GT(hb.points.size(), 0u);
  EXPECT_LT(hb.points.size(), 102u);
  polls = 0;
  o.cancelled = [&polls] { return ++polls > 100; };  // while it was traced
  o.branch.palc.cancelled = o.cancelled;
  EXPECT_EQ(TraceHopfCurve(s, o, line.special[0].p, 0.5, 1).ends.Text(), "cancelled / cancelled");
}

// An orbit curve cut at any moment never reads as whole: with fewer points
// than the uncut curve, one of its ends is `cancelled` (one cut while its
// points were sampled read as the uncut curve's ends).
TEST(ChainChart, ACancelledOrbitCurveSaysSo) {
  PoincareSection section;
  const OrbitRow seed = TorusPoint(0.3, &section);
  const Chain s = Unequal(0.3, seed.p);
  SystemChartOptions counted = Plane(s);
  long total = 0;  // the uncut trace's polls of the hook: cuts at fractions of them
  counted.cancelled = [&total] { return ++total < 0; };
  counted.branch.palc.cancelled = counted.cancelled;
  const SystemCurve whole =
      TraceOrbitCurve(s, counted, CurveKind::kTorus, seed.start, 0.3, seed.p, section, 0);
  ASSERT_GT(whole.points.size(), 10u);
  for (long cut : {total / 1000, total / 10, total / 2, total * 9 / 10, total - 2}) {
    SystemChartOptions o = Plane(s);
    long polls = 0;
    o.cancelled = [&polls, cut] { return ++polls > cut; };
    o.branch.palc.cancelled = o.cancelled;
    const SystemCurve c =
        TraceOrbitCurve(s, o, CurveKind::kTorus, seed.start, 0.3, seed.p, section, 0);
    if (c.points.size() < whole.points.size())
      EXPECT_NE(c.ends.Text().find("cancelled"), std::string::npos)
          << "cut after " << cut << " polls: " << c.points.size() << " points, ends "
          << c.ends.Text();
    else
      EXPECT_EQ(c.ends.Text(), whole.ends.Text()) << "cut after " << cut;
    std::printf("[ measured ] cut after %ld of %ld polls: %zu of %zu points, ends %s\n", cut, total,
                c.points.size(), whole.points.size(), c.ends.Text().c_str());
  }
}

// The response grid (response_grid.hpp) below the NS curve, off the cells
// next to it: there the stick-slip orbit the curve follows is unstable, so
// no cell reaches it (the attractor is the torus: quasi-periodic, locked at
// a long period, or chaotic). Above the curve the rows carry whichever of
// the coexisting attractors they reached first (here m = 3 orbits), so no
// class is asserted there.
void TorusBelowTheCurve(const System& s, const SystemCurve& ns) {
  std::vector<std::pair<double, double>> curve;  // (v, kc)
  for (const SystemCurvePoint& p : ns.points) curve.emplace_back(p.p1, p.p2);
  std::sort(curve.begin(), curve.end());
  const int sticks = ns.points[0].orbit.sticks;
  SystemPlane pl = Plane(s).plane;
  pl.from1 = 0.24, pl.to1 = 0.38, pl.from2 = 0.1, pl.to2 = 0.45;
  ResponseOptions o;
  o.n1 = 7, o.n2 = 10;
  const ResponseGrid g = Responses(s, pl, o);
  ASSERT_EQ(g.failed, 0) << g.failure;
  const double h = (pl.to2 - pl.from2) / o.n2;
  int below = 0, torus = 0;
  for (int i = 0; i < g.n1; ++i) {
    const auto hi = std::lower_bound(curve.begin(), curve.end(), std::make_pair(g.x1[i], 0.0));
    ASSERT_TRUE(hi != curve.begin() && hi != curve.end()) << "v " << g.x1[i];
    const auto lo = hi - 1;
    const double kc =
        lo->second + (hi->second - lo->second) * (g.x1[i] - lo->first) / (hi->first - lo->first);
    for (int j = 0; j < g.n2 && g.x2[j] < kc - h; ++j) {
      const Attractor& a = g.at(i, j);
      EXPECT_FALSE(a.kind == AttractorKind::kPeriodic && a.m == 1 && a.sticks == sticks)
          << "v " << g.x1[i] << ", kc " << g.x2[j];
      torus += a.kind == AttractorKind::kUndecided || a.kind == AttractorKind::kChaotic ||
               (a.kind == AttractorKind::kPeriodic && a.m >= 5);
      ++below;
    }
  }
  std::printf("[ measured ] %d cells below the NS curve, %d of them on a torus, in %.2f s\n", below,
              torus, g.seconds);
  EXPECT_GE(below, 10);
  EXPECT_GE(torus, below - 2);
}

TEST(ChainChart, TorusCurveMeetsTheBranchTorusPoints) {
  PoincareSection section;
  const OrbitRow seed = TorusPoint(0.3, &section);
  const Chain s = Unequal(0.3, seed.p);
  const SystemCurve ns =
      TraceOrbitCurve(s, Plane(s), CurveKind::kTorus, seed.start, 0.3, seed.p, section, 0);
  ASSERT_GT(ns.points.size(), 10u);
  // A complex pair on the unit circle at every point.
  for (const SystemCurvePoint& p : ns.points) {
    double off = 1;
    for (const auto& m : p.orbit.multipliers)
      if (std::abs(m.imag()) > 1e-3) off = std::min(off, std::abs(std::abs(m) - 1));
    EXPECT_LT(off, 1e-7) << "v " << p.p1;
  }
  // At v = 0.35 (a point of the curve nearest it), the branch in kc there has
  // its NS at the curve's kc.
  const SystemCurvePoint* near = &ns.points[0];
  for (const SystemCurvePoint& p : ns.points)
    if (std::abs(p.p1 - 0.35) < std::abs(near->p1 - 0.35)) near = &p;
  ASSERT_LT(std::abs(near->p1 - 0.35), 0.02);
  const OrbitRow at = TorusPoint(near->p1, &section);
  EXPECT_NEAR(at.p, near->p2, 1e-8);
  TorusBelowTheCurve(s, ns);
}

}  // namespace
}  // namespace stickslip::chain
