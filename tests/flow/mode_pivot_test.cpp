// Many contacts at one instant (switching.hpp, PivotedMode): the least-index
// pivoting finds the consistent set the enumeration finds, and takes the flow
// past the enumeration's bound. The system (mass_coupled.hpp) couples K blocks by their masses,
// M x'' = g + r, g_i = -k x_i - c x_i', r_i contact i's friction force
// (slip below: +mu_k, above: -mu_k; stick: the force that holds x_i'' = 0),
// so that every sticking contact's force depends on the others' modes; the
// reference is the enumeration of all 3^K candidates (ConsistentMode, K <= 8)
// and, for the flow, the one block of the same total mass.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <random>
#include <vector>

#include "flow/mass_coupled.hpp"
#include "stickslip/errors.hpp"
#include "stickslip/flow/flow.hpp"
#include "stickslip/flow/switching.hpp"

namespace stickslip {
namespace {

// K alike blocks (mass_coupled.hpp), damped by c as the random states here are.
MassCoupled Blocks(int k, double e, double mass = 1, double c = 0.1) {
  Coupling p;
  p.blocks = k, p.e = e, p.mass = mass, p.c = c;
  return MassCoupled(p);
}
const Coupling kLaw;  // v, mu_s, mu_k

// Every contact on its surface x_i' = v at positions x.
Eigen::VectorXd OnAll(const std::vector<double>& x) {
  Eigen::VectorXd z(2 * x.size());
  for (size_t i = 0; i < x.size(); ++i) z[2 * i] = x[i], z[2 * i + 1] = kLaw.v;
  return z;
}

std::vector<int> All(int k) {
  std::vector<int> on(k);
  for (int i = 0; i < k; ++i) on[i] = i;
  return on;
}

// Random states of 2..8 coupled blocks: wherever the enumeration of all 3^K
// candidates finds one consistent set, pivoting finds the same; where it
// finds none, pivoting finds none (kTooMany); where several, one of them.
TEST(ModePivot, FindsTheSetTheEnumerationFinds) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> x(-0.8, 0.8);
  int unique = 0, none = 0, several = 0, one_of_several = 0;
  for (int k = 2; k <= kMaxEnumeratedContacts; ++k)
    for (double e : {-0.1, 0.2, 0.45}) {
      const MassCoupled s = Blocks(k, e);
      for (int trial = 0; trial < 60; ++trial) {
        std::vector<double> pos(k);
        for (double& p : pos) p = x(rng);
        const Eigen::VectorXd z = OnAll(pos);
        const ModeChoiceResult en = ConsistentMode(s, ModeSet(), All(k), z);
        const ModeChoiceResult pv = PivotedMode(s, ModeSet(), All(k), z);
        ASSERT_EQ(en.candidates, k);
        if (en.choice == ModeChoice::kUnique) {
          ++unique;
          ASSERT_EQ(pv.choice, ModeChoice::kPivoted) << "k " << k << " e " << e;
          EXPECT_EQ(pv.mode, en.mode) << "k " << k << " e " << e << " trial " << trial;
        } else if (en.choice == ModeChoice::kInconsistent) {
          ++none;
          EXPECT_EQ(pv.choice, ModeChoice::kTooMany);
        } else {
          ++several;
          if (pv.choice == ModeChoice::kPivoted) ++one_of_several;
        }
      }
    }
  std::printf(
      "[ measured ] %d unique sets found by pivoting as enumerated, %d without a set, "
      "%d with several (pivoting found one in %d)\n",
      unique, none, several, one_of_several);
  EXPECT_GT(unique, 500);
}

// More contacts than the enumeration takes: 16 alike blocks start alike,
// arrive on their surfaces at one instant and stick together (pivoting), and
// leave together at x = mu_s, as one block of their total mass does (closed
// form: x'' = (mu_k - x) / m, m = 1 + 15 e, from (-0.35, 0) with c = 0).
TEST(ModePivot, SixteenBlocksStickAndLeaveAtOnce) {
  constexpr int kBlocks = 16;
  static_assert(kBlocks > kMaxEnumeratedContacts);
  const double e = 0.2, mass = 1 + (kBlocks - 1) * e;
  const MassCoupled s = Blocks(kBlocks, e, 1.0, 0.0);
  FlowOptions fo;
  fo.integrator = Integrator::kCvode;
  fo.rtol = 1e-11;
  fo.atol = 1e-13;
  Flow flow(s, fo);
  std::vector<FlowSwitch> sw;
  FlowRequest rq;
  rq.t_max = 20;
  rq.stop_at_exit = 1;
  rq.switches = &sw;
  const std::vector<double> start(kBlocks, -0.35);
  Eigen::VectorXd z0 = OnAll(start);
  for (int i = 0; i < kBlocks; ++i) z0[2 * i + 1] = 0;
  const FlowRun r = flow.Run(FlowPoint{0, z0, ModeSet()}, rq);
  ASSERT_TRUE(r.ok()) << r.message;
  ASSERT_EQ(r.status, FlowStatus::kStickExit);
  ASSERT_EQ(sw.size(), 2u * kBlocks);
  ModeSet stuck;
  for (int i = 0; i < kBlocks; ++i) stuck.set(i, Mode::kStick);
  for (int i = 0; i < kBlocks; ++i) {
    EXPECT_EQ(sw[i].kind, SwitchKind::kStickIn) << i;
    EXPECT_EQ(sw[i].t, sw[0].t) << i;
    EXPECT_EQ(sw[kBlocks + i].kind, SwitchKind::kStickOut) << i;
  }
  EXPECT_EQ(sw[kBlocks - 1].after, stuck);
  const double w = 1 / std::sqrt(mass), a = kLaw.mu_k + 0.35;
  const double t_in = std::asin(kLaw.v / (a * w)) / w;
  EXPECT_NEAR(sw[0].t, t_in, 1e-8);
  EXPECT_NEAR(sw[0].z[0], kLaw.mu_k - a * std::cos(w * t_in), 1e-8);
  EXPECT_NEAR(r.end.t, t_in + (kLaw.mu_s - sw[0].z[0]) / kLaw.v, 1e-8);
  for (int i = 1; i < kBlocks; ++i) EXPECT_NEAR(r.end.z[2 * i], r.end.z[0], 1e-15) << i;
  EXPECT_EQ(r.end.mode, ModeSet());
}

// The consistency conditions written out again (docs/theory.md, "Modes as
// sets"), and every candidate of `on` tried: how many sets hold, the first.
bool HoldsIn(const System& s, const ModeSet& m, int i, ConstState z) {
  if (m.sticks(i)) return std::abs(s.StickForce(m, i, z)) <= s.StaticLimit(i, z);
  ModeSet held = m;
  held.set(i, Mode::kStick);
  const double lambda = s.StickForce(held, i, z);
  const Mode side = lambda > 0 ? Mode::kSlipBelow : Mode::kSlipAbove;
  return std::abs(lambda) > s.StaticLimit(i, z) && m[i] == side;
}
int BruteForce(const System& s, const std::vector<int>& on, ConstState z, ModeSet* first) {
  static constexpr Mode kAll[] = {Mode::kSlipAbove, Mode::kStick, Mode::kSlipBelow};
  long total = 1;
  for (size_t j = 0; j < on.size(); ++j) total *= 3;
  int found = 0;
  ModeSet m;
  for (long code = 0; code < total; ++code) {
    long c = code;
    for (int i : on) m.set(i, kAll[c % 3]), c /= 3;
    bool ok = true;
    for (size_t j = 0; ok && j < on.size(); ++j) ok = HoldsIn(s, m, on[j], z);
    if (ok && found++ == 0) *first = m;
  }
  return found;
}

// Past the enumeration's 8 contacts: 9 to 11 coupled blocks in random states,
// the flow's choice (pivoting) against every candidate tried here.
TEST(ModePivot, PastEightContactsFindsTheOneSet) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> x(-0.8, 0.8);
  int unique = 0;
  for (int k = 9; k <= 11; ++k)
    for (double e : {-0.05, 0.2, 0.45, 0.8}) {
      const MassCoupled s = Blocks(k, e);
      for (int trial = 0; trial < (k == 11 ? 2 : 5); ++trial) {
        std::vector<double> pos(k);
        for (double& p : pos) p = x(rng);
        const Eigen::VectorXd z = OnAll(pos);
        ModeSet want;
        if (BruteForce(s, All(k), z, &want) != 1) continue;
        ++unique;
        const ModeChoiceResult r = ConsistentMode(s, ModeSet(), All(k), z);
        EXPECT_TRUE(Resolved(r.choice)) << "k " << k << " e " << e;
        EXPECT_EQ(r.mode, want) << "k " << k << " e " << e << " trial " << trial;
      }
    }
  std::printf("[ measured ] %d states of 9 to 11 contacts with one consistent set: all found\n",
              unique);
  EXPECT_GT(unique, 40);
}

// Where pivoting cycles (nine blocks, M nearly singular: 1 + 8e = 0.001),
// the enumeration still finds the one set (a state found by a review's
// random search).
TEST(ModePivot, ACycleFallsBackToTheEnumeration) {
  const MassCoupled s = Blocks(9, -0.999 / 8);
  const Eigen::VectorXd z = OnAll({-1.9013007667852113, 1.6899257950143616, -1.2410385718179111,
                                   0.58176688932245613, -0.047442802867267986, 1.8160963870261253,
                                   0.76936020750802303, -1.9441788510412492, -1.1336349975799238});
  EXPECT_EQ(PivotedMode(s, ModeSet(), All(9), z).choice, ModeChoice::kTooMany);
  ModeSet want;
  ASSERT_EQ(BruteForce(s, All(9), z, &want), 1);
  const ModeChoiceResult r = ConsistentMode(s, ModeSet(), All(9), z);
  EXPECT_EQ(r.choice, ModeChoice::kUnique);
  EXPECT_EQ(r.mode, want);
}

// Pivoting from the all-stuck set where the least index must give way: two
// blocks of the pair above (e = -0.5) pushed apart, so that block 0 held
// alone needs more than mu_s: the same set as the enumeration.
TEST(ModePivot, ReleasesTheLeastIndexFirst) {
  const MassCoupled s = Blocks(2, -0.5);
  const Eigen::VectorXd z = OnAll({-0.3, 0.9});
  const ModeChoiceResult en = ConsistentMode(s, ModeSet(), {0, 1}, z);
  const ModeChoiceResult pv = PivotedMode(s, ModeSet(), {0, 1}, z);
  ASSERT_EQ(en.choice, ModeChoice::kUnique);
  EXPECT_EQ(pv.choice, ModeChoice::kPivoted);
  EXPECT_EQ(pv.mode, en.mode);
  EXPECT_NE(pv.mode.sticks(1), true);  // x2 = 0.9 holds past mu_s = 0.4 alone
}

}  // namespace
}  // namespace stickslip
