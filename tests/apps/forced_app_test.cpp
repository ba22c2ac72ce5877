// End-to-end tests of ss_continue --force (issue 20, "Done when"): the Den
// Hartog run matches his closed form on every non-stop row of branch.tsv, and
// bad forced input is exit 2 with one line naming the option, nothing written.
#include <gtest/gtest.h>
#include <stdlib.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "app_test_util.hpp"

namespace {

namespace tu = stickslip::testing_util;
const std::string kApp = STICKSLIP_BIN_DIR "/ss_continue";

std::string TempDir() {
  std::string tmpl = ::testing::TempDir() + "ss_forced_test_XXXXXX";
  if (::mkdtemp(tmpl.data()) == nullptr) ADD_FAILURE() << "mkdtemp failed";
  return tmpl;
}

struct Result {
  tu::Outcome outcome;
  std::string out, err;
};

Result RunApp(const std::string& dir, std::vector<std::string> args) {
  tu::Launch l;
  l.out_path = dir + "/stdout", l.err_path = dir + "/stderr";
  args.insert(args.end(), {"--out", dir + "/out", "--no_plots"});
  Result r;
  r.outcome = tu::RunChild(kApp, args, l);
  r.out = tu::ReadFile(l.out_path), r.err = tu::ReadFile(l.err_path);
  return r;
}

// Den Hartog (1931), computed here on its own: X = sqrt(V^2 - (mu U)^2),
// V = A / (1 - W^2), U = sin(pi / W) / (W (1 + cos(pi / W))).
double DenHartogX(double mu, double a, double w) {
  const double V = a / (1 - w * w), U = std::sin(M_PI / w) / (w * (1 + std::cos(M_PI / w)));
  return std::sqrt(V * V - mu * mu * U * U);
}

TEST(ForcedApp, DenHartogRunMatchesClosedFormOnEveryNonStopRow) {
  const std::string dir = TempDir();
  const Result r =
      RunApp(dir, {"--law", "coulomb", "--mu_s", "0.3", "--mu_k", "0.3", "--v", "0", "--beta", "0",
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
  EXPECT_TRUE(tu::Contains(t.meta.at("omega"), "[0.75, 2.5]"));
  int compared = 0;
  double worst = 0, w_min = 10, w_max = 0;
  for (const auto& row : t.rows) {
    ASSERT_EQ(row.size(), t.columns.size());
    EXPECT_EQ(row[m], "1");
    if (row[kind] != "non-stop") continue;
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

TEST(ForcedApp, BadForcedInputIsExitTwoNamingTheOption) {
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {{"--force", "1", "--omega", "0"}, "omega"},
      {{"--force", "-1"}, "force"},
      {{"--force", "1", "--param", "omega", "--from", "-1"}, "omega"},
      {{"--force", "1", "--param", "omega", "--from", "1", "--to", "1"}, "--to"},
      {{"--omega", "2"}, "--omega"},
      {{"--force", "1", "--param", "mu_s"}, "--param"},
      {{"--force", "1", "--restart", "plots", "--point", "PD1"}, "--restart"},
  };
  for (const auto& c : cases) {
    const std::string dir = TempDir();
    const Result r = RunApp(dir, c.first);
    EXPECT_EQ(r.outcome.code, 2) << c.second << ": " << r.err;
    EXPECT_TRUE(tu::Contains(r.err, c.second)) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_FALSE(tu::Exists(dir + "/out")) << c.second;
  }
}

// --max_time stops the continuation itself (Palc's cancel hook), not only
// the phases around it: the files are written with status cancelled, exit 1.
// The whole run takes 0.57 s here with exit 0 (ForcedApp.DenHartog...).
TEST(ForcedApp, MaxTimeStopsAForcedRunWithStatusCancelled) {
  const std::string dir = TempDir();
  const Result r =
      RunApp(dir, {"--law",  "coulomb", "--mu_s", "0.3",     "--mu_k",     "0.3",     "--v",
                   "0",      "--beta",  "0",      "--force", "1",          "--param", "omega",
                   "--from", "0.75",    "--to",   "2.5",     "--max_time", "0.1"});
  EXPECT_EQ(r.outcome.code, 1) << r.err;
  EXPECT_LT(r.outcome.seconds, 1.0);
  const tu::Tsv t = tu::ReadTsv(tu::ReadFile(dir + "/out/branch.tsv"));
  EXPECT_TRUE(tu::Contains(t.meta.at("status"), "cancelled (time limit")) << t.meta.at("status");
  EXPECT_FALSE(t.rows.empty());
}

// special_points.tsv: each located point has the branch.tsv row it sits on
// (pt), its label with an index per type (lab) and a description; the floor
// scene of forced_sliding_test has two crossing-sliding points.
TEST(ForcedApp, SpecialPointsCarryRowLabelAndDescription) {
  const std::string dir = TempDir();
  const Result r =
      RunApp(dir, {"--law", "coulomb", "--mu_s", "0.4", "--mu_k", "0.25", "--v", "0", "--beta",
                   "0.05", "--force", "0.5", "--param", "omega", "--from", "0.5", "--to", "2.5"});
  ASSERT_EQ(r.outcome.code, 0) << r.err;
  const tu::Tsv b = tu::ReadTsv(tu::ReadFile(dir + "/out/branch.tsv"));
  const tu::Tsv sp = tu::ReadTsv(tu::ReadFile(dir + "/out/special_points.tsv"));
  auto col = [](const tu::Tsv& t, const std::string& name) {
    return static_cast<size_t>(std::find(t.columns.begin(), t.columns.end(), name) -
                               t.columns.begin());
  };
  ASSERT_EQ(sp.rows.size(), 2u);
  for (size_t i = 0; i < 2; ++i) {
    const auto& row = sp.rows[i];
    EXPECT_EQ(row[col(sp, "lab")], "CR" + std::to_string(i + 1));
    EXPECT_TRUE(tu::Contains(row[col(sp, "description")], "crossing-sliding"));
    const size_t pt = std::stoul(row[col(sp, "pt")]);
    ASSERT_GE(pt, 1u);
    ASSERT_LE(pt, b.rows.size());
    EXPECT_EQ(b.rows[pt - 1][col(b, "omega")], row[col(sp, "omega")]);
    EXPECT_EQ(b.rows[pt - 1][col(b, "pt")], row[col(sp, "pt")]);
  }
}

}  // namespace
