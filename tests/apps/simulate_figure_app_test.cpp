// The data behind ss_simulate's phase portrait: its script, run by gnuplot
// into a table (set table), draws the stick set x' = v, |x + 2 beta v| <= mu_s
// from end to end (the seed set: x from -0.425 to 0.375 at x' = 0.25).
#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "app_test_util.hpp"

namespace {

namespace tu = stickslip::testing_util;
class SimulateFigureApp : public tu::AppTest {};

TEST_F(SimulateFigureApp, PhasePortraitDrawsTheWholeStickSet) {
  if (!tu::HaveGnuplot()) GTEST_SKIP() << "no gnuplot";
  const std::string dir = NewDir();
  const auto r =
      RunOut("ss_simulate", dir,
             {"--study", std::string(STICKSLIP_SOURCE_DIR) + "/studies/seed.ini", "--t_end", "20"});
  ASSERT_EQ(r.outcome.code, 0) << r.err;
  const std::string out = dir + "/out";
  std::string gp = tu::ReadFile(out + "/trajectory.gp");
  const auto at = gp.find("set output");
  ASSERT_NE(at, std::string::npos);
  gp.replace(at, gp.find('\n', at) - at, "set output '/dev/null'\nset table 'table.txt'");
  tu::WriteFile(out + "/table.gp", gp);
  ASSERT_EQ(std::system(("cd " + tu::ShellQuoted(out) + " && gnuplot table.gp >/dev/null").c_str()),
            0);
  // The curve titled as the stick set, its defined points.
  std::istringstream is(tu::ReadFile(out + "/table.txt"));
  std::vector<std::pair<double, double>> points;
  bool in = false;
  for (std::string line; std::getline(is, line);) {
    if (line.rfind("# Curve title: ", 0) == 0) {
      in = line.find("stick set") != std::string::npos;
      continue;
    }
    if (!in || line.empty() || line[0] == '#') continue;
    std::istringstream ls(line);
    double x = 0, y = 0;
    std::string type;
    if (ls >> x >> y >> type && type != "u") points.emplace_back(x, y);
  }
  const double beta = 0.05, v = 0.25, mu_s = 0.4;
  ASSERT_EQ(points.size(), 2u) << "both ends of the stick set";
  EXPECT_NEAR(points[0].first, -mu_s - 2 * beta * v, 1e-6);
  EXPECT_NEAR(points[1].first, mu_s - 2 * beta * v, 1e-6);
  EXPECT_NEAR(points[0].second, v, 1e-6);
  EXPECT_NEAR(points[1].second, v, 1e-6);
}

}  // namespace
