// Restarts of the systems' runs (docs/systems.md, "Restarts"): the brake
// study's LP and the chain2 study's GR (at kc = 0.5), read back from the first run's files
// and continued in the same parameter, must give the first run's rows there
// (an independent check: a row of the first run, at the parameter value the
// restart is sent to, against the restart's last row); in a second parameter
// the first row is the point's orbit. Bad restarts exit 2 with one line that
// names the option, and write nothing. Cells that do not apply are empty.
#include <gtest/gtest.h>
#include <stdlib.h>
#include <sys/stat.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "app_test_util.hpp"

namespace {

namespace tu = stickslip::testing_util;

using Row = std::vector<std::string>;

class SystemRestart : public tu::AppTest {
 protected:
  // The first run of a study, once per test suite.
  static void SetUpTestSuite() {
    std::string tmpl = ::testing::TempDir() + "ss_sysrestart_XXXXXX";
    ASSERT_NE(::mkdtemp(tmpl.data()), nullptr);
    shared_ = tmpl;
    for (const char* study : {"mode_coupling", "chain2"}) {
      const std::string out = shared_ + "/" + study;
      const std::string cmd = std::string(STICKSLIP_BIN_DIR) + "/ss_continue --study " +
                              STICKSLIP_SOURCE_DIR + "/studies/" + study + ".ini" +
                              (std::string(study) == "chain2" ? " --set kc=0.5" : "") +
                              " --no_plots --out " + out + " >/dev/null 2>&1";
      // chain2 at kc = 0.5 (the study's is 0.2) ends at its GR with no orbit
      // of its period beyond (docs/systems.md).
      const int status = std::system(cmd.c_str());
      ASSERT_TRUE(tu::Exists(out + "/special_points.tsv")) << cmd << ": " << status;
    }
  }
  static void TearDownTestSuite() {
    EXPECT_EQ(std::system(("rm -rf " + tu::ShellQuoted(shared_)).c_str()), 0);
  }
  static std::string Study(const char* name) { return shared_ + "/" + name; }
  static tu::Tsv Table(const std::string& path) { return tu::ReadTsv(tu::ReadFile(path)); }
  static double At(const tu::Tsv& t, const Row& row, const std::string& column) {
    EXPECT_GE(t.Column(column), 0) << column;
    return std::stod(row.at(t.Column(column)));
  }
  // The row of `t` labelled `lab`.
  static Row Labelled(const tu::Tsv& t, const std::string& lab) {
    for (const Row& r : t.rows)
      if (r[t.Column("lab")] == lab) return r;
    ADD_FAILURE() << "no " << lab;
    return Row(t.columns.size(), "nan");
  }
  // The rows of branch b.
  static std::vector<Row> Branch(const tu::Tsv& t, int b) {
    std::vector<Row> out;
    for (const Row& r : t.rows)
      if (r[t.Column("branch")] == std::to_string(b)) out.push_back(r);
    return out;
  }
  // Row a of table ta equals row b of table tb: the parameter, the period and
  // every state component on the section, to tol.
  static void ExpectSameOrbit(const tu::Tsv& ta, const Row& a, const tu::Tsv& tb, const Row& b,
                              const std::string& param, double tol) {
    EXPECT_NEAR(At(ta, a, param), At(tb, b, param), tol);
    EXPECT_NEAR(At(ta, a, "period"), At(tb, b, "period"), tol);
    int components = 0;
    for (const std::string& c : ta.columns)
      if (c.size() > 2 && c.substr(c.size() - 2) == "_0" && c != "mode_0") {
        EXPECT_NEAR(At(ta, a, c), At(tb, b, c), tol) << c;
        ++components;
      }
    EXPECT_GE(components, 4);
    EXPECT_EQ(a[ta.Column("mode_0")], b[tb.Column("mode_0")]);
  }
  int Continue(const std::string& args, const std::string& out) {
    return RunApp(STICKSLIP_BIN_DIR, "ss_continue", args + " --no_plots --out " + out);
  }
  static std::string shared_;
};

std::string SystemRestart::shared_;

// From the brake's LP in mu_k, both halves of the fold run toward --to. Sent
// to the mu_k of a row of the first run (one on its stable side, one on its
// unstable side), the half of that stability must end on that row.
TEST_F(SystemRestart, BrakeFoldInMuKEndsOnTheFirstRunsRows) {
  const tu::Tsv first = Table(Study("mode_coupling") + "/branch.tsv");
  const tu::Tsv special = Table(Study("mode_coupling") + "/special_points.tsv");
  const std::vector<Row> b1 = Branch(first, 1);
  int lp = -1;
  for (int i = 0; i < static_cast<int>(b1.size()); ++i)
    if (At(first, b1[i], "pt") == At(special, Labelled(special, "LP1"), "pt")) lp = i;
  ASSERT_GE(lp, 4);
  for (int target : {lp - 3, lp + 3}) {  // stable before the fold, unstable after
    const Row& want = b1.at(target);
    const std::string out = dir_ + "/lp" + std::to_string(target);
    ASSERT_EQ(Continue("--restart " + Study("mode_coupling") + " --point LP1 --to " +
                           want[first.Column("mu_k")],
                       out),
              0)
        << err_;
    const tu::Tsv t = Table(out + "/branch.tsv");
    EXPECT_EQ(t.meta.at("status"), "complete");
    int matched = 0;
    for (int b : {1, 2}) {
      const std::vector<Row> rows = Branch(t, b);
      ASSERT_FALSE(rows.empty()) << b;
      if (rows.back()[t.Column("stable")] != want[first.Column("stable")]) continue;
      ExpectSameOrbit(t, rows.back(), first, want, "mu_k", 1e-9);
      ++matched;
    }
    EXPECT_EQ(matched, 1) << "one half of each stability";
  }
}

// The unstable half from the LP ends where the first run's did: at CL.
TEST_F(SystemRestart, BrakeFoldInMuKFindsTheFirstRunsContactLoss) {
  ASSERT_EQ(Continue("--restart " + Study("mode_coupling") + " --point LP1", dir_ + "/cl"), 0)
      << err_;
  const tu::Tsv first = Table(Study("mode_coupling") + "/special_points.tsv");
  const tu::Tsv t = Table(dir_ + "/cl/special_points.tsv");
  ExpectSameOrbit(t, Labelled(t, "CL1"), first, Labelled(first, "CL1"), "mu_k", 1e-9);
  EXPECT_EQ(t.meta.at("continued"), "mu_k");
  EXPECT_EQ(t.meta.at("to"), "0.3");  // the far end of the first run's range
}

// In v, the first row of each half is the LP's orbit of the first run.
TEST_F(SystemRestart, BrakeFoldInVStartsOnThePointsOrbit) {
  ASSERT_EQ(Continue("--restart " + Study("mode_coupling") + " --point LP1 --param v --to 0.4",
                     dir_ + "/v"),
            0)
      << err_;
  const tu::Tsv first = Table(Study("mode_coupling") + "/special_points.tsv");
  const Row lp = Labelled(first, "LP1");
  const tu::Tsv t = Table(dir_ + "/v/branch.tsv");
  EXPECT_EQ(t.meta.at("continued"), "v");
  EXPECT_TRUE(tu::Contains(t.meta.at("parameters"), "mu_k=" + lp[first.Column("mu_k")]));
  for (int b : {1, 2}) {
    const std::vector<Row> rows = Branch(t, b);
    ASSERT_GE(rows.size(), 2u) << b;
    EXPECT_NEAR(At(t, rows.front(), "v"), 0.5, 1e-9);  // the mode-coupling study's v
    EXPECT_NEAR(At(t, rows.front(), "period"), At(first, lp, "period"), 1e-9);
    for (const char* c : {"x_0", "xdot_0", "y_0", "ydot_0"})
      EXPECT_NEAR(At(t, rows.front(), c), At(first, lp, c), 1e-9) << c;
    EXPECT_NEAR(At(t, rows.back(), "v"), 0.4, 1e-12);
  }
}

// LP1 given by its point number is the same fold: two halves, one of each
// stability ending on the first run's row, as by its label.
TEST_F(SystemRestart, BrakeFoldByNumberIsAFoldToo) {
  const tu::Tsv first = Table(Study("mode_coupling") + "/branch.tsv");
  const tu::Tsv special = Table(Study("mode_coupling") + "/special_points.tsv");
  const std::string pt = Labelled(special, "LP1")[special.Column("pt")];
  const std::vector<Row> b1 = Branch(first, 1);
  int lp = -1;
  for (int i = 0; i < static_cast<int>(b1.size()); ++i)
    if (b1[i][first.Column("pt")] == pt) lp = i;
  ASSERT_GE(lp, 4);
  const Row& want = b1.at(lp - 3);
  const std::string out = dir_ + "/bynumber";
  ASSERT_EQ(Continue("--restart " + Study("mode_coupling") + " --point " + pt + " --to " +
                         want[first.Column("mu_k")],
                     out),
            0)
      << err_;
  const tu::Tsv t = Table(out + "/branch.tsv");
  EXPECT_TRUE(tu::Contains(t.meta.at("restart"), "LP")) << t.meta.at("restart");
  int matched = 0;
  for (int b : {1, 2}) {
    const std::vector<Row> rows = Branch(t, b);
    ASSERT_GE(rows.size(), 2u) << "branch " << b << ": both halves of the fold";
    if (rows.back()[t.Column("stable")] != want[first.Column("stable")]) continue;
    ExpectSameOrbit(t, rows.back(), first, want, "mu_k", 1e-9);
    ++matched;
  }
  EXPECT_EQ(matched, 1);
}

// The first run's range made [0.5, 0.7] (as if run from 0.7 down to 0.5): its
// far end from the LP (0.529), 0.7, lies on the side without the branch. With
// --to omitted the restart runs to 0.5, where the first run's rows next to
// the LP lie, and both halves get there.
TEST_F(SystemRestart, BrakeFoldDefaultsToTheBranchSide) {
  const std::string run = dir_ + "/range";
  ASSERT_EQ(std::system(("cp -r " + Study("mode_coupling") + " " + run +
                         " && sed -i 's/^# from: .*/# from: 0.5/' " + run + "/branch.tsv " + run +
                         "/special_points.tsv")
                            .c_str()),
            0);
  ASSERT_EQ(Continue("--restart " + run + " --point LP1", dir_ + "/side"), 0) << err_;
  const tu::Tsv special = Table(run + "/special_points.tsv");
  const double lp = At(special, Labelled(special, "LP1"), "mu_k");
  const tu::Tsv t = Table(dir_ + "/side/branch.tsv");
  EXPECT_EQ(t.meta.at("to"), "0.5");
  EXPECT_EQ(t.meta.at("status"), "complete");
  for (int b : {1, 2}) {
    const std::vector<Row> rows = Branch(t, b);
    ASSERT_GE(rows.size(), 3u) << b;
    for (const Row& r : rows) EXPECT_LE(At(t, r, "mu_k"), lp + 1e-9) << b;
    EXPECT_LT(At(t, rows.back(), "mu_k"), lp - 1e-3) << b;
  }
}

// A restart stopped by --max_time reports its cut piece as cancelled, not as
// the numerical failure the cancel caused inside a run of the flow. Small
// steps make the restart last seconds (0.2 s with the default --max_step);
// steady sliding, 10001 rows, takes a few ms.
TEST_F(SystemRestart, RestartStoppedByMaxTimeIsCancelled) {
  const std::string out = dir_ + "/late";
  EXPECT_EQ(Continue("--restart " + Study("mode_coupling") +
                         " --point LP1 --max_step 1e-4 --max_time 0.5",
                     out),
            1)
      << err_;
  const tu::Tsv t = Table(out + "/branch.tsv");
  ASSERT_EQ(t.meta.at("steady_status"), "reached-end") << "the limit fell before the branch";
  EXPECT_TRUE(tu::Contains(t.meta.at("status"), "partial: branch 1 cancelled: time limit"))
      << t.meta.at("status");
  for (const char* key : {"branch_1_status", "branch_2_status"})
    if (t.meta.count(key)) {
      EXPECT_EQ(t.meta.at(key).rfind("cancelled", 0), 0u) << t.meta.at(key);
    }
  EXPECT_TRUE(tu::Contains(err_, "cancelled")) << err_;
}

// From chain2's GR (kc = 0.5) back down in v, to the v of a row of the first run.
TEST_F(SystemRestart, ChainGrazingInVEndsOnTheFirstRunsRow) {
  const tu::Tsv first = Table(Study("chain2") + "/branch.tsv");
  const std::vector<Row> b1 = Branch(first, 1);
  ASSERT_GE(b1.size(), 10u);
  const Row& want = b1[b1.size() - 6];
  ASSERT_EQ(
      Continue("--restart " + Study("chain2") + " --point GR1 --to " + want[first.Column("v")],
               dir_ + "/gr"),
      0)
      << err_;
  const tu::Tsv t = Table(dir_ + "/gr/branch.tsv");
  const std::vector<Row> rows = Branch(t, 1);
  ASSERT_GE(rows.size(), 2u);
  ExpectSameOrbit(t, rows.back(), first, want, "v", 1e-9);
  const tu::Tsv special = Table(Study("chain2") + "/special_points.tsv");
  ExpectSameOrbit(t, rows.front(), special, Labelled(special, "GR1"), "v", 1e-9);
}

// No nan or inf is written: what does not apply is an empty cell (the period,
// the multipliers and mult_max on steady sliding, max_real on orbit rows).
TEST_F(SystemRestart, NotApplicableCellsAreEmptyNeverNan) {
  for (const char* study : {"mode_coupling", "chain2"})
    for (const char* file : {"/branch.tsv", "/special_points.tsv"}) {
      const std::string path = Study(study) + file;
      const tu::Tsv t = Table(path);
      ASSERT_FALSE(t.rows.empty()) << path;
      int eq = 0, orbits = 0;
      for (const Row& r : t.rows) {
        ASSERT_EQ(r.size(), t.columns.size()) << path;
        for (std::size_t j = 0; j < r.size(); ++j) {
          std::string cell = r[j];
          std::transform(cell.begin(), cell.end(), cell.begin(), ::tolower);
          EXPECT_TRUE(cell.find("nan") == std::string::npos &&
                      cell.find("inf") == std::string::npos)
              << path << " " << t.columns[j] << " = " << r[j];
        }
        const bool steady = r[t.Column("branch")] == "0";
        ++(steady ? eq : orbits);
        for (const std::string& c : t.columns) {
          const bool na =
              c == "max_real" ? !steady : steady && (c == "period" || c.rfind("mult", 0) == 0);
          EXPECT_EQ(r[t.Column(c)].empty(), na)
              << path << " " << c << " = '" << r[t.Column(c)] << "'";
        }
      }
      EXPECT_TRUE(eq > 0 && orbits > 0) << path;  // HB1 in special_points.tsv too
    }
}

// A file of an older run, with nan where this one has empty cells, still restarts.
TEST_F(SystemRestart, OlderFilesWithNanStillRestart) {
  const std::string old = dir_ + "/old";
  const std::string nan = "sed -i -e ':a' -e 's/\\t\\t/\\tnan\\t/' -e 'ta' ";
  ASSERT_EQ(
      std::system(("cp -r " + Study("chain2") + " " + old + " && " + nan + old + "/branch.tsv " +
                   old + "/special_points.tsv && grep -q 'nan' " + old + "/special_points.tsv")
                      .c_str()),
      0);
  ASSERT_EQ(Continue("--restart " + old + " --point GR1 --to 0.39", dir_ + "/from_old"), 0) << err_;
  const tu::Tsv t = Table(dir_ + "/from_old/branch.tsv"),
                sp = Table(Study("chain2") + "/special_points.tsv");
  ASSERT_FALSE(Branch(t, 1).empty());
  ExpectSameOrbit(t, Branch(t, 1).front(), sp, Labelled(sp, "GR1"), "v", 1e-9);
  EXPECT_EQ(Continue("--restart " + old + " --point HB1", dir_ + "/bad"), 2);
  EXPECT_TRUE(tu::Contains(err_, "--point HB1 is a point of steady sliding")) << err_;
}

TEST_F(SystemRestart, BadRestartsExitTwoWithOneLineNamingTheOption) {
  const std::string chain = Study("chain2");
  ASSERT_EQ(Continue("--no_estimates", dir_ + "/belt"), 0) << err_;
  ASSERT_EQ(std::system(("cp -r " + chain + " " + dir_ + "/fifo && rm " + dir_ +
                         "/fifo/special_points.tsv && mkfifo " + dir_ +
                         "/fifo/special_points.tsv && cp -r " + chain + " " + dir_ +
                         "/big && truncate -s 65M " + dir_ + "/big/special_points.tsv")
                            .c_str()),
            0);
  // chain2's run with one '# key:' line of both files hand-edited.
  auto edited = [&](const std::string& key, const std::string& value) {
    const std::string d = dir_ + "/edit_" + key;
    const std::string sed = "sed -i 's/^# " + key + ": .*/# " + key + ": " + value + "/' ";
    EXPECT_EQ(std::system(("cp -r " + chain + " " + d + " && " + sed + d + "/branch.tsv " + d +
                           "/special_points.tsv")
                              .c_str()),
              0);
    return d;
  };
  const std::pair<std::string, std::string> cases[] = {
      {"--restart " + edited("blocks", "nan") + " --point GR1", "blocks = 'nan' is not a whole"},
      {"--restart " + edited("section_returns", "1.5") + " --point GR1",
       "section_returns = '1.5' is not a whole"},
      {"--restart " + edited("max_steps", "1e300") + " --point 3", "max_steps = '1e300' is not"},
      {"--restart " + edited("to", "inf") + " --point GR1", "to = 'inf' is not finite"},
      {"--restart " + edited("from", "nan") + " --point 3", "branch.tsv' is corrupt: from = 'nan'"},
      {"--restart " + edited("max_amplitude", "inf") + " --point GR1",
       "max_amplitude = 'inf' is not finite"},
      {"--restart " + chain + " --point LP7", "--point LP7: no point LP7 in"},
      {"--restart " + chain + " --point GR9", "(its labels: HB1, GR1)"},
      {"--restart " + dir_ + "/belt --point GR1 --system chain",
       "is a run of the belt or the forced oscillator"},
      {"--restart " + chain + " --point GR1 --system mode_coupling",
       "--system mode_coupling: " + chain + " is a run of --system chain"},
      {"--restart " + chain + " --point GR1 --blocks 3", "--blocks 3: " + chain},
      {"--restart " + dir_ + "/fifo --point GR1", "--restart " + dir_ + "/fifo: cannot read"},
      {"--restart " + dir_ + "/fifo --point GR1 --system chain", "not a regular file"},
      {"--restart " + dir_ + "/big --point GR1 --system chain", "more than 67108864 bytes"},
      {"--restart " + chain + " --point HB1", "--point HB1 is a point of steady sliding"},
      {"--restart " + chain + " --point GR1 --param kc", "--to is required with --restart in kc"},
      {"--restart " + chain + " --point GR1 --switch", "--switch needs --point PDn"},
      {"--restart " + chain + " --point GR1 --start_at 0.3", "--start_at: a restart starts"},
      {"--restart " + chain + " --point GR1 --from 0.4 --to 0.5", "must lie between --from"},
  };
  for (const auto& [args, message] : cases) {
    const std::string out = dir_ + "/bad";
    EXPECT_EQ(Continue(args, out), 2) << args << "\n" << err_;
    EXPECT_TRUE(tu::Contains(err_, message)) << args;
    EXPECT_EQ(std::count(err_.begin(), err_.end(), '\n'), 1) << err_;
    EXPECT_FALSE(tu::Exists(out)) << args;
  }
}

}  // namespace
