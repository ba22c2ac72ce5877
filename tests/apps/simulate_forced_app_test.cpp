// End-to-end tests of ss_simulate --force (issue 20, item 1): the trajectory,
// the stroboscopic section (phase 0, settling on Den Hartog's non-stop orbit)
// and the exit section (every point on the edge of the stick band), and bad
// forced input as exit 2 with one line naming the option, nothing written.
#include <gtest/gtest.h>
#include <stdlib.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "app_test_util.hpp"
#include "forced_reference.hpp"

namespace {

namespace tu = stickslip::testing_util;
using stickslip::forced_reference::DenHartogX;
// ss_simulate's run with its two tables read (empty if not written).
class SimulateForcedApp : public tu::AppTest {
 protected:
  struct Result {
    tu::Outcome outcome;
    std::string err;
    tu::Tsv traj, section;
  };
  Result RunApp(const std::string& dir, const std::vector<std::string>& args) {
    const AppRun run = RunOut("ss_simulate", dir, args);
    Result r{run.outcome, run.err, {}, {}};
    if (tu::Exists(dir + "/out/trajectory.tsv")) {
      r.traj = tu::ReadTsv(tu::ReadFile(dir + "/out/trajectory.tsv"));
      r.section = tu::ReadTsv(tu::ReadFile(dir + "/out/section.tsv"));
    }
    return r;
  }
};

size_t Col(const tu::Tsv& t, const std::string& name) {
  const auto it = std::find(t.columns.begin(), t.columns.end(), name);
  EXPECT_NE(it, t.columns.end()) << name;
  return static_cast<size_t>(it - t.columns.begin());
}

TEST_F(SimulateForcedApp, StroboscopicSectionSettlesOnDenHartogsOrbit) {
  const std::string dir = NewDir();
  const double w = 1.5, T = 2 * M_PI / w;
  const Result r =
      RunApp(dir, {"--law", "coulomb", "--mu_s", "0.3", "--mu_k", "0.3", "--v", "0", "--beta", "0",
                   "--force", "1", "--omega", "1.5", "--t_end", "300", "--dt", "0.001"});
  ASSERT_EQ(r.outcome.code, 0) << r.err;
  EXPECT_EQ(r.traj.meta.at("status"), "complete");
  EXPECT_EQ(r.section.meta.at("section"), "strobe");
  const size_t t = Col(r.section, "t"), x = Col(r.section, "x"), xd = Col(r.section, "xdot"),
               n = Col(r.section, "n");
  ASSERT_EQ(r.section.rows.size(), static_cast<size_t>(std::floor(300 / T)) + 1);
  for (size_t i = 0; i < r.section.rows.size(); ++i) {
    EXPECT_EQ(std::stol(r.section.rows[i][n]), static_cast<long>(i));
    EXPECT_NEAR(std::stod(r.section.rows[i][t]), i * T, 1e-9 * (1 + i * T));
  }
  // The last two points agree: a fixed point of the stroboscopic map.
  const auto& a = r.section.rows[r.section.rows.size() - 2];
  const auto& b = r.section.rows.back();
  EXPECT_NEAR(std::stod(a[x]), std::stod(b[x]), 1e-8);
  EXPECT_NEAR(std::stod(a[xd]), std::stod(b[xd]), 1e-8);
  // Over the last period the rows (every 0.001) reach Den Hartog's amplitude.
  const size_t tt = Col(r.traj, "t"), tx = Col(r.traj, "x"), ph = Col(r.traj, "theta");
  double x_max = -1e9;
  for (const auto& row : r.traj.rows) {
    if (std::stod(row[tt]) >= 300 - T) x_max = std::max(x_max, std::stod(row[tx]));
    const double p = std::stod(row[ph]);
    ASSERT_TRUE(p >= 0 && p < 2 * M_PI) << p;
  }
  EXPECT_NEAR(x_max, DenHartogX(0.3, 1, w), 1e-5);  // the sampling's (w dt)^2 X / 2
}

TEST_F(SimulateForcedApp, ExitSectionLiesOnTheStickBandsEdge) {
  const std::string dir = NewDir();
  const double mu_s = 0.4, beta = 0.05, v = 0, a = 0.7, w = 0.6;
  const Result r = RunApp(
      dir, {"--law", "coulomb", "--mu_s", "0.4", "--mu_k", "0.3", "--v", "0", "--beta", "0.05",
            "--force", "0.7", "--omega", "0.6", "--t_end", "200", "--section", "exit"});
  ASSERT_EQ(r.outcome.code, 0) << r.err;
  EXPECT_EQ(r.section.meta.at("section"), "exit");
  const size_t t = Col(r.section, "t"), x = Col(r.section, "x"), xd = Col(r.section, "xdot"),
               mode = Col(r.section, "mode"), ph = Col(r.section, "theta");
  ASSERT_GT(r.section.rows.size(), 5u);
  for (const auto& row : r.section.rows) {
    EXPECT_EQ(std::stod(row[xd]), v);
    EXPECT_NE(row[mode], "stick");
    // |x + 2 beta v - A cos(Omega t)| = mu_s at an exit.
    const double f = std::stod(row[x]) + 2 * beta * v - a * std::cos(w * std::stod(row[t]));
    EXPECT_NEAR(std::abs(f), mu_s, 1e-9);
    EXPECT_NEAR(std::stod(row[ph]), std::fmod(w * std::stod(row[t]), 2 * M_PI), 1e-9);
  }
  // Every exit has a row in the trajectory too.
  EXPECT_GE(r.traj.rows.size(), 200 / 0.01);
}

// The forced studies run in ss_continue from their files, and give the points
// docs/studies.md reads off them.
TEST_F(SimulateForcedApp, ForcedStudiesRunInSsContinue) {
  const std::string studies = STICKSLIP_SOURCE_DIR "/studies/";
  const std::vector<std::pair<std::string, std::vector<std::pair<std::string, double>>>> cases = {
      {"floor_static", {}},
      {"seed_forced", {{"LP", 0.62857}, {"PD", 0.61397}}},
      {"stribeck_forced", {{"LP", 0.63020}, {"LP", 0.62374}, {"PD", 0.61821}}}};
  for (const auto& [study, points] : cases) {
    const std::string dir = NewDir();
    tu::Launch l;
    l.out_path = dir + "/stdout", l.err_path = dir + "/stderr";
    const tu::Outcome o =
        tu::RunChild(STICKSLIP_BIN_DIR "/ss_continue",
                     {"--study", studies + study + ".ini", "--no_plots", "--out", dir + "/out"}, l);
    ASSERT_EQ(o.code, 0) << study << ": " << tu::ReadFile(l.err_path);
    const tu::Tsv b = tu::ReadTsv(tu::ReadFile(dir + "/out/branch.tsv"));
    EXPECT_GT(b.rows.size(), 100u) << study;
    const tu::Tsv sp = tu::ReadTsv(tu::ReadFile(dir + "/out/special_points.tsv"));
    for (const auto& [label, at] : points) {
      bool found = false;
      for (const auto& row : sp.rows)
        found = found || (row[0] == label && std::abs(std::stod(row[2]) - at) < 1e-5);
      EXPECT_TRUE(found) << study << ": " << label << " at " << at;
    }
  }
}

TEST_F(SimulateForcedApp, BadForcedInputIsExitTwoNamingTheOption) {
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {{"--force", "1", "--omega", "0"}, "omega"},
      {{"--force", "-1"}, "force"},
      {{"--omega", "2"}, "--omega"},
      {{"--section", "exit"}, "--section"},
      {{"--force", "1", "--section", "poincare"}, "'poincare' for --section"},
      {{"--force", "1", "--mass", "1"}, "--mass"},
      {{"--force", "1", "--t_end", "0"}, "--t_end"},
      {{"--force", "1", "--section", "exit", "--orbits"}, "--section applies to a trajectory"},
      {{"--force", "1", "--max_amplitude", "3"}, "--max_amplitude bounds a branch"},
  };
  for (const auto& c : cases) {
    const std::string dir = NewDir();
    const Result r = RunApp(dir, c.first);
    EXPECT_EQ(r.outcome.code, 2) << c.second << ": " << r.err;
    EXPECT_TRUE(tu::Contains(r.err, c.second)) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_FALSE(tu::Exists(dir + "/out")) << c.second;
  }
}

}  // namespace
