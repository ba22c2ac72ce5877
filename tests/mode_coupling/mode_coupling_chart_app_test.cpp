// ss_chart --study brake_chart (studies/brake_chart.ini; docs/systems.md,
// "Charts"): the mode-coupling model's chart through the app. The HB rows of
// curves.tsv against the closed flutter threshold mu_k*(beta)
// (mode_coupling.hpp), the LP rows' largest multiplier against 1, the cusp
// in codim2.tsv; bad inputs refused with one line naming the option and
// nothing written.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "app_test_util.hpp"
#include "mode_coupling/mode_coupling.hpp"

namespace {

namespace tu = stickslip::testing_util;
class ModeCouplingChartApp : public tu::AppTest {};

const std::string kChartStudy = STICKSLIP_SOURCE_DIR "/studies/brake_chart.ini";

// The study's response grid (grid = 32) against the closed-form flutter
// threshold and the traced LP curve, off the cells next to either: left of
// mu_k*(beta) steady sliding is stable and the start comes to rest; right of
// the LP curve below the cusp (beta < 0.022) there is no stick-slip orbit and
// steady sliding is unstable, so the contact opens.
void CheckResponse(const tu::Tsv& g, const tu::Tsv& curves,
                   stickslip::mode_coupling::CouplingParams p) {
  EXPECT_EQ(g.meta.at("status"), "complete");
  ASSERT_EQ(g.rows.size(), 32u * 32u);
  std::vector<std::pair<double, double>> lp;  // (beta, mu_k) below the cusp
  for (const auto& row : curves.rows)
    if (row[2] == "LP" && std::stod(row[1]) < 0.0235)
      lp.emplace_back(std::stod(row[1]), std::stod(row[0]));
  std::sort(lp.begin(), lp.end());
  ASSERT_GT(lp.size(), 10u);
  const double w = 0.15 / 32;  // a cell's width in mu_k
  int rest = 0, lost = 0;
  for (const auto& row : g.rows) {
    const double mu = std::stod(row[0]), beta = std::stod(row[1]);
    p.beta = beta;
    if (mu < stickslip::mode_coupling::FlutterMuK(p) - w) {
      EXPECT_EQ(row[3], "rest") << "mu_k " << mu << ", beta " << beta;
      ++rest;
    }
    if (beta > 0.022 || beta < lp.front().first) continue;
    const auto hi = std::lower_bound(lp.begin(), lp.end(), std::make_pair(beta, 0.0));
    const auto lo = hi - 1;
    const double mu_lp =
        lo->second + (hi->second - lo->second) * (beta - lo->first) / (hi->first - lo->first);
    if (mu > mu_lp + w) {
      EXPECT_EQ(row[3], "contact-lost") << "mu_k " << mu << ", beta " << beta;
      ++lost;
    }
  }
  EXPECT_GT(rest, 300);
  EXPECT_GT(lost, 200);
}

TEST_F(ModeCouplingChartApp, StudyCurvesAgreeWithTheClosedFormAndTheirTests) {
  const auto r = RunOut("ss_chart", dir_, {"--study", kChartStudy});
  ASSERT_EQ(r.outcome.code, 0) << r.err;
  const tu::Tsv curves = tu::ReadTsv(tu::ReadFile(dir_ + "/out/curves.tsv"));
  const tu::Tsv codim2 = tu::ReadTsv(tu::ReadFile(dir_ + "/out/codim2.tsv"));
  EXPECT_EQ(curves.meta.at("status"), "complete");
  for (const char* c :
       {"mu_k", "beta", "curve", "x_min", "ydot_max", "mult3_im", "mult_max", "test"})
    EXPECT_GE(curves.Column(c), 0) << c;
  EXPECT_LT(curves.Column("mult4_re"), 0) << "the surface section's DP has three multipliers";
  stickslip::mode_coupling::CouplingParams p;
  p.law.law = stickslip::LawKind::kCoulomb;
  p.law.mu_s = 0.8;
  int hb = 0, lp = 0;
  for (const auto& row : curves.rows) {
    const double mu = std::stod(row[0]), beta = std::stod(row[1]);
    if (row[2] == "HB") {
      p.beta = beta;
      EXPECT_NEAR(mu, stickslip::mode_coupling::FlutterMuK(p), 1e-12) << "beta " << beta;
      ++hb;
    } else if (row[2] == "LP") {
      EXPECT_NEAR(std::stod(row[curves.Column("mult_max")]), 1, 1e-7) << "beta " << beta;
      EXPECT_LE(std::stod(row[curves.Column("y_max")]), 1);  // the contact stays closed
      ++lp;
    }
  }
  EXPECT_GT(hb, 20);
  EXPECT_GT(lp, 20);
  ASSERT_EQ(codim2.rows.size(), 1u);
  EXPECT_EQ(codim2.rows[0][0], "CP");
  EXPECT_TRUE(tu::Contains(r.out, "contact-lost"));
  CheckResponse(tu::ReadTsv(tu::ReadFile(dir_ + "/out/response.tsv")), curves, p);
}

TEST_F(ModeCouplingChartApp, BadInputsAreRefusedAndWriteNothing) {
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {{"--param2", "mu_k"}, "the two axes must differ"},
      {{"--param", "zeta"}, "'zeta' is no parameter of mode_coupling"},
      {{"--to", "0.9"}, "mu_k = 0.9"},
      {{"--from2", "0.05"}, "must exceed --from2 = 0.05"},  // the to2 of the study
      {{"--max_m", "9"}, "--max_m"},
      {{"--max_m", "0"}, "--max_m"},
      {{"--seed_lines", "21"}, "--seed_lines"},
      {{"--max_step", "0.9"}, "max_step"},
  };
  for (const auto& [extra, message] : cases) {
    const std::string d = NewDir();
    std::vector<std::string> args = {"--study", kChartStudy};
    args.insert(args.end(), extra.begin(), extra.end());
    const auto r = RunOut("ss_chart", d, args);
    EXPECT_EQ(r.outcome.code, 2) << extra[0] << ": " << r.err;
    EXPECT_TRUE(tu::Contains(r.err, message)) << r.err;
    EXPECT_FALSE(tu::Exists(d + "/out/curves.tsv")) << extra[0];
  }
  const auto r = RunOut("ss_chart", NewDir(), {"--system", "chain", "--param", "v"});
  EXPECT_EQ(r.outcome.code, 2);
  EXPECT_TRUE(tu::Contains(r.err, "--param2 is required with --system")) << r.err;
}

}  // namespace
