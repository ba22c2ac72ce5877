// End-to-end tests of ss_orbit_diagram (issue 21 item 1): on a linear window
// (coulomb, pure slip below the belt: x'' + 2 beta x' + x = mu_k + A cos(Omega t))
// every section point is the closed-form steady state and the exponent is
// -beta, and the stick-slip orbit that coexists at its end shows as
// hysteresis between the sweeps; bad input is exit 2 with one line naming the option, nothing
// written.
#include <gtest/gtest.h>
#include <stdlib.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "app_test_util.hpp"

namespace {

namespace tu = stickslip::testing_util;
class OrbitDiagramApp : public tu::AppTest {};

const std::vector<std::string> kLinear = {
    "--law", "coulomb", "--mu_s",  "0.4", "--mu_k",      "0.25",  "--beta", "0.05",
    "--v",   "0.2",     "--force", "0.3", "--param",     "omega", "--from", "0.3",
    "--to",  "0.45",    "--n",     "7",   "--transient", "400",   "--keep", "20"};

TEST_F(OrbitDiagramApp, LinearWindowMatchesClosedFormSteadyState) {
  const std::string dir = NewDir();
  const AppRun r = RunOut("ss_orbit_diagram", dir, kLinear);
  ASSERT_EQ(r.outcome.code, 0) << r.err;
  const tu::Tsv t = tu::ReadTsv(tu::ReadFile(dir + "/out/orbit_diagram.tsv"));
  const int w = t.Column("omega"), x = t.Column("x"), xd = t.Column("xdot"),
            sticks = t.Column("sticks"), lam = t.Column("lyapunov"), d = t.Column("direction");
  ASSERT_TRUE(w >= 0 && x >= 0 && xd >= 0 && sticks >= 0 && lam >= 0 && d >= 0);
  ASSERT_EQ(t.rows.size(), 2u * 7 * 20);  // both directions, 7 values, 20 points each
  int up = 0;
  for (const auto& row : t.rows) {
    if (row[d] == "down" && row[w] == "0.45") {
      // Coexistence: from rest at 0.45 the down sweep finds the stable
      // stick-slip orbit; the up sweep, continued, stays on pure slip.
      EXPECT_EQ(row[sticks], "1");
      EXPECT_LT(std::stod(row[lam]), -0.01);
      continue;
    }
    const double W = std::stod(row[w]), beta = 0.05, a = 0.3, mu_k = 0.25;
    // x = mu_k + X cos(Omega t - phi): at phase 0, x = mu_k + A (1 - W^2) / D,
    // x' = A 2 beta W^2 / D, D = (1 - W^2)^2 + (2 beta W)^2.
    const double D = (1 - W * W) * (1 - W * W) + 4 * beta * beta * W * W;
    EXPECT_NEAR(std::stod(row[x]), mu_k + a * (1 - W * W) / D, 1e-8) << W;
    EXPECT_NEAR(std::stod(row[xd]), a * 2 * beta * W * W / D, 1e-8) << W;
    EXPECT_EQ(row[sticks], "0");
    EXPECT_NEAR(std::stod(row[lam]), -beta, 1e-3);
    up += row[d] == "up";
  }
  EXPECT_EQ(up, 7 * 20);
  const tu::Tsv e = tu::ReadTsv(tu::ReadFile(dir + "/out/lyapunov.tsv"));
  EXPECT_EQ(e.rows.size(), 14u);
  EXPECT_EQ(e.meta.at("status"), "0 values failed");
}

TEST_F(OrbitDiagramApp, DrawsTheFigure) {
  if (!tu::HaveGnuplot()) GTEST_SKIP() << "gnuplot not installed";
  const std::string dir = NewDir();
  const AppRun r = RunOut("ss_orbit_diagram", dir, kLinear, true);
  ASSERT_EQ(r.outcome.code, 0) << r.err;
  EXPECT_TRUE(tu::Exists(dir + "/out/orbit_diagram.png"));
}

// Every value fails (|x| passes --max_amplitude at once): the tables are
// written with a `# failed:` line per value and no figure (gnuplot has no
// range to draw), exit 1; it used to leave an empty --out and no tables.
TEST_F(OrbitDiagramApp, EveryValueFailedWritesTheTablesWithoutAFigure) {
  const std::string dir = NewDir();
  const AppRun r = RunOut("ss_orbit_diagram", dir,
                          {"--force", "0.3", "--n", "3", "--transient", "10", "--keep", "10",
                           "--max_amplitude", "0.001"},
                          true);
  EXPECT_EQ(r.outcome.code, 1) << r.err;
  const tu::Tsv e = tu::ReadTsv(tu::ReadFile(dir + "/out/lyapunov.tsv"));
  EXPECT_EQ(e.rows.size(), 0u);
  EXPECT_EQ(e.meta.at("status"), "6 values failed");
  EXPECT_NE(tu::ReadFile(dir + "/out/orbit_diagram.tsv").find("# failed: up omega = 0.5"),
            std::string::npos);
  EXPECT_FALSE(tu::Exists(dir + "/out/orbit_diagram.png"));
}

TEST_F(OrbitDiagramApp, TimeLimitWritesAPartialResult) {
  const std::string dir = NewDir();
  const AppRun r = RunOut("ss_orbit_diagram", dir,
                          {"--law", "stribeck", "--beta", "0.01", "--v", "0.1", "--force", "0.5",
                           "--from", "0.2", "--to", "1.2", "--n", "2000", "--max_time", "0.5"});
  EXPECT_EQ(r.outcome.code, 1) << r.err;
  const tu::Tsv e = tu::ReadTsv(tu::ReadFile(dir + "/out/lyapunov.tsv"));
  EXPECT_EQ(e.meta.at("status").rfind("partial (time limit", 0), 0u) << e.meta.at("status");
  EXPECT_LT(e.rows.size(), 4000u);
}

TEST_F(OrbitDiagramApp, BadInputIsExitTwoNamingTheOption) {
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {{"--param", "mu_k"}, "--param"},  // the cubic law has none
      {{"--n", "1"}, "--n"},
      {{"--keep", "abc"}, "--keep"},
      {{"--direction", "sideways"}, "--direction"},
      {{"--n", "4", "--chunks", "5"}, "--chunks"},
      {{"--integrator", "cvode", "--rtol", "1e-14"}, "rtol"},
      {{"--from", "1", "--to", "1"}, "--to"},
      {{"--force", "-1"}, "force"},
      {{"--param", "force", "--from", "-0.5"}, "--from"}};
  for (const auto& [args, name] : cases) {
    const std::string dir = NewDir();
    const AppRun r = RunOut("ss_orbit_diagram", dir, args);
    EXPECT_EQ(r.outcome.code, 2) << args[0] << " " << r.err;
    EXPECT_TRUE(tu::Contains(r.err, name)) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_FALSE(tu::Exists(dir + "/out")) << args[0];
  }
}

}  // namespace
