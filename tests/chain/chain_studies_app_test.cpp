// The chain studies of docs/systems.md run through the apps, each against a
// closed form: chain2_asym (unequal masses), chain2_coulomb (linear pieces)
// and chain10 (ten blocks). Steady sliding of a chain of blocks with one
// damping c = 2 beta and one law linearizes to
//   M u'' + d u' + K u = 0,  d = 2 beta + mu'(v)  (D = d I),
// K tridiagonal with 1 + kc (number of neighbours) on its diagonal and -kc
// beside it; with the seed's cubic law mu(v) = mu_s - k1 v + k3 v^3
// (k1 = 0.45, k3 = 0.6), mu'(v) = -k1 + 3 k3 v^2.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <string>
#include <vector>

#include "app_test_util.hpp"
#include "chain/chain_coulomb_reference.hpp"

namespace {

namespace tu = stickslip::testing_util;
namespace cr = stickslip::chain::coulomb_reference;
using ChainStudyApp = tu::AppTest;

std::string Study(const std::string& name) {
  return STICKSLIP_SOURCE_DIR "/studies/" + name + ".ini";
}
double Cell(const tu::Tsv& t, const std::vector<std::string>& row, const std::string& c) {
  return std::stod(row[t.Column(c)]);
}
double Damping(double v) { return 2 * 0.05 - 0.45 + 3 * 0.6 * v * v; }
// d = 0: the single block's Hopf point, v = sqrt((k1 - 2 beta) / (3 k3)).
const double kHopf = std::sqrt((0.45 - 0.1) / 1.8);

// The largest real part of the roots of det(M s^2 + d s + K) for
// M = diag(1, m2), K = [[a, -kc], [-kc, a]], a = 1 + kc:
// m2 s^4 + d (1 + m2) s^3 + (a (1 + m2) + d^2) s^2 + 2 a d s + a^2 - kc^2,
// from its companion matrix.
double LargestRealPart(double d, double m2, double kc) {
  const double a = 1 + kc;
  const double c[4] = {(a * a - kc * kc) / m2, 2 * a * d / m2, (a * (1 + m2) + d * d) / m2,
                       d * (1 + m2) / m2};
  Eigen::Matrix4d comp = Eigen::Matrix4d::Zero();
  for (int i = 0; i < 3; ++i) comp(i + 1, i) = 1;
  for (int i = 0; i < 4; ++i) comp(i, 3) = -c[i];
  return Eigen::EigenSolver<Eigen::Matrix4d>(comp).eigenvalues().real().maxCoeff();
}

// m2 = 1.5: the Hopf point is still d = 0 (D = d I is definite on either
// side of it), with both pairs at the roots of det(K - w^2 M) = 0,
// 1.5 w^4 - 2.5 a w^2 + a^2 - kc^2 = 0, a = 1 + kc. Every steady-sliding
// row's largest real part is the quartic's. Returns the orbit rows.
std::vector<std::vector<std::string>> ExpectUnequalSteadySliding(const tu::Tsv& branch,
                                                                 const tu::Tsv& special,
                                                                 double kc) {
  EXPECT_EQ(special.rows[0][special.Column("lab")], "HB1");
  EXPECT_NEAR(Cell(special, special.rows[0], "v"), kHopf, 1e-12);
  const double a = 1 + kc, disc = std::sqrt(6.25 * a * a - 6 * (a * a - kc * kc));
  const double w_hi = std::sqrt((2.5 * a + disc) / 3), w_lo = std::sqrt((2.5 * a - disc) / 3);
  const std::string hb = special.rows[0].back();
  const double w = std::stod(hb.substr(hb.find("w = ") + 4));
  EXPECT_LT(std::min(std::abs(w - w_hi), std::abs(w - w_lo)), 1e-10) << hb;
  int steady = 0;
  std::vector<std::vector<std::string>> orbits;
  for (const auto& row : branch.rows) {
    const double v = Cell(branch, row, "v");
    if (row[branch.Column("kind")] != "equilibrium") {
      orbits.push_back(row);
      continue;
    }
    EXPECT_NEAR(Cell(branch, row, "max_real"), LargestRealPart(Damping(v), 1.5, kc), 1e-10) << v;
    ++steady;
  }
  EXPECT_EQ(steady, 102);
  return orbits;
}

// The study (kc = 0.2): steady sliding as above; the attractor at v = 0.3
// sticks 6 times a period, stable on its short branch, which ends at SL on
// both sides (docs/systems.md).
TEST_F(ChainStudyApp, UnequalBlocksHopfIsTheLinearizations) {
  const auto r = RunOut("ss_continue", dir_, {"--study", Study("chain2_asym")});
  ASSERT_EQ(r.outcome.code, 0) << r.err;
  const tu::Tsv branch = tu::ReadTsv(tu::ReadFile(dir_ + "/out/branch.tsv"));
  const tu::Tsv special = tu::ReadTsv(tu::ReadFile(dir_ + "/out/special_points.tsv"));
  ASSERT_EQ(special.rows.size(), 3u);
  const auto orbits = ExpectUnequalSteadySliding(branch, special, 0.2);
  for (const auto& row : orbits) {
    EXPECT_EQ(row[branch.Column("sticks")], "6") << Cell(branch, row, "v");
    EXPECT_EQ(row[branch.Column("stable")], "1") << Cell(branch, row, "v");
  }
  EXPECT_GT(orbits.size(), 30u);
  for (int k : {1, 2}) EXPECT_EQ(special.rows[k][special.Column("lab")], "SL" + std::to_string(k));
}

// At kc = 0.5 (--set kc=0.5) the orbit breaks the symmetry: block 1 alone
// sticks, and the blocks' ranges differ; both ends are GR.
TEST_F(ChainStudyApp, UnequalBlocksAtKc05TheOrbitIsAsymmetric) {
  const auto r = RunOut("ss_continue", dir_, {"--study", Study("chain2_asym"), "--set", "kc=0.5"});
  ASSERT_EQ(r.outcome.code, 0) << r.err;
  const tu::Tsv branch = tu::ReadTsv(tu::ReadFile(dir_ + "/out/branch.tsv"));
  const tu::Tsv special = tu::ReadTsv(tu::ReadFile(dir_ + "/out/special_points.tsv"));
  ASSERT_EQ(special.rows.size(), 3u);
  const auto orbits = ExpectUnequalSteadySliding(branch, special, 0.5);
  for (const auto& row : orbits) {
    const double v = Cell(branch, row, "v");
    EXPECT_EQ(row[branch.Column("sticks")], "1") << v;
    EXPECT_EQ(row[branch.Column("stable")], "1") << v;
    EXPECT_GT(Cell(branch, row, "x1_max") - Cell(branch, row, "x2_max"), 0.01) << v;
    EXPECT_GT(Cell(branch, row, "x2_min") - Cell(branch, row, "x1_min"), 0.05) << v;
  }
  EXPECT_GT(orbits.size(), 90u);
  for (int k : {1, 2}) EXPECT_EQ(special.rows[k][special.Column("lab")], "GR" + std::to_string(k));
}

// Ten identical blocks: M = I and D = d I, so each mode of K gives
// s^2 + d s + w_k^2 = 0, w_k^2 = 1 + 2 kc (1 - cos(k pi / 10)): all ten pairs
// cross at d = 0, and every row's largest real part is -d / 2. Steady
// sliding is x_i = mu(v) (K's rows sum to 1).
TEST_F(ChainStudyApp, TenBlocksCrossTogetherAtTheModesFrequencies) {
  const auto r = RunOut("ss_continue", dir_, {"--study", Study("chain10")});
  ASSERT_EQ(r.outcome.code, 0) << r.err;
  EXPECT_TRUE(tu::Contains(r.err, "no stick exit recurs")) << r.err;
  const tu::Tsv branch = tu::ReadTsv(tu::ReadFile(dir_ + "/out/branch.tsv"));
  const tu::Tsv special = tu::ReadTsv(tu::ReadFile(dir_ + "/out/special_points.tsv"));
  ASSERT_EQ(special.rows.size(), 1u);
  EXPECT_NEAR(Cell(special, special.rows[0], "v"), kHopf, 1e-12);
  const std::string hb = special.rows[0].back();
  const double w = std::stod(hb.substr(hb.find("w = ") + 4));
  double nearest = 1;
  for (int k = 0; k < 10; ++k)
    nearest = std::min(nearest, std::abs(w - std::sqrt(2 - std::cos(k * M_PI / 10))));
  EXPECT_LT(nearest, 1e-10) << hb;
  ASSERT_EQ(branch.rows.size(), 102u);
  for (const auto& row : branch.rows) {
    const double v = Cell(branch, row, "v");
    EXPECT_NEAR(Cell(branch, row, "max_real"), -Damping(v) / 2, 1e-10) << v;
    const double mu = 0.4 - 0.45 * v + 0.6 * v * v * v;
    for (int i = 1; i <= 10; ++i)
      EXPECT_NEAR(Cell(branch, row, "x" + std::to_string(i) + "_0"), mu, 1e-12) << v << " " << i;
  }
  // The figure's title: block 5's stiffness is k5 as k4 and k6 are, not the
  // cubic law's quintic term k_5; its lines fit the 1000 px figure (<= 96).
  const std::string gp = tu::ReadFile(dir_ + "/out/bifurcation.gp");
  const std::size_t at = gp.find("title \"chain:");
  ASSERT_NE(at, std::string::npos);
  const std::string title = gp.substr(at, gp.find('\n', at) - at);
  EXPECT_TRUE(tu::Contains(title, " k5=1 ")) << title;
  EXPECT_FALSE(tu::Contains(title, "k_5")) << title;
  std::size_t line = 0, longest = 0;
  for (std::size_t i = title.find('"') + 1; i < title.size(); ++i, ++line) {
    if (title.compare(i, 2, "\\n") == 0) longest = std::max(longest, line), line = 0, i += 2;
    if (title.compare(i, 3, "\\\\_") == 0) i += 2;  // an escaped _: one character shown
  }
  EXPECT_LE(std::max(longest, line), 97u) << title;  // and the closing quote
}
// The coulomb chain's trajectory from the study's start, every row against
// the closed-form pieces of chain_coulomb_reference.hpp (the reference of
// ChainCoulomb, walked here to t = 40), in each component to 1e-9.
TEST_F(ChainStudyApp, CoulombTrajectoryIsTheClosedFormPieces) {
  const auto r = RunOut("ss_simulate", dir_,
                        {"--study", Study("chain2_coulomb"), "--t_end", "40", "--dt", "0.1"});
  ASSERT_EQ(r.outcome.code, 0) << r.err;
  const tu::Tsv t = tu::ReadTsv(tu::ReadFile(dir_ + "/out/trajectory.tsv"));
  const cr::Coulomb q;
  int m[2] = {0, 0};
  std::vector<cr::Switch> switches;
  std::vector<cr::Piece> pieces;
  cr::Walk(q, cr::Vec{0.1L, 0, -0.25L, 0.05L, 1}, m, 40, &switches, &pieces);
  ASSERT_GE(switches.size(), 8u);
  const char* cols[4] = {"x1", "x1dot", "x2", "x2dot"};
  for (const auto& row : t.rows) {
    const double time = Cell(t, row, "t");
    const cr::Vec z = cr::At(q, pieces, time);
    for (int i = 0; i < 4; ++i) EXPECT_NEAR(Cell(t, row, cols[i]), double(z[i]), 1e-9) << time;
  }
  EXPECT_GT(t.rows.size(), 400u);
}

// The whole study: the blocks fall into step on the single block's Coulomb
// orbit. From there both leave stick at x = mu_s (k = 1, the coupling
// unstretched) at one instant, once per period
// pi + 2 atan(v / (mu_s - mu_k)) + 2 (mu_s - mu_k) / v.
TEST_F(ChainStudyApp, CoulombBlocksFallIntoStepOnTheSingleBlocksOrbit) {
  const auto r = RunOut("ss_simulate", dir_, {"--study", Study("chain2_coulomb")});
  ASSERT_EQ(r.outcome.code, 0) << r.err;
  const tu::Tsv s = tu::ReadTsv(tu::ReadFile(dir_ + "/out/section.tsv"));
  ASSERT_GT(s.rows.size(), 100u);
  const double period = M_PI + 2 * std::atan(2.0) + 1;
  for (size_t k = s.rows.size() - 20; k < s.rows.size(); ++k) {
    for (const char* c : {"x1", "x2"}) EXPECT_NEAR(Cell(s, s.rows[k], c), 0.4, 1e-9) << k;
    for (const char* c : {"x1dot", "x2dot"}) EXPECT_NEAR(Cell(s, s.rows[k], c), 0.2, 1e-9) << k;
    const double dt = Cell(s, s.rows[k], "t") - Cell(s, s.rows[k - 2], "t");
    EXPECT_NEAR(dt, period, 1e-9) << k;
  }
}

// Without damping and with mu'(v) = 0, steady sliding x_i = mu_k is a center
// at every v: largest real part 0, no Hopf point, and the attractor search's
// run from it moved by 0.01 never sticks.
TEST_F(ChainStudyApp, CoulombSteadySlidingIsACenter) {
  const auto r = RunOut("ss_continue", dir_, {"--study", Study("chain2_coulomb")});
  ASSERT_EQ(r.outcome.code, 0) << r.err;
  EXPECT_TRUE(tu::Contains(r.err, "no stick phase")) << r.err;
  const tu::Tsv branch = tu::ReadTsv(tu::ReadFile(dir_ + "/out/branch.tsv"));
  const tu::Tsv special = tu::ReadTsv(tu::ReadFile(dir_ + "/out/special_points.tsv"));
  EXPECT_TRUE(special.rows.empty());
  ASSERT_EQ(branch.rows.size(), 101u);
  for (const auto& row : branch.rows) {
    EXPECT_NEAR(Cell(branch, row, "max_real"), 0, 1e-12);
    for (const char* c : {"x1_0", "x2_0"}) EXPECT_NEAR(Cell(branch, row, c), 0.3, 1e-14);
  }
}
}  // namespace
