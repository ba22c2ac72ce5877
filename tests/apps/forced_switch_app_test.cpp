// ss_continue --restart DIR --point PD1 --switch (issue 20: "PD, with a
// switch onto the doubled branch"; AUTO-07p's ISW = -1): on the forced
// Stribeck study the doubled branch starts at the PD point, has m = 2, and its
// last row is a 2-periodic orbit of the independent long-double map
// (reference/forced_lyapunov.hpp), not a 1-periodic one. Misuse is exit 2
// with one line naming --switch, nothing written.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "app_test_util.hpp"
#include "reference/forced_lyapunov.hpp"
#include "test_paths.hpp"

namespace {

namespace tu = stickslip::testing_util;
const std::string kSwitchStudy = STICKSLIP_SOURCE_DIR "/studies/stribeck_forced.ini";

class ForcedSwitchApp : public tu::AppTest {
 protected:
  void SetUp() override {
    AppTest::SetUp();
    ASSERT_EQ(Run("--study " + kSwitchStudy + " --from 0.7 --to 0.6 --out " + dir_ + "/one"), 0)
        << err_;
  }
  int Run(const std::string& args) { return RunApp(kBin, "ss_continue", args + " --no_plots"); }
  tu::Tsv Table(const std::string& path) const { return tu::ReadTsv(tu::ReadFile(path)); }
  static double Num(const tu::Tsv& t, size_t row, const std::string& col) {
    return std::stod(t.rows.at(row).at(t.Column(col)));
  }
};

TEST_F(ForcedSwitchApp, DoubledBranchStartsAtThePdPointAndIsTwoPeriodic) {
  const tu::Tsv one = Table(dir_ + "/one/special_points.tsv");
  size_t pd = one.rows.size();
  for (size_t i = 0; i < one.rows.size(); ++i)
    if (one.rows[i][one.Column("lab")] == "PD1") pd = i;
  ASSERT_LT(pd, one.rows.size()) << "no PD1 on the m = 1 branch";
  const double w_pd = Num(one, pd, "omega");
  ASSERT_EQ(
      Run("--restart " + dir_ + "/one --point PD1 --switch --to 0.612 --out " + dir_ + "/two"), 0)
      << err_;
  const tu::Tsv two = Table(dir_ + "/two/branch.tsv");
  ASSERT_GT(two.rows.size(), 5u);
  EXPECT_TRUE(tu::Contains(two.meta.at("switch"), "turns 1 -> 2")) << two.meta.at("switch");
  for (size_t i = 0; i < two.rows.size(); ++i) EXPECT_EQ(two.rows[i][two.Column("m")], "2");
  // The first row: next to the PD point (the pitchfork's offset ~ ds).
  EXPECT_LT(std::abs(Num(two, 0, "omega") - w_pd), 1e-4);
  EXPECT_LT(std::hypot(Num(two, 0, "x_0") - Num(one, pd, "x_0"),
                       Num(two, 0, "xdot_0") - Num(one, pd, "xdot_0")),
            0.02);
  // The last row at omega = 0.612: closes after two forcing periods of the
  // reference map, not after one.
  const size_t last = two.rows.size() - 1;
  EXPECT_NEAR(Num(two, last, "omega"), 0.612, 1e-12);
  stickslip::ForcedBeltParams p;
  p.base.law = stickslip::LawKind::kStribeck;
  p.base.mu_s = 0.4, p.base.mu_k = 0.25, p.base.v_s = 0.2, p.base.beta = 0.05, p.base.v = 0.25;
  p.force = 0.3, p.omega = Num(two, last, "omega");
  const stickslip::reference::ForcedRef m(p);
  const double x0 = Num(two, last, "x_0"), y0 = Num(two, last, "xdot_0");
  const auto a = stickslip::reference::RefOnePeriod(m, x0, y0, y0 == 0.25, 1e-16L);
  const auto b = stickslip::reference::RefOnePeriod(m, a.x, a.y, a.stuck, 1e-16L);
  ASSERT_TRUE(a.ok && b.ok);
  EXPECT_GT(std::hypot(double(a.x) - x0, double(a.y) - y0), 1e-2);
  EXPECT_LT(std::hypot(double(b.x) - x0, double(b.y) - y0), 1e-9);
}

// Without --from and --to the doubled branch takes the range of the run the
// PD point came from (0.7 .. 0.6 here), as AUTO keeps RL0 and RL1.
TEST_F(ForcedSwitchApp, WithoutARangeTheDoubledBranchKeepsTheRunsRange) {
  ASSERT_EQ(Run("--restart " + dir_ + "/one --point PD1 --switch --out " + dir_ + "/two"), 0)
      << err_;
  const tu::Tsv two = Table(dir_ + "/two/branch.tsv");
  ASSERT_GT(two.rows.size(), 5u);
  for (size_t i = 0; i < two.rows.size(); ++i) {
    EXPECT_EQ(two.rows[i][two.Column("m")], "2");
    EXPECT_GE(Num(two, i, "omega"), 0.6 - 1e-12);
    EXPECT_LE(Num(two, i, "omega"), 0.7 + 1e-12);
  }
}

TEST_F(ForcedSwitchApp, MisuseIsExitTwoWithOneLineNamingSwitch) {
  const std::string out = " --out " + dir_ + "/bad";
  for (const std::string& args :
       {"--restart " + dir_ + "/one --point LP1 --switch",
        "--restart " + dir_ + "/one --point PD1 --switch --from 0.62 --to 0.7",
        "--restart " + dir_ + "/one --point PD1 --switch --param force", std::string("--switch")}) {
    EXPECT_EQ(Run(args + out), 2) << args;
    EXPECT_TRUE(tu::Contains(err_, "--switch")) << err_;
    EXPECT_EQ(std::count(err_.begin(), err_.end(), '\n'), 1) << err_;
    EXPECT_FALSE(tu::Exists(dir_ + "/bad")) << args;
  }
}

}  // namespace
