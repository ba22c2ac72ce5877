// ss_continue --force starts on the orbit that is there: by default on the
// attractor the transient from rest reaches, with its period (a period-11
// stick-slip attractor of the seed belt at A 0.1, Omega 1.5, as ss_basin
// finds it); --all on each orbit of the start list (the scan's orbits and
// the attractor), --m M / --point N on one of them (docs/cli.md). Each
// branch's first row is checked against the flow itself: iterated at a
// tighter tolerance (no Newton), it returns after m forcing periods, not
// before, with the row's stick count.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "app_test_util.hpp"
#include "forced_fixed_point.hpp"
#include "forced_run.hpp"
#include "stickslip/systems/forced/flow.hpp"
#include "stickslip/systems/forced/forced.hpp"

namespace {

namespace tu = stickslip::testing_util;
class ForcedStartApp : public tu::AppTest {};

const std::vector<std::string> kAt = {"--law",   "cubic", "--v",     "0.25",  "--beta", "0.05",
                                      "--force", "0.1",   "--param", "omega", "--from", "1.5"};

std::vector<std::string> With(std::vector<std::string> extra) {
  std::vector<std::string> a = kAt;
  a.insert(a.end(), extra.begin(), extra.end());
  return a;
}

double Cell(const tu::Tsv& t, const std::vector<std::string>& row, const std::string& col) {
  return std::stod(row[t.Column(col)]);
}

using stickslip::testing_util::ExpectFixedPointOfPm;

TEST_F(ForcedStartApp, StartsOnThePeriodElevenAttractorWhereNoPeriodOneOrbitIs) {
  const std::string dir = NewDir();
  const AppRun r = RunOut("ss_continue", dir, With({"--to", "1.505"}));
  ASSERT_TRUE(tu::Exists(dir + "/out/branch.tsv")) << r.err;
  const tu::Tsv t = tu::ReadTsv(tu::ReadFile(dir + "/out/branch.tsv"));
  ASSERT_FALSE(t.rows.empty());
  const auto& row = t.rows.front();
  EXPECT_DOUBLE_EQ(Cell(t, row, "omega"), 1.5);
  EXPECT_EQ(row[t.Column("m")], "11");
  EXPECT_EQ(row[t.Column("sticks")], "5");
  EXPECT_EQ(row[t.Column("stable")], "1");
  ExpectFixedPointOfPm(Cell(t, row, "x_0"), Cell(t, row, "xdot_0"), 11, 5);
}

// The scan's three orbits at Omega 1.5 (as ss_simulate --orbits --max_m 12
// lists them): the unstable non-stop m = 1 orbit, the period-11 attractor
// and its unstable period-11 partner; one branch each, up to Omega 1.5005,
// before their fold at 1.50064.
TEST_F(ForcedStartApp, AllContinuesEachOrbitOfTheStartList) {
  const std::string dir = NewDir();
  const AppRun r = RunOut("ss_continue", dir, With({"--to", "1.5005", "--all"}));
  ASSERT_EQ(r.outcome.code, 0) << r.err;
  EXPECT_TRUE(tu::Contains(r.out, "2: m = 11, 5 sticks"));
  EXPECT_TRUE(tu::Contains(r.out, "the attractor reached from rest"));
  const tu::Tsv t = tu::ReadTsv(tu::ReadFile(dir + "/out/branch.tsv"));
  struct Want {
    int m, sticks, stable;
  };
  const Want want[3] = {{1, 0, 0}, {11, 5, 1}, {11, 5, 0}};
  for (int b = 1; b <= 3; ++b) {
    SCOPED_TRACE("branch " + std::to_string(b));
    const std::vector<std::string>* first = nullptr;
    for (const auto& row : t.rows)
      if (row[t.Column("branch")] == std::to_string(b)) {
        first = &row;
        break;
      }
    ASSERT_NE(first, nullptr);
    const Want& w = want[b - 1];
    EXPECT_DOUBLE_EQ(Cell(t, *first, "omega"), 1.5);
    EXPECT_EQ((*first)[t.Column("m")], std::to_string(w.m));
    EXPECT_EQ((*first)[t.Column("sticks")], std::to_string(w.sticks));
    EXPECT_EQ((*first)[t.Column("stable")], std::to_string(w.stable));
    EXPECT_EQ(Cell(t, *first, "mult_max") < 1, w.stable == 1);
    ExpectFixedPointOfPm(Cell(t, *first, "x_0"), Cell(t, *first, "xdot_0"), w.m, w.sticks);
  }
}

// --m 11 --point 2: the second period-11 orbit, the unstable one.
TEST_F(ForcedStartApp, PeriodAndPointChooseOneOrbit) {
  const std::string dir = NewDir();
  const AppRun r =
      RunOut("ss_continue", dir, With({"--to", "1.5005", "--m", "11", "--point", "2"}));
  ASSERT_EQ(r.outcome.code, 0) << r.err;
  const tu::Tsv t = tu::ReadTsv(tu::ReadFile(dir + "/out/branch.tsv"));
  ASSERT_FALSE(t.rows.empty());
  const auto& row = t.rows.front();
  EXPECT_EQ(row[t.Column("m")], "11");
  EXPECT_EQ(row[t.Column("sticks")], "5");
  EXPECT_EQ(row[t.Column("stable")], "0");
  EXPECT_GT(Cell(t, row, "mult_max"), 1.5);
  ExpectFixedPointOfPm(Cell(t, row, "x_0"), Cell(t, row, "xdot_0"), 11, 5);
  for (const auto& other : t.rows) EXPECT_EQ(other[t.Column("branch")], "1");
}

// Bad choices: exit 2, one line naming the option and value, nothing written.
TEST_F(ForcedStartApp, BadChoicesAreUsageErrors) {
  struct Case {
    std::vector<std::string> args;
    std::string says;
  };
  const std::vector<Case> cases = {
      {With({"--m", "0"}), "invalid value '0' for --m"},
      {With({"--m", "65"}), "invalid value '65' for --m"},
      {With({"--m", "2.5"}), "invalid value '2.5' for --m"},
      {With({"--point", "0"}), "invalid value '0' for --point"},
      {With({"--point", "x"}), "invalid value 'x' for --point"},
      {With({"--to", "1.5005", "--point", "4"}), "invalid value '4' for --point"},
      {With({"--all", "--point", "1"}), "--point 1"},
      {{"--m", "2"}, "--m"},
      {{"--all"}, "--all"},
  };
  for (const Case& c : cases) {
    const std::string dir = NewDir();
    const AppRun r = RunOut("ss_continue", dir, c.args);
    SCOPED_TRACE(c.says);
    EXPECT_EQ(r.outcome.code, 2) << r.err;
    EXPECT_TRUE(tu::Contains(r.err, c.says));
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_FALSE(tu::Exists(dir + "/out/branch.tsv"));
  }
}

}  // namespace
