// The one branch driver (orbit_branch.hpp) on two systems and two kinds of
// section, against references computed another way:
//  - the forced oscillator's stroboscopic branch: Den Hartog's (1931) closed
//    form on every non-stop row, and both period doublings of the seed study
//    against the sign changes of det(Phi + I) of the independent long-double
//    stroboscopic map (reference/forced_lyapunov.hpp);
//  - the belt's pure-slip branch on the section x' = 0: every row against the
//    long-double reference orbit and its trace-formula multiplier, and its
//    change of switching sequence at the grazing point the belt's own driver
//    locates from the stick-slip side.
#include "stickslip/continuation/orbit_branch.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "forced_flip_reference.hpp"
#include "forced_reference.hpp"
#include "reference/reference_orbit.hpp"
#include "stickslip/continuation/continuation.hpp"
#include "stickslip/errors.hpp"
#include "stickslip/systems/belt/model.hpp"
#include "stickslip/systems/forced/forced.hpp"

namespace stickslip {
namespace {

OrbitBranchOptions Tight() {
  OrbitBranchOptions o;
  o.shooting.flow.rtol = o.shooting.flow.atol = 1e-14;
  return o;
}

// A belt state (x, x') and a forced one (x, x', theta = 0), slipping below.
FlowPoint At(double x, double xdot) {
  return {0, Eigen::Vector2d(x, xdot), ModeSet(Mode::kSlipBelow)};
}
FlowPoint AtPhase0(double x, double xdot) {
  return {0, Eigen::Vector3d(x, xdot, 0), ModeSet(Mode::kSlipBelow)};
}

// The undamped coulomb floor (mu = 0.3, A = 1, v = 0): unbounded at Omega = 1.
TEST(OrbitBranch, DenHartogRowsMatchTheClosedForm) {
  ForcedBeltParams p;
  p.base.law = LawKind::kCoulomb;
  p.base.mu_s = p.base.mu_k = 0.3;
  p.base.beta = 0, p.base.v = 0;
  p.force = 1, p.omega = 0.75;
  const ForcedBelt m(p);
  OrbitBranchOptions o = Tight();
  o.max_amplitude = 10;
  o.palc.ds_max = 0.05;
  const double V = 1 / (1 - p.omega * p.omega);
  const FlowPoint guess = AtPhase0(V, 0.01);
  const OrbitBranch b = ContinueOrbits(m, m.ParameterIndex("omega"), guess,
                                       PoincareSection::Stroboscopic(m, guess.z, 1), 2.5, o);
  EXPECT_EQ(b.status, BranchStatus::kUnbounded) << b.message;
  int compared = 0;
  double worst = 0;
  for (const OrbitRow& r : b.rows) {
    if (r.sticks > 0) continue;
    ++compared;
    const double X = forced_reference::DenHartogX(0.3, 1, r.p);
    EXPECT_NEAR(r.hi[0], X, 1e-9 * std::max(1.0, X)) << "Omega = " << r.p;
    worst = std::max(worst, std::abs(r.hi[0] - X) / std::max(1.0, X));
  }
  EXPECT_GT(compared, 10);
  std::printf("[ measured ] %zu rows, %d non-stop: max |x_max - X| / max(1, X) = %.2e, %.3f s\n",
              b.rows.size(), compared, worst, b.seconds);
}

// The seed belt under A = 0.3 cos(Omega t) (studies/seed_forced.ini), from
// Omega = 1 down: past the folds (LP 0.62849) the multiplier crosses -1
// twice before GR1 0.57949. Each located PD must sit inside the reference's
// sign change of det(Phi + I), and each LP have a multiplier at +1.
TEST(OrbitBranch, BothPeriodDoublingsOfTheSeedStudyMatchTheReference) {
  ForcedBeltParams p = forced_reference::SeedBelt(0.25, 0.3, 1);
  const ForcedBelt m(p);
  // 200 periods from (0, v) settle on the m = 1 orbit.
  Flow flow(m, FlowOptions());
  FlowRequest rq;
  rq.t_max = 200 * 2 * M_PI / p.omega;
  const FlowRun tr = flow.Run(AtPhase0(0, p.base.v), rq);
  ASSERT_EQ(tr.status, FlowStatus::kTimeLimit);
  FlowPoint guess = tr.end;
  guess.t = 0, guess.z[2] = 0;
  OrbitBranchOptions o;
  const OrbitBranch b = ContinueOrbits(m, m.ParameterIndex("omega"), guess,
                                       PoincareSection::Stroboscopic(m, guess.z, 1), 0.5797, o);
  ASSERT_EQ(b.status, BranchStatus::kReachedEnd) << b.message;
  std::vector<OrbitRow> pd;
  int lp = 0;
  for (const OrbitRow& s : b.special) {
    if (s.label == SpecialKind::kPeriodDoubling) pd.push_back(s);
    if (s.label != SpecialKind::kFold) continue;
    ++lp;
    double mu_near = 10;
    for (const auto& mu : s.multipliers) mu_near = std::min(mu_near, std::abs(mu - 1.0));
    EXPECT_LT(mu_near, 1e-8) << "LP at Omega = " << s.p;
  }
  EXPECT_GE(lp, 1);
  ASSERT_EQ(pd.size(), 2u);
  for (const OrbitRow& s : pd) {
    double mu_near = 10;
    for (const auto& mu : s.multipliers) mu_near = std::min(mu_near, std::abs(mu + 1.0));
    EXPECT_LT(mu_near, 1e-9);
    // The reference's det(Phi + I) changes sign across p_PD +- 5e-12.
    forced_reference::LReal x = s.start.z[0], y = s.start.z[1], g[2];
    for (int side = 0; side < 2; ++side) {
      p.omega = s.p + (side ? 5e-12 : -5e-12);
      bool ok = false;
      g[side] = forced_reference::RefFlip(p, &x, &y, &ok);
      ASSERT_TRUE(ok) << "Omega = " << p.omega;
    }
    EXPECT_NE(g[0] > 0, g[1] > 0) << "PD at Omega = " << s.p;
    std::printf("[ measured ] PD at Omega = %.15g, reference det(Phi + I) %.3Le | %.3Le\n", s.p,
                g[0], g[1]);
  }
  EXPECT_GT(pd[0].p, pd[1].p);
  std::printf("[ measured ] %zu rows, %d evaluations, %.3f s\n", b.rows.size(), b.evaluations,
              b.seconds);
}

PoincareSection FallingXdot() {
  PoincareSection s;
  s.kind = SectionKind::kSurface;
  s.surface.g.terms[0] = {1, 1.0};
  s.surface.g.size = 1;
  s.surface.direction = -1;
  return s;
}

Params Seed(double v) {
  Params p;
  p.v = v;
  return p;
}

// The belt's pure-slip orbits between GR (v 0.3958) and HB (0.44096), on the
// section x' = 0 falling: the map's unknowns are the whole state.
TEST(OrbitBranch, BeltPureSlipRowsMatchTheReference) {
  const Model m(Seed(0.42));
  const OrbitBranch b = ContinueOrbits(m, m.ParameterIndex("v"), At(m.SteadySliding().x + 0.3, 0),
                                       FallingXdot(), 0.44, Tight());
  ASSERT_EQ(b.status, BranchStatus::kReachedEnd) << b.message;
  EXPECT_TRUE(b.special.empty());
  EXPECT_GT(b.rows.size(), 3u);
  for (const OrbitRow& r : b.rows) {
    const reference::PureSlipOrbit ref =
        reference::PureSlip(Seed(r.p), static_cast<long double>(r.start.z[0]));
    ASSERT_TRUE(ref.found) << "v = " << r.p;
    EXPECT_NEAR(r.start.z[0], static_cast<double>(ref.x_section), 1e-10) << "v = " << r.p;
    EXPECT_NEAR(r.start.z[1], 0, 1e-12) << "v = " << r.p;
    EXPECT_NEAR(r.period, static_cast<double>(ref.period), 1e-9) << "v = " << r.p;
    ASSERT_EQ(r.multipliers.size(), 1u);
    EXPECT_NEAR(r.multipliers[0].real(), static_cast<double>(ref.multiplier), 1e-8);
    EXPECT_EQ(r.sticks, 0);
  }
  EXPECT_EQ(b.rows.back().p, 0.44);
}

// Down from 0.42 the pure-slip orbit grazes x' = v and sticks: the one driver
// labels GR (sticks 0 -> 1, the slip phase between sticks not short) where
// the belt's driver locates GR.
TEST(OrbitBranch, BeltGrazingIsTheSwitchingSequencesChange) {
  const Model m(Seed(0.42));
  const OrbitBranch b = ContinueOrbits(m, m.ParameterIndex("v"), At(m.SteadySliding().x + 0.3, 0),
                                       FallingXdot(), 0.38, Tight());
  ASSERT_EQ(b.status, BranchStatus::kReachedEnd) << b.message;
  ASSERT_EQ(b.special.size(), 1u);
  const OrbitRow& sl = b.special[0];
  EXPECT_EQ(sl.label, SpecialKind::kGrazing) << sl.description;
  EXPECT_NE(sl.description.find("sticks 0 -> 1"), std::string::npos) << sl.description;
  ContinuationOptions co;
  co.from = 0.38, co.to = 0.42;
  const ContinuationResult belt = Continue(Seed(0.38), co);
  double gr = NAN;
  for (const SpecialPoint& s : belt.special)
    if (s.kind == SpecialKind::kGrazing) gr = s.p;
  EXPECT_NEAR(sl.p, gr, 1e-9);
  EXPECT_EQ(b.rows.back().sticks, 1);
  EXPECT_GE(b.jumps, 1);  // the corner: no pseudo-arclength step turns it
  std::printf("[ measured ] SL at v = %.15g, the belt's GR at %.15g\n", sl.p, gr);
}

TEST(OrbitBranch, MisuseThrows) {
  const Model m(Seed(0.42));
  const FlowPoint guess = At(0.5, 0);
  const OrbitBranchOptions o;
  EXPECT_THROW(ContinueOrbits(m, 99, guess, FallingXdot(), 0.44, o), InvalidArgument);
  EXPECT_THROW(ContinueOrbits(m, m.ParameterIndex("v"), guess, FallingXdot(), 0.42, o),
               InvalidArgument);
  EXPECT_THROW(ContinueOrbits(m, m.ParameterIndex("v"), guess, FallingXdot(), NAN, o),
               InvalidArgument);
  EXPECT_THROW(ContinueOrbits(m, m.ParameterIndex("v"), AtPhase0(0.5, 0), FallingXdot(), 0.44, o),
               InvalidArgument);
  OrbitBranchOptions bad;
  bad.max_amplitude = -1;
  EXPECT_THROW(ContinueOrbits(m, m.ParameterIndex("v"), guess, FallingXdot(), 0.44, bad),
               InvalidArgument);
}

// A restart cut short by its cancel hook is kCancelled, wherever the cancel
// falls: in the first correction (before the fix: start-failed), in a step's
// corrector, in a jump. The hook turns true at its n-th poll, for many n.
TEST(OrbitBranch, RestartCutShortByTheCancelIsCancelled) {
  const Model first(Seed(0.42));
  const OrbitBranch b =
      ContinueOrbits(first, first.ParameterIndex("v"), At(first.SteadySliding().x + 0.3, 0),
                     FallingXdot(), 0.44, OrbitBranchOptions());
  ASSERT_EQ(b.status, BranchStatus::kReachedEnd) << b.message;
  ASSERT_GE(b.rows.size(), 3u);
  const OrbitRow& row = b.rows[1];
  const Model m(Seed(row.p));
  int cut = 0;
  for (long n = 1; n < 200000; n = n * 3 / 2 + 1) {
    long polls = 0;
    OrbitBranchOptions o;
    o.palc.cancelled = [&polls, n] { return ++polls >= n; };
    const OrbitBranch r =
        ContinueOrbitsFrom(m, m.ParameterIndex("v"), row.start, FallingXdot(), 0.38, 0, o);
    if (Complete(r.status)) break;  // done before the n-th poll
    EXPECT_EQ(r.status, BranchStatus::kCancelled)
        << "n = " << n << ": " << Name(r.status) << ": " << r.message;
    ++cut;
  }
  EXPECT_GE(cut, 10);
  EXPECT_THROW(ContinueOrbitsFrom(m, m.ParameterIndex("v"), row.start, FallingXdot(), 0.38, 2,
                                  OrbitBranchOptions()),
               InvalidArgument);
}

}  // namespace
}  // namespace stickslip
