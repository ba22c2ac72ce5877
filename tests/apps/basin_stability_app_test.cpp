// End-to-end tests of ss_basin's exact basin stability: the printed
// "basin stability <attractor> <fraction>" lines and their copy in orbits.tsv;
// the curve against v (--param) agrees with single-point runs in the same box;
// bad curve options exit 2 with one line naming the option, writing nothing.
#include <gtest/gtest.h>
#include <stdlib.h>
#include <sys/wait.h>

#include <cmath>
#include <cstdlib>
#include <sstream>
#include <string>

#include "app_test_util.hpp"
#include "test_paths.hpp"

namespace {

using stickslip::testing_util::Contains;
using stickslip::testing_util::Exists;
using stickslip::testing_util::ReadFile;
using stickslip::testing_util::ReadTsv;
using stickslip::testing_util::Tsv;

const std::string kBox = " --x_min -0.4 --x_max 1.0 --xdot_min -0.8 --xdot_max 0.7";

class BasinStabilityApp : public stickslip::testing_util::AppTest {
 protected:
  int Run(const std::string& args) { return RunApp(STICKSLIP_BIN_DIR, "ss_basin", args); }
  // The fraction printed for an attractor, nan if none.
  double Printed(const std::string& attractor) const {
    const std::string key = "basin stability " + attractor + " ";
    const auto at = out_.find(key);
    return at == std::string::npos ? std::nan("") : std::stod(out_.substr(at + key.size()));
  }
};

// --size and --font reach the curve's figure too (they were ignored: a
// 10 x 7.2 in page whatever was asked); a bad --size is exit 2 before any work.
TEST_F(BasinStabilityApp, CurveFigureTakesSizeAndFont) {
  ASSERT_EQ(Run("--study " + kStudies + "/stribeck_basin_stability.ini --from 0.56 --to 0.64 " +
                "--n 3 --format pdf --size single --font Sans,8 --no_plots --out " + dir_ + "/o"),
            0)
      << err_;
  const std::string gp = ReadFile(dir_ + "/o/basin_stability.gp");
  EXPECT_TRUE(Contains(gp, "set terminal pdfcairo size 3.5in,")) << gp.substr(0, 400);
  EXPECT_TRUE(Contains(gp, "font 'Sans,8' fontscale 0.75")) << gp.substr(0, 400);
  EXPECT_EQ(Run("--study " + kStudies + "/stribeck_basin_stability.ini --from 0.56 --to 0.64 " +
                "--n 3 --size triple --no_plots --out " + dir_ + "/bad"),
            2);
  EXPECT_TRUE(Contains(err_, "--size")) << err_;
  EXPECT_FALSE(Exists(dir_ + "/bad"));
}

TEST_F(BasinStabilityApp, PrintsOneLinePerAttractorAndWritesThemToOrbitsTsv) {
  ASSERT_EQ(Run("--study " + kStudies + "/stribeck_basin.ini --nx 5 --ny 5 --no_plots --out " +
                dir_ + "/o"),
            0)
      << err_;
  const double steady = Printed("steady-sliding"), stick = Printed("stick-slip");
  EXPECT_GT(steady, 0.05);
  EXPECT_NEAR(steady + stick, 1.0, 2e-12);
  const std::string orbits = ReadFile(dir_ + "/o/orbits.tsv");
  for (const char* a : {"steady-sliding", "stick-slip"}) {
    const std::string key = std::string("basin stability ") + a + " ";
    const std::string line =
        out_.substr(out_.find(key), out_.find('\n', out_.find(key)) - out_.find(key));
    EXPECT_TRUE(Contains(orbits, "# " + line + "\n")) << line;
  }
  const Tsv t = ReadTsv(orbits);
  ASSERT_GE(t.Column("basin_stability"), 0);
  for (const auto& row : t.rows) {
    const double share = std::stod(row[t.Column("basin_stability")]);
    if (row[t.Column("kind")] == "stick-slip")
      EXPECT_NEAR(share, stick, 1e-12);
    else
      EXPECT_EQ(share, 0.0);  // the unstable pure-slip orbit attracts nothing
  }
}

TEST_F(BasinStabilityApp, CurveAgreesWithSinglePointRunsInTheSameBox) {
  ASSERT_EQ(Run("--study " + kStudies +
                "/stribeck_basin_stability.ini --from 0.56 --to 0.64 --n 5 --no_plots --out " +
                dir_ + "/c"),
            0)
      << err_;
  const Tsv t = ReadTsv(ReadFile(dir_ + "/c/basin_stability.tsv"));
  ASSERT_EQ(t.rows.size(), 5u);
  EXPECT_EQ(t.meta.at("v"), "continued");
  for (const auto& row : t.rows) {
    double sum = 0;
    for (const char* c : {"steady_sliding", "stick_slip", "pure_slip", "undecided"})
      sum += std::stod(row[t.Column(c)]);
    EXPECT_NEAR(sum, 1.0, 2e-12);
  }
  for (size_t i : {0, 2, 4}) {
    const std::string v = t.rows[i][0];
    ASSERT_EQ(Run("--study " + kStudies + "/stribeck_basin.ini --v " + v + kBox +
                  " --nx 3 --ny 3 --no_plots --out " + dir_ + "/p"),
              0)
        << err_;
    EXPECT_NEAR(std::stod(t.rows[i][t.Column("steady_sliding")]), Printed("steady-sliding"), 1e-12)
        << v;
  }
}

TEST_F(BasinStabilityApp, BadCurveOptionsExitTwoWritingNothing) {
  const std::string base = "--study " + kStudies + "/stribeck_basin.ini --out " + dir_ + "/bad ";
  const std::pair<std::string, std::string> cases[] = {
      {"--param v", "--param needs a fixed box"},
      {"--param gamma" + kBox, "invalid value 'gamma' for --param"},
      {"--param v --n 1" + kBox, "invalid value '1' for --n"},
      {"--param v --from 0.6 --to 0.6" + kBox, "the range is empty"},
      {"--param v --from -1 --to 0.6" + kBox, "--from"},
  };
  for (const auto& [args, message] : cases) {
    EXPECT_EQ(Run(base + args), 2) << args;
    EXPECT_TRUE(Contains(err_, message)) << args << ": " << err_;
    EXPECT_EQ(std::count(err_.begin(), err_.end(), '\n'), 1) << err_;
    EXPECT_FALSE(Exists(dir_ + "/bad")) << args;
  }
}

}  // namespace
