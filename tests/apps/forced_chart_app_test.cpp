// ss_chart --force end to end (issue 21 item 3): the Den Hartog floor's chart
// in (omega, force) writes its four files with a complete status and the GR
// curve on his stop condition; --max_time cuts it short with status `cut
// short`; bad input is exit 2 with one line naming the option, nothing written.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "app_test_util.hpp"

namespace stickslip {
namespace {

using testing_util::AppTest;
using testing_util::Contains;
using testing_util::Exists;
using testing_util::ReadFile;
using testing_util::ReadTsv;

class ForcedChartAppTest : public AppTest {
 protected:
  int Chart(const std::string& args, const std::string& signal = "KILL", int seconds = 300) {
    return RunApp(STICKSLIP_BIN_DIR, "ss_chart", args + " --out " + dir_ + "/c", signal, seconds);
  }
};

const char* const kFloor =
    "--law coulomb --mu_s 0.3 --mu_k 0.3 --beta 0 --v 0 --force 0.5 --param omega --from 0.6 "
    "--to 0.9 --param2 force --from2 0.05 --to2 1.5 --seed_lines 1 --no_plots";

// Den Hartog (1931), the stop condition of forced_chart_test.cpp.
double DenHartogStopForce(double mu, double w) {
  const double U = std::sin(M_PI / w) / (w * (1 + std::cos(M_PI / w)));
  return mu * std::abs(1 - w * w) * std::sqrt(U * U + 1 / (w * w * w * w));
}

TEST_F(ForcedChartAppTest, DenHartogChartHasHisStopCurve) {
  ASSERT_EQ(Chart(std::string(kFloor) + " --grid 4"), 0) << err_;
  for (const char* f : {"curves.tsv", "codim2.tsv", "response.tsv"}) {
    const std::string text = ReadFile(dir_ + "/c/" + f);
    EXPECT_TRUE(Contains(text, "# status: complete")) << f;
    EXPECT_EQ(stickslip::testing_util::DataLines(text).find("nan"), std::string::npos) << f;
  }
  const auto t = ReadTsv(ReadFile(dir_ + "/c/curves.tsv"));
  int gr = 0;
  for (const auto& row : t.rows) {
    if (row[t.Column("curve")] != "GR") continue;
    const double w = std::stod(row[t.Column("omega")]), a = std::stod(row[t.Column("force")]);
    EXPECT_NEAR(a, DenHartogStopForce(0.3, w), 1e-8) << "omega = " << w;
    // The multipliers, the larger first, and mult_max the larger's modulus.
    auto at = [&](const char* c) { return std::stod(row[t.Column(c)]); };
    const double m1 = std::hypot(at("mult1_re"), at("mult1_im"));
    EXPECT_GE(m1, std::hypot(at("mult2_re"), at("mult2_im"))) << "omega = " << w;
    EXPECT_NEAR(at("mult_max"), m1, 1e-15 * (1 + m1)) << "omega = " << w;
    ++gr;
  }
  EXPECT_GT(gr, 10) << out_;
  const auto g = ReadTsv(ReadFile(dir_ + "/c/response.tsv"));
  EXPECT_EQ(g.rows.size(), 16u);
}

TEST_F(ForcedChartAppTest, TimeLimitCutsItShort) {
  const std::string args = std::string(kFloor) + " --grid 200 --max_time 1";
  EXPECT_EQ(Chart(args), 1) << err_;
  EXPECT_TRUE(Contains(err_, "cut short")) << err_;
  EXPECT_TRUE(Contains(ReadFile(dir_ + "/c/curves.tsv"), "# status: cut short")) << out_;
  if (Exists(dir_ + "/c/response.tsv")) {  // the curves may take the whole second
    EXPECT_TRUE(Contains(ReadFile(dir_ + "/c/response.tsv"), "# status: cut short")) << out_;
  }
}

TEST_F(ForcedChartAppTest, BadInputExits2NamingTheOption) {
  const std::string base = "--force 0.3 --param omega ";
  const std::pair<std::string, std::string> cases[] = {
      {base + "--param2 omega", "--param2"},
      {base + "--param2 mu_k", "mu_k"},  // the cubic law has none
      {base + "--param2 force --from 2 --to 1", "--to"},
      {base + "--param2 force --grid 1", "--grid"},
      {base + "--param2 force --from2 -1", "force"},
      {base + "--param2 force --max_m 9", "--max_m"},
      {base + "--param2 force --max_m 0", "--max_m"},
      {base + "--param2 force --restart plots --point 2", "--restart"},  // was ignored
      {base + "--param2 force --point 2", "--point"},
      {"--force -0.3", "--force"},  // an axis: its value is not used, but checked
      {"--force 0.3 --omega 0", "--omega"},
      {"--force 0.3 --param v --param2 beta --omega -1", "--omega"},  // not "rectangle"
      {base + "--param2 force --from -0.5", "--from"},                // the end at fault
      {base + "--param2 force --max_amplitude 0", "--max_amplitude = 0"},
      {base + "--param2 force --seed_lines 0 --grid 0", "--seed_lines"},  // nothing to do
      {base + "--param2 force --integrator cvode", "--integrator"},       // Taylor only
      {"--param v --param2 beta --seed_lines 2", "--seed_lines"},  // a belt chart: forced only
      {"--param v --param2 beta --max_m 4", "--max_m"},
  };
  for (const auto& [args, word] : cases) {
    EXPECT_EQ(Chart(args), 2) << args;
    EXPECT_TRUE(Contains(err_, word)) << args;
    EXPECT_EQ(std::count(err_.begin(), err_.end(), '\n'), 1) << err_;
    EXPECT_FALSE(Exists(dir_ + "/c")) << args;
  }
}

}  // namespace
}  // namespace stickslip
