// Switching-sliding on Den Hartog's floor (coulomb mu_s = mu_k = 0.3, v = 0,
// beta = 0, A = 1, studies/den_hartog.ini below its range): the library once
// labelled SW (sticks 2 -> 2, crossings 0 -> 1) at Omega 0.4807234 and an SL
// (2 -> 0, 1 -> 2) 3.4e-7 above it. Reference: the m = 1 orbit of the
// closed-form coulomb pieces in long double (forced_reference.hpp), a fixed
// point of the map from t0 = T / 4 (mid-slip) over one period by Newton with
// a difference Jacobian, its (sticks, crossings) counted over that period,
// and Omega bisected on them. The structure goes (2, 0) -> (0, 2) at one
// Omega, never (2, 1): both stick phases of the symmetric orbit shrink to
// crossings on the band's edge at once, a crossing-sliding point (theory.md,
// "Which sliding bifurcation occurs under which law").
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>
#include <vector>

#include "forced_reference.hpp"
#include "forced_run.hpp"
#include "forced_trace.hpp"
#include "stickslip/continuation/orbit_branch.hpp"
#include "stickslip/systems/forced/flow.hpp"

namespace stickslip {
namespace {

namespace ref = forced_reference;
using ref::Real;

const ForcedBeltParams kFloor = ref::Coulomb(0.3, 0.3, 0, 0, 1, 1);

ref::Setup SetupAt(Real w) {
  return ref::Setup{reference::Law(kFloor.base), Real(0), Real(0), Real(1), w};
}

struct Structure {
  int sticks = -1, crossings = -1;
  bool operator==(const Structure& o) const {
    return sticks == o.sticks && crossings == o.crossings;
  }
};

// The state at t1 from (t0, x, y).
std::pair<Real, Real> Flow(const ref::Setup& s, Real t0, Real x, Real y, Real t1,
                           Structure* counted = nullptr) {
  ref::PieceSim<ref::CoulombPiece> sim(s);
  sim.dt = 2e-3L;
  Real t = t0;
  sim.Run(t, x, y, t1);
  if (counted) *counted = {sim.sticks, sim.crossings};
  return {x, y};
}

// The m = 1 orbit at Omega = w through z = (x, y) at t0 = T / 4: Newton on
// P(z) - z (difference Jacobian, step 1e-9); z is updated; its structure.
Structure OrbitAt(Real w, Real* x, Real* y) {
  const ref::Setup s = SetupAt(w);
  const Real T = 2 * std::acos(Real(-1)) / w, t0 = T / 4, h = 1e-9L;
  for (int it = 0; it < 40; ++it) {
    const auto p = Flow(s, t0, *x, *y, t0 + T);
    const Real f0 = p.first - *x, f1 = p.second - *y;
    if (std::abs(f0) + std::abs(f1) < 1e-15L) break;
    const auto px = Flow(s, t0, *x + h, *y, t0 + T), py = Flow(s, t0, *x, *y + h, t0 + T);
    const Real a = (px.first - p.first) / h - 1, b = (py.first - p.first) / h;
    const Real c = (px.second - p.second) / h, d = (py.second - p.second) / h - 1;
    const Real det = a * d - b * c;
    *x -= (d * f0 - b * f1) / det;
    *y -= (-c * f0 + a * f1) / det;
  }
  Structure st;
  const auto p = Flow(s, t0, *x, *y, t0 + T, &st);
  EXPECT_LT(double(std::abs(p.first - *x) + std::abs(p.second - *y)), 1e-13)
      << "no orbit at Omega = " << double(w);
  return st;
}

// Omega bisected between lo and hi on whether the orbit's structure is
// `below`, each midpoint's orbit by Newton from lo's (the family followed);
// every midpoint's structure is one of `allowed`.
Real BisectStructure(Real lo, Real hi, Real* x, Real* y, Structure below,
                     const std::vector<Structure>& allowed, Real tol) {
  for (int i = 0; i < 60 && hi - lo > tol; ++i) {
    const Real mid = (lo + hi) / 2;
    Real xm = *x, ym = *y;
    const Structure st = OrbitAt(mid, &xm, &ym);
    EXPECT_TRUE(std::find(allowed.begin(), allowed.end(), st) != allowed.end())
        << "Omega " << double(mid) << ": sticks " << st.sticks << ", crossings " << st.crossings;
    if (st == below)
      lo = mid, *x = xm, *y = ym;
    else
      hi = mid;
  }
  return lo;
}

// The reference along the symmetric family from the library's orbit at
// Omega 0.48: (2, 0) -> (2, 2) near Omega_1, where the arrival at x' = 0
// after each stick exit moves out of the band: it becomes a crossing on the
// band's edge, followed by a short slip and a stick (crossing-sliding); in a
// sliver [Omega_1a, Omega_1b] one half period has crossed and the other not
// (sticks 2, crossings 1). Then (2, 2) -> (0, 2) at Omega_2, where that
// stick vanishes as the short slip returns tangentially (grazing-sliding).
struct Events {
  Real omega1a, omega1b, omega2;
};
Events ReferenceEvents() {
  OrbitBranchOptions o(ForcedBelt::FlowDefaults());
  o.max_amplitude = 20;
  const OrbitBranch b = testing_util::TraceOmega(kFloor, 0.48, 0.4801, o);
  EXPECT_FALSE(b.rows.empty()) << b.message;
  if (b.rows.empty()) return {};
  const OrbitRow& first = b.rows.front();
  const double T = 2 * M_PI / first.p;
  const auto z = Flow(SetupAt(first.p), 0, first.start.z[0], first.start.z[1], T / 4);
  Real x = z.first, y = z.second;
  EXPECT_EQ(OrbitAt(first.p, &x, &y), (Structure{2, 0}));
  for (Real w = first.p; w < 0.48070L; w += 0.0001L) OrbitAt(w, &x, &y);  // follow
  EXPECT_EQ(OrbitAt(0.4807L, &x, &y), (Structure{2, 0}));
  Real x2 = x, y2 = y;
  EXPECT_EQ(OrbitAt(0.4808L, &x2, &y2), (Structure{2, 2}));
  const std::vector<Structure> near1 = {{2, 0}, {2, 1}, {2, 2}};
  Events e;
  Real xa = x, ya = y;
  e.omega1a = BisectStructure(0.4807L, 0.4808L, &xa, &ya, {2, 0}, near1, 1e-10L);
  // The upper end of the sliver: the first orbit with both crossings.
  Real lo = 0.4807L, hi = 0.4808L;
  for (int i = 0; i < 60 && hi - lo > 1e-10L; ++i) {
    const Real mid = (lo + hi) / 2;
    Real xm = x, ym = y;
    const Structure st = OrbitAt(mid, &xm, &ym);
    (st == (Structure{2, 2}) ? hi : lo) = mid;
    if (!(st == (Structure{2, 2}))) x = xm, y = ym;
  }
  e.omega1b = hi;
  for (Real w = 0.4808L; w < 0.4814L; w += 0.0001L) OrbitAt(w, &x2, &y2);
  EXPECT_EQ(OrbitAt(0.4814L, &x2, &y2), (Structure{2, 2}));
  Real x3 = x2, y3 = y2;
  EXPECT_EQ(OrbitAt(0.4816L, &x3, &y3), (Structure{0, 2}));
  e.omega2 = BisectStructure(0.4814L, 0.4816L, &x2, &y2, {2, 2}, {{2, 2}, {0, 2}}, 1e-12L);
  std::printf(
      "[ measured ] reference: crossings 0 -> 1 at Omega = %.13Lf, 1 -> 2 at %.13Lf, "
      "sticks 2 -> 0 at %.13Lf\n",
      e.omega1a, e.omega1b, e.omega2);
  return e;
}

TEST(ForcedSwitchingSliding, DenHartogFloorReferenceHasCrossingThenGrazingSlidingNoSwitching) {
  const Events e = ReferenceEvents();
  EXPECT_NEAR(double(e.omega1a), 0.4807234, 1e-7);
  EXPECT_LT(double(e.omega1b - e.omega1a), 2e-7);  // the one-crossing sliver
  EXPECT_GE(double(e.omega1b), double(e.omega1a));
  EXPECT_NEAR(double(e.omega2), 0.481478247, 1e-9);
}

// The library's run below the study's range (ss_continue --study
// studies/den_hartog.ini --from 0.3 --to 0.75 traces the same family):
// no SW anywhere; the structure change near Omega_1 is a CR. Before the
// fix the crossings-only changes were SW (at 0.4807234 in the app's run,
// at 0.49999998 (sticks 1 -> 1, crossings 1 -> 2... ) here).
TEST(ForcedSwitchingSliding, DenHartogFloorRunLabelsNoSwitchingSliding) {
  OrbitBranchOptions o(ForcedBelt::FlowDefaults());
  o.max_amplitude = 20;
  o.palc.ds_max = 0.009;  // ss_continue's 0.02 |to - from|
  o.palc.ds = std::min(o.palc.ds, o.palc.ds_max);
  ForcedBeltParams p0 = kFloor;
  p0.omega = 0.3;
  const ForcedBelt m0(p0);
  const FlowRun tr =
      testing_util::RunForced(m0, ForcedStart(m0, 0, 0, 0), 200 * m0.period(), {}, o.shooting.flow);
  const OrbitBranch b = testing_util::StrobeBranch(kFloor, Parameter::kOmega, 0.3, 0.75,
                                                   tr.end.z[0], tr.end.z[1], 1, o);
  ASSERT_FALSE(b.rows.empty()) << b.message;
  int cr_near_omega1 = 0;
  for (const OrbitRow& r : b.special) {
    std::printf("[ measured ] %s at Omega = %.15g: %s\n", Name(r.label), r.p,
                r.description.c_str());
    if (r.label == SpecialKind::kCrossing && std::abs(r.p - 0.4807234) < 1e-4) ++cr_near_omega1;
  }
  EXPECT_EQ(cr_near_omega1, 1);
}

}  // namespace
}  // namespace stickslip
