// A system with a clock in ss_continue's system run (clock_start.hpp,
// docs/systems.md): studies/models/forced.ini, the forced seed belt written
// as a model file, gets the built-in forced oscillator's start list (--all,
// --m, --point), each branch's first row checked against the built-in
// model's flow at a tighter tolerance; and a Den Hartog block written as a
// file is traced from both ends of its undamped resonance, the rows on his
// closed form and the gap named.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "app_test_util.hpp"
#include "forced_fixed_point.hpp"
#include "forced_reference.hpp"
#include "forced_run.hpp"
#include "stickslip/systems/forced/flow.hpp"

namespace {

namespace tu = stickslip::testing_util;
using stickslip::forced_reference::DenHartogX;
class ClockStartApp : public tu::AppTest {};

const std::string kForcedFile = STICKSLIP_SOURCE_DIR "/studies/models/forced.ini";

double Cell(const tu::Tsv& t, const std::vector<std::string>& row, const std::string& col) {
  return std::stod(row[t.Column(col)]);
}

using stickslip::testing_util::ExpectFixedPointOfPm;

const std::vector<std::string> kAt = {"--model", kForcedFile, "--set",  "force=0.1,omega=1.5",
                                      "--param", "omega",     "--from", "1.5",
                                      "--to",    "1.5005"};

// The three orbits at Omega 1.5 the built-in forced oscillator's start list
// has (tests/apps/forced_start_app_test.cpp): the unstable non-stop m = 1
// orbit, the period-11 attractor and its unstable partner; one branch each.
TEST_F(ClockStartApp, AllContinuesEachOrbitOfTheModelFilesStartList) {
  const std::string dir = NewDir();
  std::vector<std::string> a = kAt;
  a.push_back("--all");
  const AppRun r = RunOut("ss_continue", dir, a);
  ASSERT_EQ(r.outcome.code, 0) << r.err;
  EXPECT_TRUE(tu::Contains(r.out, "2: m = 11, 5 sticks")) << r.out;
  EXPECT_TRUE(tu::Contains(r.out, "the attractor reached from rest")) << r.out;
  const tu::Tsv t = tu::ReadTsv(tu::ReadFile(dir + "/out/branch.tsv"));
  struct Want {
    int m, sticks, stable;
  };
  const Want want[3] = {{1, 0, 0}, {11, 5, 1}, {11, 5, 0}};
  for (int b = 1; b <= 3; ++b) {
    SCOPED_TRACE("branch " + std::to_string(b));
    const auto first = std::find_if(t.rows.begin(), t.rows.end(), [&](const auto& row) {
      return row[t.Column("branch")] == std::to_string(b);
    });
    ASSERT_NE(first, t.rows.end());
    const Want& w = want[b - 1];
    EXPECT_DOUBLE_EQ(Cell(t, *first, "omega"), 1.5);
    EXPECT_EQ((*first)[t.Column("m")], std::to_string(w.m));
    EXPECT_EQ((*first)[t.Column("sticks")], std::to_string(w.sticks));
    EXPECT_EQ((*first)[t.Column("stable")], std::to_string(w.stable));
    ExpectFixedPointOfPm(Cell(t, *first, "x_0"), Cell(t, *first, "xdot_0"), w.m, w.sticks);
  }
}

// --m 11 --point 2: the unstable period-11 orbit; a restart from one of its
// points reads its m (the row's, not the first start's).
TEST_F(ClockStartApp, PeriodAndPointChooseOneOrbitAndItsRowsKeepTheirPeriod) {
  const std::string dir = NewDir();
  std::vector<std::string> a = kAt;
  a.insert(a.end(), {"--m", "11", "--point", "2"});
  const AppRun r = RunOut("ss_continue", dir, a);
  ASSERT_EQ(r.outcome.code, 0) << r.err;
  const tu::Tsv t = tu::ReadTsv(tu::ReadFile(dir + "/out/branch.tsv"));
  ASSERT_FALSE(t.rows.empty());
  const auto& row = t.rows.front();
  EXPECT_EQ(row[t.Column("m")], "11");
  EXPECT_EQ(row[t.Column("stable")], "0");
  EXPECT_GT(Cell(t, row, "mult_max"), 1.5);
  ExpectFixedPointOfPm(Cell(t, row, "x_0"), Cell(t, row, "xdot_0"), 11, 5);
  for (const auto& other : t.rows) EXPECT_EQ(other[t.Column("branch")], "1");
}

// Without a clock the choice is refused: exit 2, one line naming it.
TEST_F(ClockStartApp, AStartChoiceNeedsAClock) {
  for (const std::vector<std::string>& extra :
       {std::vector<std::string>{"--all"}, {"--m", "2"}, {"--point", "1"}}) {
    const std::string dir = NewDir();
    std::vector<std::string> a = {"--system", "chain", "--param", "v", "--to", "0.3"};
    a.insert(a.end(), extra.begin(), extra.end());
    const AppRun r = RunOut("ss_continue", dir, a);
    EXPECT_EQ(r.outcome.code, 2) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_TRUE(tu::Contains(r.err, extra[0])) << r.err;
    EXPECT_FALSE(tu::Exists(dir + "/out")) << r.err;
  }
}

// Den Hartog's (1931) block, x'' + x = F(x') + A cos(Omega t), coulomb mu =
// 0.3, A = 1, written as a model file: undamped, |x| passes max_amplitude
// near Omega = 1, so the branch from 0.75 ends there (unbounded) and one from
// 2.5 is traced back; every non-stop row on his closed form, the gap named.
TEST_F(ClockStartApp, AnUnboundedResonanceIsTracedFromBothEnds) {
  const std::string dir = NewDir(), file = dir + "/den_hartog.ini";
  tu::WriteFile(file,
                "name = den_hartog\ncoordinates = x\nclock theta = omega\nparameter mu = 0.3\n"
                "parameter force = 1\nparameter omega = 1\nx'' = -x + F + force*cos(theta)\n"
                "contact F = x'\nlaw F = mu\n");
  const AppRun r = RunOut("ss_continue", dir,
                          {"--model", file, "--param", "omega", "--from", "0.75", "--to", "2.5",
                           "--max_amplitude", "20"});
  ASSERT_EQ(r.outcome.code, 0) << r.err;
  const tu::Tsv t = tu::ReadTsv(tu::ReadFile(dir + "/out/branch.tsv"));
  ASSERT_TRUE(t.meta.count("gap"));
  EXPECT_TRUE(tu::Contains(t.meta.at("gap"), "unbounded resonance")) << t.meta.at("gap");
  double end1 = 0, end2 = 0, worst = 0;  // the largest Omega of branches 1 and 2
  int compared = 0;
  for (const auto& row : t.rows) {
    const double w = Cell(t, row, "omega");
    const int branch = std::stoi(row[t.Column("branch")]);
    if (branch == 1) end1 = std::max(end1, w);
    if (branch == 2) end2 = std::max(end2, w);
    if (row[t.Column("kind")] != "pure-slip") continue;
    const double X = DenHartogX(0.3, 1, w);
    worst = std::max(worst, std::abs(Cell(t, row, "x_max") - X) / std::max(1.0, X));
    ++compared;
  }
  EXPECT_GT(compared, 100);
  EXPECT_LT(worst, 1e-12);  // measured 1.9e-14
  EXPECT_LT(end1, 1) << "branch 1 stops below the resonance";
  EXPECT_EQ(end2, 2.5) << "branch 2 starts at --to";
  // The figure shades the gap, from branch 1's last Omega to branch 2's.
  const std::string gp = tu::ReadFile(dir + "/out/bifurcation.gp");
  EXPECT_TRUE(tu::Contains(gp, "rect from " + t.meta.at("gap").substr(19, 10))) << gp;
  EXPECT_TRUE(tu::Contains(gp, "not traced: unbounded")) << gp;
  std::printf("[ measured ] %d non-stop rows: max |x_max - X| / max(1, X) = %.2e\n", compared,
              worst);
}

}  // namespace
