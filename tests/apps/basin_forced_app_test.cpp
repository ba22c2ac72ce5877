// End-to-end tests of ss_basin --force (issue 21 item 4): a small grid on the
// forced coulomb belt writes both coexisting period-1 attractors, one with a
// stick and one without; bad forced input is exit 2 naming the option.
#include <gtest/gtest.h>
#include <stdlib.h>

#include <algorithm>
#include <string>
#include <vector>

#include "app_test_util.hpp"

namespace {

namespace tu = stickslip::testing_util;
class BasinForcedApp : public tu::AppTest {};

const std::vector<std::string> kBelt = {"--law",   "coulomb", "--mu_s",  "0.4", "--mu_k",
                                        "0.25",    "--beta",  "0.05",    "--v", "0.2",
                                        "--force", "0.3",     "--omega", "0.45"};

TEST_F(BasinForcedApp, FindsBothCoexistingOrbits) {
  const std::string dir = NewDir();
  std::vector<std::string> args = kBelt;
  args.insert(args.end(), {"--nx", "6", "--ny", "6", "--x_min", "0.3", "--x_max", "0.8",
                           "--xdot_min", "-0.2", "--xdot_max", "0.2"});
  const AppRun r = RunOut("ss_basin", dir, args);
  ASSERT_EQ(r.outcome.code, 0) << r.err;
  const tu::Tsv a = tu::ReadTsv(tu::ReadFile(dir + "/out/attractors.tsv"));
  ASSERT_EQ(a.rows.size(), 2u);
  std::vector<std::string> sticks;
  for (const auto& row : a.rows) {
    EXPECT_EQ(row[a.Column("kind")], "periodic");
    EXPECT_EQ(row[a.Column("m")], "1");
    sticks.push_back(row[a.Column("sticks")]);
  }
  std::sort(sticks.begin(), sticks.end());
  EXPECT_EQ(sticks, (std::vector<std::string>{"0", "1"}));
  EXPECT_EQ(tu::ReadTsv(tu::ReadFile(dir + "/out/basins_forced.tsv")).rows.size(), 36u);
}

TEST_F(BasinForcedApp, BadForcedInputIsExitTwo) {
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {{"--omega", "0.5"}, "--omega"},
      {{"--force", "0.3", "--keep", "4"}, "--keep"},
      {{"--force", "0.3", "--omega", "-1"}, "omega"},
      {{"--force", "0.3", "--nx", "0"}, "--nx"},
      {{"--force", "0.3", "--x_min", "1"}, "--x_min"}};
  for (const auto& [args, name] : cases) {
    const std::string dir = NewDir();
    const AppRun r = RunOut("ss_basin", dir, args);
    EXPECT_EQ(r.outcome.code, 2) << args[0] << " " << r.err;
    EXPECT_TRUE(tu::Contains(r.err, name)) << r.err;
    EXPECT_FALSE(tu::Exists(dir + "/out"));
  }
}

}  // namespace
