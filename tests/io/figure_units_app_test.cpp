// SI units in the figures of a physical run (issue 22 item 4): every drawing
// app's script labels its axes with symbols and units and scales the
// dimensionless columns by the seed's scales (section 3), L = M g / K and
// t0 = sqrt(M / K), here computed from M = 2 kg, K = 8 N/m, g = 9.81 m/s^2:
// L = 2.4525 m, t0 = 0.5 s, speeds L / t0 = 4.905 m/s, damping
// C = 2 beta M / t0 = 8 beta N s/m. A dimensionless run says so on its axes.
#include <gtest/gtest.h>

#include <cmath>
#include <regex>
#include <string>

#include "app_test_util.hpp"
#include "stickslip/io/figure_style.hpp"
#include "stickslip/systems/belt/parameter_axis.hpp"
#include "test_paths.hpp"

namespace stickslip {
namespace {

using testing_util::Contains;

const double kL = 2 * 9.81 / 8, kT0 = std::sqrt(2.0 / 8), kSpeed = kL / kT0;
const std::string kPhysical =
    " --mass 2 --stiffness 8 --damping 0.4 --belt_speed 1 --speed_m 2.4525 --mu_s 0.4 "
    "--mu_m 0.25";

// The value of gnuplot variable `name` as the script sets it ("ul = 2.4525").
double Variable(const std::string& script, const std::string& name) {
  std::smatch m;
  if (!std::regex_search(script, m, std::regex("\\n" + name + " = ([-0-9.e+]+)\\n")))
    return std::nan("");
  return std::stod(m[1]);
}

class FigureUnitsTest : public testing_util::AppTest {
 protected:
  std::string Script(const std::string& app, const std::string& args, const std::string& gp) {
    const std::string out = dir_ + "/" + app;
    EXPECT_EQ(RunApp(kBin, app, args + " --out " + out), 0) << err_;
    return testing_util::ReadFile(out + "/" + gp);
  }
};

TEST(FigureUnits, DimensionlessAxesSaySo) {
  const FigureUnits u;
  EXPECT_EQ(u.P1Label(Parameter::kV), "belt speed v (dimensionless)");
  EXPECT_EQ(u.P1Label(Parameter::kBeta), "damping ratio β (dimensionless)");
  EXPECT_EQ(u.P1Label(Parameter::kMuS), "static friction coefficient μ_s");  // a coefficient
  EXPECT_EQ(u.LengthUnit(), " (dimensionless)");
  const std::string vars = FigureUnitVariables(u);
  for (const char* name : {"ul", "ut", "uv", "up", "up2"})
    EXPECT_EQ(Variable("\n" + vars, name), 1);
}

TEST_F(FigureUnitsTest, ContinuationFiguresInSiUnits) {
  const std::string gp =
      Script("ss_continue", kPhysical + " --param belt_speed --from 1.5 --to 2.4525 --no_estimates",
             "bifurcation.gp");
  EXPECT_NEAR(Variable(gp, "ul"), kL, 1e-12);
  EXPECT_NEAR(Variable(gp, "ut"), kT0, 1e-12);
  EXPECT_NEAR(Variable(gp, "uv"), kSpeed, 1e-12);
  EXPECT_NEAR(Variable(gp, "up"), kSpeed, 1e-12);  // v to belt speed V
  for (const char* label : {"belt speed V [m/s]", "displacement x: min and max [m]",
                            "velocity dx/dt: min and max [m/s]", "period T [s]"})
    EXPECT_TRUE(Contains(gp, label)) << label;
  EXPECT_FALSE(Contains(gp, "(dimensionless)"));
  // Every curve's parameter and value are scaled: ($1*up) and $5*ul (x_min).
  EXPECT_TRUE(Contains(gp, "using ($1*up):"));
  EXPECT_TRUE(Contains(gp, "? $5*ul : NaN"));
}

TEST_F(FigureUnitsTest, ChartAndBasinFiguresInSiUnits) {
  const std::string chart =
      Script("ss_chart", kPhysical + " --from 0.3 --to 0.5 --from2 0.02 --to2 0.1 --max_step 0.05",
             "chart.gp");
  EXPECT_TRUE(Contains(chart, "belt speed V [m/s]"));
  EXPECT_TRUE(Contains(chart, "damping C [N s/m]"));
  EXPECT_NEAR(Variable(chart, "up"), kSpeed, 1e-12);
  EXPECT_NEAR(Variable(chart, "up2"), 2 * 2 / kT0, 1e-12);  // C = 2 beta M / t0
  std::smatch m;
  ASSERT_TRUE(std::regex_search(chart, m, std::regex("set xrange \\[([-0-9.e]+):([-0-9.e]+)\\]")));
  EXPECT_NEAR(std::stod(m[1]), 0.3 * kSpeed, 1e-12);
  EXPECT_NEAR(std::stod(m[2]), 0.5 * kSpeed, 1e-12);

  const std::string basins = Script("ss_basin", kPhysical + " --nx 3 --ny 3", "basins.gp");
  EXPECT_TRUE(Contains(basins, "initial displacement x [m]"));
  EXPECT_TRUE(Contains(basins, "initial velocity dx/dt [m/s]"));
  EXPECT_TRUE(Contains(basins, "using ($1*ul):($2*uv)"));
  EXPECT_NEAR(Variable(basins, "ul"), kL, 1e-12);

  const std::string curve =
      Script("ss_basin",
             kPhysical +
                 " --param v --from 0.3 --to 0.4 --n 2 --x_min -0.4 --x_max 1.0 "
                 "--xdot_min -0.8 --xdot_max 0.7",
             "basin_stability.gp");
  EXPECT_TRUE(Contains(curve, "belt speed V [m/s]"));
  EXPECT_NEAR(Variable(curve, "up"), kSpeed, 1e-12);
}

}  // namespace
}  // namespace stickslip
