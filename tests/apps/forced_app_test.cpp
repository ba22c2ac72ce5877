// End-to-end tests of ss_continue --force (issue 20, "Done when"): the Den
// Hartog run matches his closed form on every non-stop row of branch.tsv, and
// bad forced input is exit 2 with one line naming the option, nothing written;
// a restart from a forced run's point starts a forced branch there (issue 22).
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
class ForcedApp : public tu::AppTest {};

TEST_F(ForcedApp, DenHartogRunMatchesClosedFormOnEveryNonStopRow) {
  const std::string dir = NewDir();
  const AppRun r =
      RunOut("ss_continue", dir,
             {"--law", "coulomb", "--mu_s", "0.3", "--mu_k", "0.3", "--v", "0", "--beta", "0",
              "--force", "1", "--param", "omega", "--from", "0.75", "--to", "2.5"});
  ASSERT_EQ(r.outcome.code, 0) << r.err;
  const tu::Tsv t = tu::ReadTsv(tu::ReadFile(dir + "/out/branch.tsv"));
  auto col = [&](const std::string& name) {
    const auto it = std::find(t.columns.begin(), t.columns.end(), name);
    EXPECT_NE(it, t.columns.end()) << name;
    return static_cast<size_t>(it - t.columns.begin());
  };
  const size_t omega = col("omega"), x_max = col("x_max"), kind = col("kind"), m = col("m"),
               sticks = col("sticks");
  EXPECT_TRUE(tu::Contains(t.meta.at("gap"), "unbounded")) << "beta = 0: Omega = 1 is not traced";
  EXPECT_EQ(t.meta.at("continued"), "omega");
  EXPECT_EQ(t.meta.at("from"), "0.75");
  EXPECT_EQ(t.meta.at("to"), "2.5");
  int compared = 0;
  double worst = 0, w_min = 10, w_max = 0;
  for (const auto& row : t.rows) {
    ASSERT_EQ(row.size(), t.columns.size());
    EXPECT_EQ(row[m], "1");
    if (row[kind] != "pure-slip") continue;
    EXPECT_EQ(row[sticks], "0");
    const double w = std::stod(row[omega]), x = std::stod(row[x_max]);
    const double X = DenHartogX(0.3, 1, w);
    EXPECT_NEAR(x, X, 1e-9 * std::max(1.0, X)) << "omega = " << w;
    worst = std::max(worst, std::abs(x - X) / std::max(1.0, X));
    w_min = std::min(w_min, w), w_max = std::max(w_max, w);
    ++compared;
  }
  EXPECT_GT(compared, 100);
  EXPECT_EQ(w_min, 0.75);
  EXPECT_EQ(w_max, 2.5);
  std::printf("[ measured ] %d non-stop rows of %zu: max |x_max - X| / max(1, X) = %.2e\n",
              compared, t.rows.size(), worst);
}

// The one lens: a forced run continues any parameter of its law, here the
// Den Hartog run in mu_k at Omega = 2 (mu_s = 0.3 held), against his closed form.
TEST_F(ForcedApp, ContinuesAParameterOfTheLaw) {
  const std::string dir = NewDir();
  const AppRun r = RunOut("ss_continue", dir,
                          {"--law",   "coulomb", "--mu_s", "0.3",     "--mu_k", "0.3",     "--v",
                           "0",       "--beta",  "0",      "--force", "1",      "--omega", "2",
                           "--param", "mu_k",    "--from", "0.3",     "--to",   "0.05"});
  ASSERT_EQ(r.outcome.code, 0) << r.err;
  const tu::Tsv t = tu::ReadTsv(tu::ReadFile(dir + "/out/branch.tsv"));
  EXPECT_EQ(t.meta.at("continued"), "mu_k");
  EXPECT_TRUE(tu::Contains(t.meta.at("system"), " mu_k=[continued] ")) << t.meta.at("system");
  EXPECT_EQ(t.meta.at("from"), "0.3");
  EXPECT_EQ(t.meta.at("to"), "0.05");
  const auto mu = std::find(t.columns.begin(), t.columns.end(), "mu_k");
  const auto x_max = std::find(t.columns.begin(), t.columns.end(), "x_max");
  ASSERT_TRUE(mu != t.columns.end() && x_max != t.columns.end());
  for (const auto& row : t.rows) {
    const double m = std::stod(row[mu - t.columns.begin()]);
    EXPECT_NEAR(std::stod(row[x_max - t.columns.begin()]), DenHartogX(m, 1, 2), 1e-9) << m;
  }
  EXPECT_GT(t.rows.size(), 10u);
}

TEST_F(ForcedApp, BadForcedInputIsExitTwoNamingTheOption) {
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {{"--force", "1", "--omega", "0"}, "omega"},
      {{"--force", "-1"}, "force"},
      {{"--force", "1", "--param", "omega", "--from", "-1"}, "omega"},
      {{"--force", "1", "--param", "omega", "--from", "1", "--to", "1"}, "--to"},
      {{"--omega", "2"}, "--omega"},
      {{"--force", "1", "--param", "mu_k"}, "--param"},  // the cubic law has none
      {{"--force", "1", "--param", "gamma"}, "--param"},
      {{"--force", "1", "--restart", "plots", "--point", "PD1"}, "--restart"},
      {{"--force", "1", "--mass", "1"}, "--mass: the forced oscillator takes dimensionless inputs"},
  };
  for (const auto& c : cases) {
    const std::string dir = NewDir();
    const AppRun r = RunOut("ss_continue", dir, c.first);
    EXPECT_EQ(r.outcome.code, 2) << c.second << ": " << r.err;
    EXPECT_TRUE(tu::Contains(r.err, c.second)) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_FALSE(tu::Exists(dir + "/out")) << c.second;
  }
}

// --max_time stops the continuation itself (Palc's cancel hook), not only
// the phases around it: the files are written with status cancelled, exit 1.
// With --max_step 1e-4 the whole run takes 0.59 s here (0.13 s at the default
// max_step since the speed-ups of issue 19: too short for a 0.1 s limit).
TEST_F(ForcedApp, MaxTimeStopsAForcedRunWithStatusCancelled) {
  const std::string dir = NewDir();
  const tu::WallBound bound;
  const AppRun r =
      RunOut("ss_continue", dir,
             {"--law",  "coulomb", "--mu_s",     "0.3", "--mu_k",     "0.3",   "--v",    "0",
              "--beta", "0",       "--force",    "1",   "--param",    "omega", "--from", "0.75",
              "--to",   "2.5",     "--max_time", "0.1", "--max_step", "1e-4"});
  EXPECT_EQ(r.outcome.code, 1) << r.err;
  EXPECT_LT(r.outcome.seconds, bound.Of(1.0));
  const tu::Tsv t = tu::ReadTsv(tu::ReadFile(dir + "/out/branch.tsv"));
  EXPECT_TRUE(tu::Contains(t.meta.at("status"), "cancelled: time limit")) << t.meta.at("status");
  EXPECT_FALSE(t.rows.empty());
}

size_t Col(const tu::Tsv& t, const std::string& name) {
  const auto it = std::find(t.columns.begin(), t.columns.end(), name);
  EXPECT_NE(it, t.columns.end()) << name;
  return static_cast<size_t>(it - t.columns.begin());
}

double Cell(const tu::Tsv& t, size_t row, const std::string& name) {
  return std::stod(t.rows.at(row).at(Col(t, name)));
}

// A parameter of the run at its start, from the `parameters` line ("beta=0,...,omega=1.5").
double Parameter(const tu::Tsv& t, const std::string& name) {
  const std::string list = "," + t.meta.at("parameters");
  const size_t at = list.find("," + name + "=");
  EXPECT_NE(at, std::string::npos) << name << " in " << list;
  return std::stod(list.substr(at + name.size() + 2));
}

// The floor scene of forced_sliding_test (two crossing-sliding points), in omega.
std::vector<std::string> FloorScene() {
  return {"--law", "coulomb", "--mu_s", "0.4",     "--mu_k", "0.25",   "--v", "0",    "--beta",
          "0.05",  "--force", "0.5",    "--param", "omega",  "--from", "0.5", "--to", "2.5"};
}

// special_points.tsv: each located point has the branch.tsv row it sits on
// (pt), its label with an index per type (lab) and a description; the floor
// scene of forced_sliding_test has two crossing-sliding points.
TEST_F(ForcedApp, SpecialPointsCarryRowLabelAndDescription) {
  const std::string dir = NewDir();
  const AppRun r = RunOut("ss_continue", dir, FloorScene());
  ASSERT_EQ(r.outcome.code, 0) << r.err;
  const tu::Tsv b = tu::ReadTsv(tu::ReadFile(dir + "/out/branch.tsv"));
  const tu::Tsv sp = tu::ReadTsv(tu::ReadFile(dir + "/out/special_points.tsv"));
  ASSERT_EQ(sp.rows.size(), 2u);
  for (size_t i = 0; i < 2; ++i) {
    const auto& row = sp.rows[i];
    EXPECT_EQ(row[Col(sp, "lab")], "CR" + std::to_string(i + 1));
    EXPECT_TRUE(tu::Contains(row[Col(sp, "description")], "crossing-sliding"));
    const size_t pt = std::stoul(row[Col(sp, "pt")]);
    ASSERT_GE(pt, 1u);
    ASSERT_LE(pt, b.rows.size());
    EXPECT_EQ(b.rows[pt - 1][Col(b, "omega")], row[Col(sp, "omega")]);
    EXPECT_EQ(b.rows[pt - 1][Col(b, "pt")], row[Col(sp, "pt")]);
  }
}

// --restart from a forced run's label, without --force (the run's files say
// it was forced), in another axis: the new branch's first row is the point
// (its omega, its A, its stroboscopic state) and it runs to the far end of
// force's default range [0.1, 2].
TEST_F(ForcedApp, RestartFromLabelInForceStartsAtThePoint) {
  const std::string dir = NewDir();
  const AppRun r0 = RunOut("ss_continue", dir, FloorScene());
  ASSERT_EQ(r0.outcome.code, 0) << r0.err;
  const tu::Tsv sp = tu::ReadTsv(tu::ReadFile(dir + "/out/special_points.tsv"));
  ASSERT_FALSE(sp.rows.empty());
  ASSERT_EQ(sp.rows[0][Col(sp, "lab")], "CR1");
  const std::string dir2 = NewDir();
  const AppRun r = RunOut("ss_continue", dir2,
                          {"--restart", dir + "/out", "--point", "CR1", "--param", "force"});
  ASSERT_EQ(r.outcome.code, 0) << r.err;
  const tu::Tsv b = tu::ReadTsv(tu::ReadFile(dir2 + "/out/branch.tsv"));
  ASSERT_GT(b.rows.size(), 10u);
  EXPECT_EQ(b.meta.at("continued"), "force");
  EXPECT_EQ(b.meta.at("to"), "2");
  EXPECT_TRUE(tu::Contains(b.meta.at("restart"), "CR1")) << b.meta.at("restart");
  const double w = Parameter(b, "omega"), a = Cell(b, 0, "force");
  const double dx = std::abs(Cell(b, 0, "x_0") - Cell(sp, 0, "x_0"));
  const double dv = std::abs(Cell(b, 0, "xdot_0") - Cell(sp, 0, "xdot_0"));
  EXPECT_NEAR(w, Cell(sp, 0, "omega"), 1e-9);
  EXPECT_NEAR(a, 0.5, 1e-9);
  EXPECT_LT(dx, 1e-9);
  EXPECT_LT(dv, 1e-9);
  EXPECT_NEAR(Cell(b, b.rows.size() - 1, "force"), 2, 1e-12);
  // A = 0 on the restart is no forced oscillator: refused by name, nothing written.
  for (const std::vector<std::string>& zero :
       {std::vector<std::string>{"--force", "0"}, std::vector<std::string>{"--set", "force=0"}}) {
    const std::string dir3 = NewDir();
    std::vector<std::string> a = {"--restart", dir + "/out", "--point", "CR1", "--to", "0.5"};
    a.insert(a.end(), zero.begin(), zero.end());
    const AppRun e = RunOut("ss_continue", dir3, a);
    EXPECT_EQ(e.outcome.code, 2) << e.err;
    EXPECT_TRUE(tu::Contains(e.err, "force = 0: the forced oscillator needs a force A != 0"))
        << e.err;
    EXPECT_EQ(std::count(e.err.begin(), e.err.end(), '\n'), 1) << e.err;
    EXPECT_FALSE(tu::Exists(dir3 + "/out")) << e.err;
  }
  std::printf("[ measured ] first row - CR1: omega %.1e, A %.1e, x0 %.1e, xdot0 %.1e\n",
              std::abs(w - Cell(sp, 0, "omega")), std::abs(a - 0.5), dx, dv);
}

// Den Hartog's parameters: a restart in force from a non-stop row (by its
// pt) of the omega branch matches his closed form X(A) at that Omega.
TEST_F(ForcedApp, RestartInForceFromNonStopRowMatchesDenHartog) {
  const std::string dir = NewDir();
  const AppRun r0 =
      RunOut("ss_continue", dir,
             {"--law", "coulomb", "--mu_s", "0.3", "--mu_k", "0.3", "--v", "0", "--beta", "0",
              "--force", "1", "--param", "omega", "--from", "0.75", "--to", "2.5"});
  ASSERT_EQ(r0.outcome.code, 0) << r0.err;
  const tu::Tsv t = tu::ReadTsv(tu::ReadFile(dir + "/out/branch.tsv"));
  size_t i = 0;
  while (i < t.rows.size() && !(t.rows[i][Col(t, "kind")] == "pure-slip" &&
                                Cell(t, i, "omega") > 1.5 && Cell(t, i, "omega") < 1.6))
    ++i;
  ASSERT_LT(i, t.rows.size());
  const std::string pt = t.rows[i][Col(t, "pt")];
  const std::string dir2 = NewDir();
  const AppRun r =
      RunOut("ss_continue", dir2, {"--restart", dir + "/out", "--point", pt, "--param", "force"});
  ASSERT_EQ(r.outcome.code, 0) << r.err;
  const tu::Tsv b = tu::ReadTsv(tu::ReadFile(dir2 + "/out/branch.tsv"));
  const double w = Parameter(b, "omega");
  EXPECT_NEAR(w, Cell(t, i, "omega"), 1e-9);
  EXPECT_NEAR(Cell(b, 0, "force"), 1, 1e-9);
  EXPECT_NEAR(Cell(b, 0, "x_0"), Cell(t, i, "x_0"), 1e-9);
  EXPECT_NEAR(Cell(b, 0, "xdot_0"), Cell(t, i, "xdot_0"), 1e-9);
  int compared = 0;
  double worst = 0;
  for (size_t k = 0; k < b.rows.size(); ++k) {
    if (b.rows[k][Col(b, "kind")] != "pure-slip") continue;
    const double a = Cell(b, k, "force"), X = DenHartogX(0.3, a, w);
    EXPECT_NEAR(Cell(b, k, "x_max"), X, 1e-9 * std::max(1.0, X)) << "A = " << a;
    worst = std::max(worst, std::abs(Cell(b, k, "x_max") - X) / std::max(1.0, X));
    ++compared;
  }
  EXPECT_GT(compared, 20);
  EXPECT_NEAR(Cell(b, b.rows.size() - 1, "force"), 2, 1e-12);
  std::printf(
      "[ measured ] restart at pt %s (Omega %.6f): %d non-stop rows, max |x_max - X| / "
      "max(1, X) = %.2e\n",
      pt.c_str(), w, compared, worst);
  // A label the run does not have, or no label at all: exit 2, one line.
  for (const std::string bad : {"PD7", "XY1"}) {
    const std::string dir3 = NewDir();
    const AppRun e = RunOut("ss_continue", dir3, {"--restart", dir + "/out", "--point", bad});
    EXPECT_EQ(e.outcome.code, 2) << bad << ": " << e.err;
    EXPECT_TRUE(tu::Contains(e.err, "--point " + bad)) << e.err;
    EXPECT_EQ(std::count(e.err.begin(), e.err.end(), '\n'), 1) << e.err;
    EXPECT_FALSE(tu::Exists(dir3 + "/out")) << bad;
  }
}

}  // namespace
