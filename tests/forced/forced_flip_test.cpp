// Every period doubling a forced branch crosses (issue 35, item 1): on the
// m = 1 branches of studies/stribeck_forced.ini and studies/seed_forced.ini
// the multiplier crosses -1 into instability (PD1) and back again just
// before the grazing point GR1 (PD2, in the step that also holds GR1). The
// reference: a brute-force scan in Omega of det(Phi + I) at the m = 1
// fixed point of the independent long-double stroboscopic map
// (reference/forced_lyapunov.hpp, RKF78), its sign changes bisected here.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "forced_flip_reference.hpp"
#include "forced_reference.hpp"
#include "forced_trace.hpp"
#include "stickslip/continuation/orbit_branch.hpp"

namespace stickslip {
namespace {

using forced_reference::RefFlip;
using reference::LReal;

// The reference's roots of det(Phi + I) on a grid of n steps over [lo, hi],
// each bisected to 1e-13, from the state of the branch row nearest each value
// (after the last fold).
std::vector<double> RefFlipRoots(ForcedBeltParams p, const OrbitBranch& b, double lo, double hi,
                                 int n) {
  auto at = [&](double w, LReal* x, LReal* y) {
    p.omega = w;
    bool ok = false;
    const LReal g = RefFlip(p, x, y, &ok);
    EXPECT_TRUE(ok) << "Omega = " << w;
    return g;
  };
  auto start = [&](double w, LReal* x, LReal* y) {
    const OrbitRow* best = nullptr;
    size_t first = 0;  // past the folds: the sheet the window lies on
    for (size_t i = 0; i < b.rows.size(); ++i)
      if (b.rows[i].label == SpecialKind::kFold) first = i + 1;
    for (size_t i = first; i < b.rows.size(); ++i)
      if (const OrbitRow& r = b.rows[i];
          r.sticks == 1 && (!best || std::abs(r.p - w) < std::abs(best->p - w)))
        best = &r;
    *x = best->start.z[0], *y = best->start.z[1];
  };
  std::vector<double> roots;
  LReal x, y;
  start(lo, &x, &y);
  LReal g_prev = at(lo, &x, &y);
  for (int i = 1; i <= n; ++i) {
    const double w = lo + (hi - lo) * i / n;
    start(w, &x, &y);
    const LReal g = at(w, &x, &y);
    if ((g > 0) != (g_prev > 0)) {
      double a = lo + (hi - lo) * (i - 1) / n, c = w;
      const bool pos_a = g_prev > 0;
      LReal xb = x, yb = y;
      while (c - a > 1e-13) {
        const double mid = 0.5 * (a + c);
        ((at(mid, &xb, &yb) > 0) == pos_a ? a : c) = mid;
      }
      roots.push_back(0.5 * (a + c));
    }
    g_prev = g;
  }
  return roots;
}

// Issue 35, item 4: a sliding point's description follows its counts, "(sticks
// a -> b": "born" or "splits" only where b > a, "vanishes", "merge" or "shrinks" where b < a.
void ExpectDescriptionsFollowCounts(const OrbitBranch& b) {
  for (const OrbitRow& s : b.special) {
    int a = 0, c = 0;
    const size_t at = s.description.find("(sticks ");
    if (at == std::string::npos) continue;
    ASSERT_EQ(std::sscanf(s.description.c_str() + at, "(sticks %d -> %d", &a, &c), 2);
    const bool more = s.description.find("stick phase is born") != std::string::npos ||
                      s.description.find("turns into a stick phase") != std::string::npos ||
                      s.description.find("splits") != std::string::npos;
    const bool fewer = s.description.find("vanishes") != std::string::npos ||
                       s.description.find("merge") != std::string::npos ||
                       s.description.find("shrinks") != std::string::npos;
    EXPECT_EQ(more, c > a) << s.description;
    EXPECT_EQ(fewer, c < a) << s.description;
  }
}

// The branch's PD points within (lo, hi) against the reference's roots.
void ExpectEveryFlip(const ForcedBeltParams& p, double from, double to, double lo, double hi,
                     const OrbitBranchOptions& o, const char* name) {
  const OrbitBranch b = testing_util::TraceOmega(p, from, to, o);
  ASSERT_EQ(b.status, BranchStatus::kReachedEnd) << b.message;
  ExpectDescriptionsFollowCounts(b);
  std::vector<double> pd;
  for (const OrbitRow& s : b.special)
    if (s.label == SpecialKind::kPeriodDoubling && s.p > lo && s.p < hi) pd.push_back(s.p);
  std::sort(pd.begin(), pd.end());
  const std::vector<double> ref = RefFlipRoots(p, b, lo, hi, 200);
  ASSERT_EQ(pd.size(), ref.size()) << name;
  ASSERT_EQ(ref.size(), 2u) << name;
  for (size_t i = 0; i < ref.size(); ++i) {
    std::printf("[ measured ] %s PD%zu at Omega = %.15g, reference %.15g, error %.2e\n", name,
                i + 1, pd[i], ref[i], pd[i] - ref[i]);
    EXPECT_NEAR(pd[i], ref[i], 1e-12) << name;
  }
}

// Stribeck: PD1 0.61821, PD2 0.58000, GR1 0.57876; the window ends inside the
// single-valued stick-slip stretch between GR1 and the folds (LP 0.62374).
TEST(ForcedFlip, StribeckStudyBothCrossingsOfMinusOne) {
  const ForcedBeltParams p = forced_reference::StribeckBelt(0.25, 0.3, 0.8);
  ExpectEveryFlip(p, 0.8, 0.5, 0.5790, 0.6230, OrbitBranchOptions(ForcedBelt::FlowDefaults()),
                  "stribeck");
}

// The seed belt: PD1 0.61397, PD2 0.58019, GR1 0.57949 (LP 0.62849).
TEST(ForcedFlip, SeedStudyBothCrossingsOfMinusOne) {
  const ForcedBeltParams p = forced_reference::SeedBelt(0.25, 0.3, 1);
  ExpectEveryFlip(p, 1, 0.5, 0.5797, 0.6280, OrbitBranchOptions(ForcedBelt::FlowDefaults()),
                  "seed");
}

// Two crossings within one step of one stick structure: steps up to 0.05 in
// Omega from inside the stretch (0.62 to 0.5795) hold both PD points in
// two steps (measured: 3 rows); the step is halved while the multiplier moves by more
// than 0.1, and both are found.
TEST(ForcedFlip, TwoCrossingsInOneLongStep) {
  const ForcedBeltParams p = forced_reference::StribeckBelt(0.25, 0.3, 0.62);
  OrbitBranchOptions o(ForcedBelt::FlowDefaults());
  o.palc.ds = o.palc.ds_max = 0.05;
  const OrbitBranch b = testing_util::TraceOmega(p, 0.62, 0.5795, o);
  ASSERT_EQ(b.status, BranchStatus::kReachedEnd) << b.message;
  int pd = 0, steps = 0;
  for (const OrbitRow& r : b.rows) (r.label == SpecialKind::kPeriodDoubling ? pd : steps)++;
  std::printf("[ measured ] %d rows, %d PD points\n", steps, pd);
  EXPECT_EQ(pd, 2);
  for (const OrbitRow& s : b.special) {
    if (s.label == SpecialKind::kPeriodDoubling) {
      EXPECT_NEAR(s.multipliers[0].real(), -1, 1e-9);
    }
  }
}

}  // namespace
}  // namespace stickslip
