// End-to-end tests of labelled points and restarts (AUTO-07p's PT, LAB, IRS):
// the seed run numbers its rows and labels GR1 and HB1; a restart from HB1 in
// beta finds the Hopf point of the closed form 2 beta + mu'(v) = 0; a restart
// from GR1 finds the grazing point a fresh run at those parameters finds;
// ss_chart starts its curves at such points; bad restarts exit 2 with one line.
#include <gtest/gtest.h>
#include <stdlib.h>
#include <sys/wait.h>

#include <cmath>
#include <cstdlib>
#include <string>

#include "app_test_util.hpp"
#include "test_paths.hpp"

namespace {

using stickslip::testing_util::Contains;
using stickslip::testing_util::Exists;
using stickslip::testing_util::ReadFile;
using stickslip::testing_util::ReadTsv;
using stickslip::testing_util::Tsv;

class Restart : public stickslip::testing_util::AppTest {
 protected:
  void SetUp() override {
    AppTest::SetUp();
    ASSERT_EQ(Run("ss_continue", "--out " + Seed() + " --no_plots --no_estimates"), 0) << err_;
  }
  int Run(const std::string& app, const std::string& args) { return RunApp(kBin, app, args); }
  std::string Seed() const { return dir_ + "/seed"; }
  Tsv Table(const std::string& path) const { return ReadTsv(ReadFile(path)); }
  // The cell of column `col` in the row whose `key` column is `value`.
  static std::string Cell(const Tsv& t, const std::string& key, const std::string& value,
                          const std::string& col) {
    for (const auto& row : t.rows)
      if (row[t.Column(key)] == value) return row[t.Column(col)];
    return "";
  }
};

TEST_F(Restart, RowsAreNumberedAndSpecialPointsLabelledOnTheirRows) {
  const Tsv b = Table(Seed() + "/branch.tsv"), s = Table(Seed() + "/special_points.tsv");
  ASSERT_GE(b.Column("pt"), 0);
  for (size_t i = 0; i < b.rows.size(); ++i)
    ASSERT_EQ(b.rows[i][b.Column("pt")], std::to_string(i + 1));
  ASSERT_EQ(s.rows.size(), 2u);
  EXPECT_EQ(Cell(s, "label", "GR", "lab"), "GR1");
  EXPECT_EQ(Cell(s, "label", "HB", "lab"), "HB1");
  // Each sits on a row of its kind at its parameter (the grazing row and the
  // Hopf row of the steady-sliding branch are the located points themselves).
  for (const char* lab : {"GR1", "HB1"}) {
    const int pt = std::stoi(Cell(s, "lab", lab, "pt"));
    const auto& row = b.rows[pt - 1];
    EXPECT_EQ(row[b.Column("kind")], std::string(lab) == "HB1" ? "equilibrium" : "stick-slip");
    EXPECT_EQ(row[b.Column("v")], Cell(s, "lab", lab, "v")) << lab;
    EXPECT_EQ(row[b.Column("x_start")], Cell(s, "lab", lab, "x_start")) << lab;
  }
  // GR's state is the exit point (x0, v) = (mu_s - 2 beta v, v).
  const double v = std::stod(Cell(s, "lab", "GR1", "v"));
  EXPECT_NEAR(std::stod(Cell(s, "lab", "GR1", "x_start")), 0.4 - 2 * 0.05 * v, 1e-15);
}

// Closed form of the Hopf point in beta (design.md section 1, seed 3.16):
// 2 beta + mu'(v) = 0, mu'(v) = -k1 + 3 k3 v^2, k1 = 0.45, k3 = 0.6.
double HopfBeta(double v) { return (0.45 - 3 * 0.6 * v * v) / 2; }

TEST_F(Restart, FromHopfPointInBetaFindsTheClosedFormHopfPoint) {
  const std::string v_text = Cell(Table(Seed() + "/special_points.tsv"), "lab", "HB1", "v");
  const double v = std::stod(v_text);
  for (const std::string range : {"", "--from 0.01 --to 0.3"}) {
    const std::string out = dir_ + "/hb" + std::to_string(range.size());
    ASSERT_EQ(Run("ss_continue", "--restart " + Seed() + " --point HB1 --param beta --no_plots " +
                                     range + " --out " + out),
              0)
        << err_;
    const Tsv s = Table(out + "/special_points.tsv");
    EXPECT_EQ(s.meta.at("v"), v_text);  // every digit of the point's v
    EXPECT_EQ(s.meta.at("continued"), "beta");
    EXPECT_TRUE(Contains(s.meta.at("restart"), "point HB1"));
    const std::string beta = Cell(s, "lab", "HB1", "beta");
    ASSERT_FALSE(beta.empty()) << range;
    EXPECT_NEAR(std::stod(beta), HopfBeta(v), 1e-10) << range;
  }
}

// HB1's row of branch.tsv is steady sliding: its period and t_stick are empty
// cells (never nan), and a restart from its number reads it.
TEST_F(Restart, FromASteadySlidingRowWithEmptyCells) {
  const Tsv b = Table(Seed() + "/branch.tsv");
  const std::string pt = Cell(Table(Seed() + "/special_points.tsv"), "lab", "HB1", "pt");
  ASSERT_FALSE(pt.empty());
  const auto& row = b.rows.at(std::stoi(pt) - 1);
  EXPECT_EQ(row[b.Column("period")], "");
  EXPECT_EQ(row[b.Column("t_stick")], "");
  const std::string out = dir_ + "/row";
  ASSERT_EQ(Run("ss_continue", "--restart " + Seed() + " --point " + pt +
                                   " --param beta --from 0.01 --to 0.3 --no_plots --out " + out),
            0)
      << err_;
  const std::string beta = Cell(Table(out + "/special_points.tsv"), "lab", "HB1", "beta");
  ASSERT_FALSE(beta.empty());
  EXPECT_NEAR(std::stod(beta), HopfBeta(std::stod(row[b.Column("v")])), 1e-10);
}

TEST_F(Restart, FromGrazingPointMatchesAFreshRunAtItsParameters) {
  const std::string v_text = Cell(Table(Seed() + "/special_points.tsv"), "lab", "GR1", "v");
  const std::string range = " --param beta --from 0.02 --to 0.1 --no_plots --no_estimates";
  ASSERT_EQ(
      Run("ss_continue", "--restart " + Seed() + " --point GR1" + range + " --out " + dir_ + "/gr"),
      0)
      << err_;
  ASSERT_EQ(Run("ss_continue", "--v " + v_text + range + " --out " + dir_ + "/fresh"), 0) << err_;
  const std::string restarted = Cell(Table(dir_ + "/gr/special_points.tsv"), "label", "GR", "beta");
  const std::string fresh = Cell(Table(dir_ + "/fresh/special_points.tsv"), "label", "GR", "beta");
  ASSERT_FALSE(restarted.empty());
  EXPECT_EQ(restarted, fresh);
  // The seed run found this grazing point at beta = 0.05.
  EXPECT_NEAR(std::stod(restarted), 0.05, 1e-8);
}

TEST_F(Restart, ChartStartsItsCurveAtTheRestartPoint) {
  const Tsv s = Table(Seed() + "/special_points.tsv");
  for (const char* lab : {"GR1", "HB1"}) {
    const std::string out = dir_ + "/chart" + lab;
    ASSERT_EQ(Run("ss_chart", "--restart " + Seed() + " --point " + lab +
                                  " --param2 beta --no_plots --out " + out),
              0)
        << err_;
    const Tsv c = Table(out + "/curves.tsv");
    const double v = std::stod(Cell(s, "lab", lab, "v"));
    double nearest = 1;
    for (const auto& row : c.rows)
      if (row[c.Column("curve")] == std::string(lab).substr(0, 2) &&
          std::stod(row[c.Column("beta")]) == 0.05)
        nearest = std::min(nearest, std::abs(std::stod(row[c.Column("v")]) - v));
    EXPECT_LT(nearest, 1e-9) << lab;
  }
  EXPECT_EQ(Run("ss_chart", "--restart " + Seed() + " --point 3 --no_plots --out " + dir_ + "/c3"),
            2);
  EXPECT_TRUE(Contains(err_, "--point 3 is a stick-slip point")) << err_;
}

TEST_F(Restart, BadRestartsExitTwoWithOneLineNamingTheOption) {
  stickslip::testing_util::WriteFile(dir_ + "/corrupt_branch", "");
  ASSERT_EQ(std::system(("cp -r '" + Seed() + "' '" + dir_ + "/corrupt' && sed -i '/^# rtol/d' '" +
                         dir_ + "/corrupt/special_points.tsv' && mkdir '" + dir_ + "/empty'")
                            .c_str()),
            0);
  const std::pair<std::string, std::string> cases[] = {
      {"--restart " + dir_ + "/none --point HB1", "--restart " + dir_ + "/none: cannot read"},
      {"--restart " + dir_ + "/empty --point GR1", "--restart " + dir_ + "/empty: cannot read"},
      {"--restart " + Seed() + " --point HB2", "--point HB2: no point HB2"},
      {"--restart " + Seed() + " --point XY1", "--point XY1: 'XY1' is neither a label"},
      {"--restart " + Seed() + " --point 9999", "--point 9999: no point 9999"},
      {"--restart " + dir_ + "/corrupt --point HB1", "has no '# rtol:' line"},
      {"--point HB1", "--point HB1 needs --restart DIR"},
      {"--restart " + Seed(), "needs --point LABEL"},
  };
  for (const auto& [args, message] : cases) {
    EXPECT_EQ(Run("ss_continue", args + " --out " + dir_ + "/bad"), 2) << args;
    EXPECT_TRUE(Contains(err_, message)) << args;
    EXPECT_EQ(std::count(err_.begin(), err_.end(), '\n'), 1) << err_;
    EXPECT_FALSE(Exists(dir_ + "/bad")) << args;
  }
}

}  // namespace

namespace {

// Issue 35: a restart file gets a study file's checks. A FIFO must not block
// (--max_time cannot stop an open()), /dev/zero must not be read into memory,
// a junk file over 64 MiB is refused unread; period = nan or empty and '# from:
// nan' are corrupt. Every case exits 2 within seconds, naming --restart, in both apps.
TEST_F(Restart, RestartFilesMustBeRegularFilesOfBoundedSizeAndFiniteValues) {
  const std::string s = Seed();
  auto copy = [&](const std::string& name) {
    EXPECT_EQ(std::system(("cp -r '" + s + "' '" + dir_ + "/" + name + "'").c_str()), 0);
    return dir_ + "/" + name;
  };
  const std::string fifo = copy("fifo"), zero = copy("zero"), big = copy("big");
  const std::string nan_period = copy("nan_period"), nan_from = copy("nan_from");
  const std::string no_period = copy("no_period");
  const std::string sp = "/special_points.tsv";
  ASSERT_EQ(
      std::system(("rm " + fifo + sp + " && mkfifo " + fifo + sp + " && rm " + zero + sp +
                   " && ln -s /dev/zero " + zero + sp + " && truncate -s 65M " + big + sp +
                   " && sed -i 's/^HB\\t\\([^\\t]*\\)\\t[^\\t]*/HB\\t\\1\\tnan/' " + nan_period +
                   sp + " && sed -i 's/^HB\\t\\([^\\t]*\\)\\t[^\\t]*/HB\\t\\1\\t/' " + no_period +
                   sp + " && sed -i 's/^# from: .*/# from: nan/' " + nan_from + sp)
                      .c_str()),
      0);
  const std::pair<std::string, std::string> cases[] = {
      {fifo, "not a regular file"},
      {zero, "not a regular file"},
      {big, "68157440 bytes, more than 67108864 bytes (64 MiB)"},
      {nan_period, "the point HB1 has period = nan"},
      {no_period, "the point HB1 has period = (empty)"},
      {nan_from, "'# from: nan' and '# to: 0.5' must be finite"},
  };
  for (const char* app : {"ss_continue", "ss_chart"})
    for (const auto& [dir, message] : cases) {
      const std::string args = "--restart " + dir + " --point HB1 --max_time 5 --no_plots";
      EXPECT_EQ(RunApp(kBin, app, args + " --out " + dir_ + "/bad", "KILL", 20), 2)
          << app << " " << args;
      EXPECT_TRUE(Contains(err_, "--restart " + dir + ": cannot read") ||
                  Contains(err_, "--restart " + dir + ": '"))
          << err_;
      EXPECT_TRUE(Contains(err_, message)) << app << " " << err_;
      EXPECT_FALSE(Exists(dir_ + "/bad")) << app << " " << args;
    }
}

}  // namespace

namespace {

// Issue 35: `ss_chart --restart <forced run> --point PD1` said "--param: param =
// 'omega' is no parameter" though no --param was given. A forced run's point
// is refused as such, naming --restart (the Den Hartog run of the Python test).
TEST_F(Restart, ChartRefusesAForcedRunNamingTheRestart) {
  const std::string forced = dir_ + "/forced";
  ASSERT_EQ(Run("ss_continue",
                "--no_plots --law coulomb --mu_s 0.3 --mu_k 0.3 --v 0 --beta 0 --force 1 "
                "--param omega --from 1.5 --to 2.5 --out " +
                    forced),
            0)
      << err_;
  EXPECT_EQ(Run("ss_chart", "--restart " + forced + " --point 1 --no_plots --out " + dir_ + "/c"),
            2);
  EXPECT_TRUE(Contains(err_, "--restart " + forced + " is a forced run (point 1")) << err_;
  EXPECT_FALSE(Contains(err_, "--param")) << err_;
  EXPECT_FALSE(Exists(dir_ + "/c"));
}

}  // namespace
