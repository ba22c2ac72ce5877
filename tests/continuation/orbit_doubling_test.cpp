// Branch switching at a period doubling on any section (orbit_branch.hpp,
// ContinueDoubled). The Stribeck forced scene (studies/stribeck_forced.ini)
// doubles near Omega = 0.618; the doubled branch is followed twice, on the
// stroboscopic section and on the stick-exit section, two different maps
// with two different Jacobians (the tangent block of Phi; the event
// section's projection with its saltations). Floquet multipliers do not
// depend on the section, so at the branch's far end both give the same
// multipliers and period. ForcedSwitch.* checks the stroboscopic doubled
// branch against the independent long-double map.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "forced_reference.hpp"
#include "stickslip/continuation/orbit_branch.hpp"
#include "stickslip/errors.hpp"
#include "stickslip/systems/forced/forced.hpp"

namespace stickslip {
namespace {

// studies/stribeck_forced.ini's scene (v 0.25, A 0.3) at Omega.
ForcedBeltParams Scene(double omega) { return forced_reference::StribeckBelt(0.25, 0.3, omega); }

OrbitBranchOptions Options() {
  OrbitBranchOptions o;
  o.shooting.flow.rtol = o.shooting.flow.atol = 1e-13;
  o.palc.ds = o.palc.ds_max = 0.004;
  return o;
}

// The first PD of the m = 1 branch from Omega = 0.7 down.
OrbitRow FirstPeriodDoubling() {
  const ForcedBelt m(Scene(0.7));
  Flow flow(m, FlowOptions());
  FlowRequest rq;
  rq.t_max = 200 * 2 * M_PI / 0.7;
  FlowPoint z = flow.Run({0, Eigen::Vector3d(0, 0.25, 0), ModeSet()}, rq).end;
  z.t = 0, z.z[2] = 0;
  const OrbitBranch b = ContinueOrbits(m, m.ParameterIndex("omega"), z,
                                       PoincareSection::Stroboscopic(m, z.z, 1), 0.6, Options());
  for (const OrbitRow& r : b.special)
    if (r.label == SpecialKind::kPeriodDoubling) return r;
  ADD_FAILURE() << "no PD: " << Name(b.status) << " " << b.message;
  return {};
}

TEST(OrbitDoubling, StroboscopicAndStickExitSectionsGiveTheSameDoubledOrbits) {
  const OrbitRow pd = FirstPeriodDoubling();
  ASSERT_EQ(pd.label, SpecialKind::kPeriodDoubling);
  ASSERT_EQ(pd.sticks, 1);
  const ForcedBelt m(Scene(pd.p));
  const int j = m.ParameterIndex("omega");
  const double lo = pd.p - 0.006, hi = pd.p + 0.006;
  const OrbitBranch strobe = ContinueDoubled(
      m, j, pd.start, PoincareSection::Stroboscopic(m, pd.start.z, 1), lo, hi, Options());
  // The same orbit cut at its stick exit: one exit and one turn per period.
  Flow flow(m, FlowOptions());
  FlowRequest rq;
  rq.stop_at_exit = 1;
  rq.t_max = 2 * 2 * M_PI / pd.p;
  const FlowRun exit = flow.Run(pd.start, rq);
  ASSERT_EQ(exit.sticks, 1) << Name(exit.status);
  const OrbitBranch event =
      ContinueDoubled(m, j, exit.end, PoincareSection::StickExit(0, 1, 1), lo, hi, Options());
  for (const OrbitBranch* b : {&strobe, &event}) {
    ASSERT_EQ(b->status, BranchStatus::kReachedEnd) << b->message;
    EXPECT_EQ(b->rows.back().p, lo);  // supercritical: it opens toward lower Omega
    EXPECT_EQ(b->rows.back().sticks, 2);
    EXPECT_NEAR(b->rows.back().period, 2 * 2 * M_PI / lo, 1e-9);
  }
  const OrbitRow &a = strobe.rows.back(), &e = event.rows.back();
  ASSERT_EQ(a.multipliers.size(), 2u);
  ASSERT_EQ(e.multipliers.size(), 2u);
  double worst = 0;
  for (int i = 0; i < 2; ++i)
    worst = std::max(worst, std::abs(a.multipliers[i] - e.multipliers[i]));
  EXPECT_LT(worst, 1e-8);
  std::printf(
      "[ measured ] Omega = %.12g: multipliers %.12f, %.12f (strobe) vs %.12f, %.12f "
      "(stick exit), max difference %.1e; %zu and %zu rows\n",
      lo, std::abs(a.multipliers[0]), std::abs(a.multipliers[1]), std::abs(e.multipliers[0]),
      std::abs(e.multipliers[1]), worst, strobe.rows.size(), event.rows.size());
}

TEST(OrbitDoubling, MisuseThrowsAndAPointWithoutAFlipIsRefused) {
  const ForcedBelt m(Scene(0.7));
  const int j = m.ParameterIndex("omega");
  const FlowPoint z{0, Eigen::Vector3d(0, 0.25, 0), ModeSet()};
  const PoincareSection s = PoincareSection::Stroboscopic(m, z.z, 1);
  EXPECT_THROW(ContinueDoubled(m, j, z, s, 0.75, 0.8, Options()), InvalidArgument);
  EXPECT_THROW(ContinueDoubled(m, j, z, s, 0.6, NAN, Options()), InvalidArgument);
  const OrbitBranch b = ContinueDoubled(m, j, z, s, 0.6, 0.8, Options());
  EXPECT_EQ(b.status, BranchStatus::kStartFailed);
  EXPECT_TRUE(b.rows.empty());
}

}  // namespace
}  // namespace stickslip
