// ss_continue's run log against the files the same run writes: the special
// points with the labels and point numbers of special_points.tsv (what
// --restart DIR --point takes), --verbose's line per branch.tsv row, and the
// SI values of a physical run beside the dimensionless ones.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "app_test_util.hpp"

namespace {

namespace tu = stickslip::testing_util;
class RunLogApp : public tu::AppTest {};

std::vector<std::string> Lines(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream is(text);
  for (std::string line; std::getline(is, line);) lines.push_back(line);
  return lines;
}

std::vector<std::string> Words(const std::string& line) {
  std::vector<std::string> w;
  std::istringstream is(line);
  for (std::string s; is >> s;) w.push_back(s);
  return w;
}

// The lines of the per-point table: after its header line, up to "special points".
std::vector<std::vector<std::string>> PointRows(const std::string& out) {
  std::vector<std::vector<std::string>> rows;
  bool in = false;
  for (const std::string& line : Lines(out)) {
    if (line.rfind("special points", 0) == 0) break;
    if (in) rows.push_back(Words(line));
    if (line.rfind("  pt ", 0) == 0) in = true;
  }
  return rows;
}

// The special-point line of label `lab` ("  GR1  pt 87  v = ..."), or "".
std::string SpecialLine(const std::string& out, const std::string& lab) {
  for (const std::string& line : Lines(out))
    if (line.rfind("  " + lab + "  pt ", 0) == 0) return line;
  return "";
}

// Every row of special_points.tsv is printed with its lab and pt, and that
// pt is the branch.tsv row at the point's parameter value.
void ExpectSpecialPointsPrinted(const std::string& out, const std::string& dir,
                                const std::string& param) {
  const tu::Tsv sp = tu::ReadTsv(tu::ReadFile(dir + "/special_points.tsv"));
  const tu::Tsv br = tu::ReadTsv(tu::ReadFile(dir + "/branch.tsv"));
  ASSERT_GE(sp.rows.size(), 2u);
  for (const auto& row : sp.rows) {
    const std::string lab = row[sp.Column("lab")], pt = row[sp.Column("pt")];
    const std::string line = SpecialLine(out, lab);
    ASSERT_FALSE(line.empty()) << lab << " not printed:\n" << out;
    const std::vector<std::string> w = Words(line);
    EXPECT_EQ(w[2], pt) << line;
    EXPECT_EQ(w[3], param) << line;
    const double p = std::stod(row[sp.Column(param)]);
    EXPECT_NEAR(std::stod(w[5]), p, 1e-12 * std::max(1.0, std::abs(p))) << line;
    const auto& at = br.rows.at(std::stoul(pt) - 1);
    EXPECT_EQ(at[br.Column("pt")], pt);
    EXPECT_NEAR(std::stod(at[br.Column(param)]), p, 1e-12) << lab;
  }
}

TEST_F(RunLogApp, SpecialPointsPrintTheirLabelAndPointNumber) {
  const std::string dir = NewDir();
  const auto r = RunOut(
      "ss_continue", dir,
      {"--study", std::string(STICKSLIP_SOURCE_DIR) + "/studies/seed.ini", "--no_estimates"});
  ASSERT_EQ(r.outcome.code, 0) << r.err;
  ExpectSpecialPointsPrinted(r.out, dir + "/out", "v");
  EXPECT_TRUE(PointRows(r.out).empty()) << "one line per point only with --verbose";
  // The printed pt restarts the run there: its first row is the GR1 row.
  const std::vector<std::string> w = Words(SpecialLine(r.out, "GR1"));
  ASSERT_GE(w.size(), 6u);
  const std::string again = NewDir();
  const auto s =
      RunOut("ss_continue", again, {"--restart", dir + "/out", "--point", w[2], "--to", "0.5"});
  ASSERT_EQ(s.outcome.code, 0) << s.err;
  const tu::Tsv b = tu::ReadTsv(tu::ReadFile(again + "/out/branch.tsv"));
  EXPECT_NEAR(std::stod(b.rows.at(0)[b.Column("v")]), std::stod(w[5]), 1e-12);
}

TEST_F(RunLogApp, VerbosePrintsEveryRowOfBranchTsv) {
  const std::string dir = NewDir();
  const auto r = RunOut("ss_continue", dir,
                        {"--study", std::string(STICKSLIP_SOURCE_DIR) + "/studies/seed.ini",
                         "--no_estimates", "--verbose"});
  ASSERT_EQ(r.outcome.code, 0) << r.err;
  const tu::Tsv br = tu::ReadTsv(tu::ReadFile(dir + "/out/branch.tsv"));
  const auto rows = PointRows(r.out);
  ASSERT_EQ(rows.size(), br.rows.size()) << r.out;
  int labelled = 0;
  for (size_t i = 0; i < rows.size(); ++i) {
    const auto& w = rows[i];
    const auto& b = br.rows[i];
    ASSERT_GE(w.size(), 8u);
    EXPECT_EQ(w[0], b[br.Column("pt")]);
    EXPECT_EQ(w[1], b[br.Column("kind")]);
    EXPECT_NEAR(std::stod(w[2]), std::stod(b[br.Column("v")]), 1e-10);
    EXPECT_NEAR(std::stod(w[4]), std::stod(b[br.Column("x_min")]), 1e-6);
    EXPECT_NEAR(std::stod(w[5]), std::stod(b[br.Column("x_max")]), 1e-6);
    EXPECT_EQ(w[7], b[br.Column("stable")] == "1" ? "stable" : "unstable") << i;
    if (w.size() > 8) ++labelled;
  }
  EXPECT_EQ(labelled, 2) << "GR1 and HB1 on their rows";
  ExpectSpecialPointsPrinted(r.out, dir + "/out", "v");
}

TEST_F(RunLogApp, PhysicalRunPrintsSiValuesBesideDimensionless) {
  const std::string dir = NewDir();
  const auto r = RunOut("ss_continue", dir,
                        {"--mass", "2", "--stiffness", "8", "--damping", "0.4", "--belt_speed", "1",
                         "--speed_m", "2.4525", "--no_estimates"});
  ASSERT_EQ(r.outcome.code, 0) << r.err;
  const tu::Tsv sp = tu::ReadTsv(tu::ReadFile(dir + "/out/special_points.tsv"));
  for (const auto& row : sp.rows) {
    const std::string line = SpecialLine(r.out, row[sp.Column("lab")]);
    ASSERT_FALSE(line.empty()) << r.out;
    const auto at = line.find("(belt_speed ");
    ASSERT_NE(at, std::string::npos) << line;
    const double si = std::stod(line.substr(at + 12));
    const double ref = std::stod(row[sp.Column("belt_speed")]);
    EXPECT_NEAR(si, ref, 1e-9 * ref) << line;
    const auto s = line.find(" s)");
    ASSERT_NE(s, std::string::npos) << line;
    const double period = std::stod(line.substr(line.rfind('(', s) + 1));
    EXPECT_NEAR(period, std::stod(row[sp.Column("period_s")]), 1e-9 * period) << line;
    EXPECT_TRUE(tu::Contains(line, "] m)")) << line;
  }
}

TEST_F(RunLogApp, ForcedRunPrintsLabelsPointNumbersAndEveryRow) {
  const std::string dir = NewDir();
  const auto r =
      RunOut("ss_continue", dir,
             {"--study", std::string(STICKSLIP_SOURCE_DIR) + "/studies/stribeck_forced.ini",
              "--from", "0.7", "--to", "0.6", "--verbose"});
  ASSERT_EQ(r.outcome.code, 0) << r.err;
  ExpectSpecialPointsPrinted(r.out, dir + "/out", "omega");
  const tu::Tsv br = tu::ReadTsv(tu::ReadFile(dir + "/out/branch.tsv"));
  const auto rows = PointRows(r.out);
  ASSERT_EQ(rows.size(), br.rows.size());
  for (size_t i = 0; i < rows.size(); ++i) {
    EXPECT_EQ(rows[i][0], br.rows[i][br.Column("pt")]);
    EXPECT_NEAR(std::stod(rows[i][3]), std::stod(br.rows[i][br.Column("omega")]), 1e-10);
    EXPECT_NEAR(std::stod(rows[i][8]), std::stod(br.rows[i][br.Column("mult_max")]), 1e-6);
  }
}

}  // namespace
