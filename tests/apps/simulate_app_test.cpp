// End-to-end tests of the built ss_simulate: output format (--out DIR holds
// trajectory.tsv), and bad input rejected with exit code 2, one line on
// stderr, and no output file.
#include <dirent.h>
#include <gtest/gtest.h>
#include <stdlib.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "app_test_util.hpp"
#include "test_paths.hpp"

namespace {

using stickslip::testing_util::Contains;
using stickslip::testing_util::Exists;
using stickslip::testing_util::ReadFile;
using stickslip::testing_util::ReadTsv;
using stickslip::testing_util::Tsv;
using stickslip::testing_util::WriteFile;

using stickslip::testing_util::ShellQuoted;

// A fresh directory per test, removed afterwards.
class SimulateApp : public stickslip::testing_util::AppTest {
 protected:
  struct Result {
    int code = -1;
    std::string out, err;
    // stderr lines
    std::vector<std::string> err_lines() const {
      std::vector<std::string> lines;
      std::istringstream is(err);
      for (std::string l; std::getline(is, l);) lines.push_back(l);
      return lines;
    }
  };

  // Runs ss_simulate with the arguments (each quoted for the shell), without
  // figures (tests/io/figure_format_app_test.cpp draws them).
  Result Run(const std::vector<std::string>& args) {
    std::string words = " --no_plots";
    for (const auto& a : args) words += " " + ShellQuoted(a);
    Result r;
    r.code = RunApp(STICKSLIP_BIN_DIR, "ss_simulate", words);
    r.out = out_, r.err = err_;
    return r;
  }

  std::string Path(const std::string& name) const { return dir_ + "/" + name; }
  // The trajectory written into the output directory `out`.
  static std::string Traj(const std::string& out) { return ReadFile(out + "/trajectory.tsv"); }

  // Expects a rejection: exit 2, one stderr line naming `part`, no output.
  void ExpectRejected(std::vector<std::string> args, const std::string& part) {
    const std::string out = Path("rejected");
    args.push_back("--out");
    args.push_back(out);
    const Result r = Run(args);
    std::string shown;
    for (const auto& a : args) shown += a + " ";
    EXPECT_EQ(r.code, 2) << shown << "\n" << r.err;
    const auto lines = r.err_lines();
    ASSERT_EQ(lines.size(), 1u) << shown << "\n" << r.err;
    EXPECT_TRUE(Contains(lines[0], "ss_simulate: error: ")) << shown;
    EXPECT_TRUE(Contains(lines[0], part)) << shown;
    EXPECT_FALSE(Exists(out)) << shown;
    EXPECT_EQ(r.out, "") << shown;
  }
};

struct Row {
  double t, x, xdot;
  std::string mode;
};

// Data rows of a ss_simulate TSV (comment lines skipped).
std::vector<Row> ReadRows(const std::string& text) {
  std::vector<Row> rows;
  std::istringstream is(text);
  for (std::string line; std::getline(is, line);) {
    if (line.empty() || line[0] == '#' || line.rfind("t\t", 0) == 0) continue;  // header
    std::istringstream ls(line);
    std::string t, x, xdot, mode;
    std::getline(ls, t, '\t');
    std::getline(ls, x, '\t');
    std::getline(ls, xdot, '\t');
    std::getline(ls, mode, '\t');
    rows.push_back({std::strtod(t.c_str(), nullptr), std::strtod(x.c_str(), nullptr),
                    std::strtod(xdot.c_str(), nullptr), mode});
  }
  return rows;
}

TEST_F(SimulateApp, HelpExitsZeroAndListsOptions) {
  const Result r = Run({"--help"});
  EXPECT_EQ(r.code, 0);
  EXPECT_EQ(r.err, "");
  for (const char* opt :
       {"--study", "--law", "--beta", "--v ", "--mu_s", "--mass", "--rtol", "--method", "--x0",
        "--xdot0", "--t_end", "--dt", "--out", "--no_plots", "--force", "--omega", "--section"})
    EXPECT_TRUE(Contains(r.out, opt));
}

TEST_F(SimulateApp, VersionAndShortHelp) {
  const Result v = Run({"--version"});
  ASSERT_EQ(v.code, 0) << v.err;
  EXPECT_EQ(v.out.rfind("ss_simulate 0.", 0), 0u) << v.out;
  const Result h = Run({"-h"});
  ASSERT_EQ(h.code, 0) << h.err;
  EXPECT_TRUE(Contains(h.out, "--version"));
}

TEST_F(SimulateApp, WritesTrajectoryWithExactStick) {
  const std::string out = Path("seed");
  const Result r = Run({"--study", kStudies + "/seed.ini", "--t_end", "30", "--out", out});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.err, "");
  const std::string text = Traj(out);
  const Tsv tsv = ReadTsv(text);
  EXPECT_EQ(tsv.columns, (std::vector<std::string>{"t", "x", "xdot", "mode"}));
  EXPECT_EQ(text.rfind("# tool: ss_simulate ", 0), 0u);
  EXPECT_EQ(tsv.meta.at("t_end"), "30");
  EXPECT_EQ(tsv.meta.at("status"), "complete");
  const auto rows = ReadRows(text);
  ASSERT_GT(rows.size(), 3000u);
  EXPECT_EQ(rows.front().t, 0.0);
  EXPECT_EQ(rows.front().mode, "stick");  // (0, 0.25) lies in Omega
  EXPECT_NEAR(rows.back().t, 30.0, 1e-9);
  int stick = 0, below = 0;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const Row& row = rows[i];
    ASSERT_TRUE(row.mode == "stick" || row.mode == "slip-below" || row.mode == "slip-above")
        << row.mode;
    if (i > 0) {
      EXPECT_GE(row.t, rows[i - 1].t);
    }
    if (row.mode == "stick") {
      ++stick;
      EXPECT_EQ(row.xdot, 0.25) << "t = " << row.t;  // exactly v
      EXPECT_LE(std::abs(row.x + 2 * 0.05 * 0.25), 0.4 + 1e-12);
    } else if (row.mode == "slip-below") {
      ++below;
      EXPECT_LE(row.xdot, 0.25 + 1e-9);
    }
  }
  EXPECT_GT(stick, 100);
  EXPECT_GT(below, 100);
}

TEST_F(SimulateApp, CommandLineOverridesStudy) {
  WriteFile(Path("s.ini"), "# test study\nlaw = cubic\nv = 0.3\n\n[simulate]\nxdot0 = 0.3\n");
  const std::string out = Path("o");
  const Result r = Run(
      {"--study", Path("s.ini"), "--v", "0.2", "--xdot0", "0.2", "--t_end", "20", "--out", out});
  ASSERT_EQ(r.code, 0) << r.err;
  int stick = 0;
  for (const Row& row : ReadRows(Traj(out))) {
    if (row.mode == "stick") {
      ++stick;
      EXPECT_EQ(row.xdot, 0.2);
    }
  }
  EXPECT_GT(stick, 0);
}

TEST_F(SimulateApp, StudySectionsOfOtherAppsAreSkipped) {
  WriteFile(Path("s.ini"), "v = 0.25\n[continue]\nparam = v\nfrom = 0.05\n[simulate]\nt_end = 5\n");
  const std::string out = Path("o");
  const Result r = Run({"--study", Path("s.ini"), "--out", out});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NEAR(ReadRows(Traj(out)).back().t, 5.0, 1e-9);
}

TEST_F(SimulateApp, AllStudiesRun) {
  for (const char* study : {"seed", "seed_beta", "stribeck", "coulomb", "leine", "den_hartog",
                            "floor_static", "seed_forced", "stribeck_forced"}) {
    const std::string out = Path(study);
    const Result r =
        Run({"--study", kStudies + "/" + study + ".ini", "--t_end", "20", "--out", out});
    EXPECT_EQ(r.code, 0) << study << ": " << r.err;
    EXPECT_TRUE(Exists(out + "/trajectory.tsv")) << study;
  }
}

TEST_F(SimulateApp, PhysicalInputsAtUnitScalesMatchTheSeedSet) {
  // M = K = g = 1: the physical numbers are the dimensionless ones.
  const Result a = Run({"--t_end", "10", "--out", Path("a")});
  const Result b =
      Run({"--mass", "1", "--stiffness", "1", "--gravity", "1", "--damping", "0.1", "--belt_speed",
           "0.25", "--speed_m", "0.5", "--t_end", "10", "--out", Path("b")});
  ASSERT_EQ(a.code, 0) << a.err;
  ASSERT_EQ(b.code, 0) << b.err;
  // The same rows; b also carries the physical copies (t_s, x_m, xdot_m_s) and scales.
  const Tsv ta = ReadTsv(Traj(Path("a"))), tb = ReadTsv(Traj(Path("b")));
  ASSERT_EQ(ta.rows.size(), tb.rows.size());
  ASSERT_GT(ta.rows.size(), 100u);
  for (size_t i = 0; i < ta.rows.size(); ++i)
    ASSERT_EQ(ta.rows[i], std::vector<std::string>(tb.rows[i].begin(), tb.rows[i].begin() + 4));
  EXPECT_EQ(tb.meta.at("L"), "1 m (M g / K)");
  EXPECT_EQ(tb.meta.at("t0"), "1 s (sqrt(M / K))");
  EXPECT_EQ(tb.columns.at(4), "t_s");
}

TEST_F(SimulateApp, RejectsUnknownOption) { ExpectRejected({"--gamma", "1"}, "--gamma"); }

TEST_F(SimulateApp, RejectsAbbreviatedOption) { ExpectRejected({"--bet", "0.1"}, "--bet"); }

TEST_F(SimulateApp, RejectsPositionalArgument) { ExpectRejected({"stray"}, "stray"); }

TEST_F(SimulateApp, RejectsNonNumbers) {
  ExpectRejected({"--beta", "abc"}, "'abc' for --beta");
  ExpectRejected({"--beta", "1.2x"}, "'1.2x' for --beta");
  ExpectRejected({"--x0", ""}, "--x0");
  ExpectRejected({"--t_end", "1e999"}, "'1e999' for --t_end");
}

TEST_F(SimulateApp, RejectsNanAndInf) {
  ExpectRejected({"--mu_s", "nan"}, "'nan' for --mu_s");
  ExpectRejected({"--v", "inf"}, "'inf' for --v");
  ExpectRejected({"--xdot0", "-inf"}, "'-inf' for --xdot0");
}

TEST_F(SimulateApp, RejectsInvalidModels) {
  ExpectRejected({"--mu_m", "0.5"}, "mu_m = 0.5");
  ExpectRejected({"--v", "0"}, "v = 0");
  ExpectRejected({"--v", "-0.1"}, "v = -0.1");
  ExpectRejected({"--beta", "-0.01"}, "beta = -0.01");
  ExpectRejected({"--law", "coulomb", "--mu_k", "0.5"}, "mu_k = 0.5");
  ExpectRejected({"--law", "viscous"}, "viscous");
}

TEST_F(SimulateApp, RejectsMixedPhysicalAndDimensionless) {
  ExpectRejected({"--mass", "1", "--beta", "0.1"}, "--beta");
  ExpectRejected({"--mass", "1", "--stiffness", "1", "--belt_speed", "1", "--speed_m", "1"},
                 "--damping");
  ExpectRejected({"--mass", "-1", "--stiffness", "1", "--damping", "0.1", "--belt_speed", "1",
                  "--speed_m", "1"},
                 "mass = -1");
}

TEST_F(SimulateApp, RejectsBadSolverOptions) {
  ExpectRejected({"--rtol", "1"}, "rtol = 1");
  ExpectRejected({"--rtol", "1e-20"}, "rtol = 1e-20");
  ExpectRejected({"--atol", "0"}, "atol = 0");
  ExpectRejected({"--method", "rk4"}, "'rk4'");
  ExpectRejected({"--max_steps", "2.5"}, "'2.5'");
}

TEST_F(SimulateApp, RejectsBadRunOptions) {
  ExpectRejected({"--t_end", "0"}, "--t_end");
  ExpectRejected({"--dt", "-0.1"}, "--dt");
  ExpectRejected({"--dt", "1e-9"}, "--dt");
}

TEST_F(SimulateApp, RejectsMissingStudyFile) {
  ExpectRejected({"--study", Path("missing.ini")}, "missing.ini");
  ExpectRejected({"--study", dir_}, dir_);
}

TEST_F(SimulateApp, RejectsMalformedStudyLineWithLineNumber) {
  WriteFile(Path("bad.ini"), "# comment\nlaw = cubic\nbeta 0.05\nv = 0.25\n");
  ExpectRejected({"--study", Path("bad.ini")}, "bad.ini:3");
  WriteFile(Path("bad2.ini"), "v = 0.25\n\n[simulate\n");
  ExpectRejected({"--study", Path("bad2.ini")}, "bad2.ini:3");
  WriteFile(Path("bad3.ini"), "v =\n");
  ExpectRejected({"--study", Path("bad3.ini")}, "bad3.ini:1");
  WriteFile(Path("bad4.ini"), "v = 0.25\nbeta = 0.1\nv = 0.3\n");
  ExpectRejected({"--study", Path("bad4.ini")}, "bad4.ini:3");
}

TEST_F(SimulateApp, RejectsUnknownStudyKey) {
  WriteFile(Path("bad.ini"), "law = cubic\ngamma = 2\n");
  ExpectRejected({"--study", Path("bad.ini")}, "'gamma'");
  WriteFile(Path("bad2.ini"), "[simulation]\nx0 = 1\n");
  ExpectRejected({"--study", Path("bad2.ini")}, "simulation");
}

TEST_F(SimulateApp, BadStudyValueNamesTheLine) {
  WriteFile(Path("bad.ini"), "law = cubic\n\nbeta = fast\n");
  ExpectRejected({"--study", Path("bad.ini")}, "'fast' for beta (" + Path("bad.ini") + ":3)");
  WriteFile(Path("bad2.ini"), "mu_m = 0.45\n");
  ExpectRejected({"--study", Path("bad2.ini")}, "mu_m = 0.45");
}

TEST_F(SimulateApp, RejectsUnwritableOutputDirectory) {
  // Running as root defeats permission bits: use paths that cannot exist.
  const Result r = Run({"--out", Path("no/such/dir/out.tsv")});
  EXPECT_EQ(r.code, 2);
  ASSERT_EQ(r.err_lines().size(), 1u) << r.err;
  EXPECT_TRUE(Contains(r.err, Path("no/such/dir/out.tsv")));
  EXPECT_FALSE(Exists(Path("no")));
  WriteFile(Path("plain"), "x");
  const Result r2 = Run({"--out", Path("plain/out.tsv")});
  EXPECT_EQ(r2.code, 2);
  EXPECT_TRUE(Contains(r2.err, "plain/out.tsv"));
  EXPECT_EQ(ReadFile(Path("plain")), "x");
}

// Issue 19 item 4: --out names a directory, as in every app.
TEST_F(SimulateApp, OutIsADirectory) {
  const Result r = Run({"--t_end", "1", "--out", Path("o")});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(Exists(Path("o/trajectory.tsv")));
  EXPECT_TRUE(Exists(Path("o/trajectory.gp")));
  WriteFile(Path("file"), "x");
  const Result r2 = Run({"--t_end", "1", "--out", Path("file")});
  EXPECT_EQ(r2.code, 2);
  EXPECT_TRUE(Contains(r2.err, "--out")) << r2.err;
  EXPECT_EQ(ReadFile(Path("file")), "x");
}

TEST_F(SimulateApp, LeavesExistingOutputUnchangedOnBadInput) {
  const std::string out = Path("keep");
  ASSERT_EQ(::mkdir(out.c_str(), 0755), 0);
  WriteFile(out + "/trajectory.tsv", "precious\n");
  for (const std::vector<std::string>& bad : {std::vector<std::string>{"--beta", "nan"},
                                              {"--mu_m", "0.5"},
                                              {"--gamma", "1"},
                                              {"--study", Path("missing.ini")}}) {
    std::vector<std::string> args = bad;
    args.push_back("--out");
    args.push_back(out);
    const Result r = Run(args);
    EXPECT_EQ(r.code, 2) << bad[0];
    EXPECT_EQ(Traj(out), "precious\n") << bad[0];
  }
}

TEST_F(SimulateApp, IntegratorFailureWritesThePartialTrajectory) {
  // 10 CVODE steps cannot cover an output interval of 50 at tight tolerance.
  const std::string out = Path("fail");
  ASSERT_EQ(::mkdir(out.c_str(), 0755), 0);
  WriteFile(out + "/trajectory.tsv", "old\n");
  const Result r = Run({"--integrator", "cvode", "--xdot0", "0.125", "--max_steps", "10", "--dt",
                        "50", "--t_end", "100", "--out", out});
  EXPECT_EQ(r.code, 1);
  const auto lines = r.err_lines();
  ASSERT_EQ(lines.size(), 1u) << r.err;
  EXPECT_TRUE(Contains(lines[0], "at t = "));
  EXPECT_TRUE(Contains(lines[0], "slip-below"));
  // The rows so far, marked partial with where it stopped (as every app).
  const std::string data = Traj(out);
  EXPECT_TRUE(Contains(data, "# status: partial (")) << data;
  EXPECT_TRUE(Contains(data, "at t = ")) << data;
  EXPECT_TRUE(Contains(data, "\n0\t")) << data;  // the first row, at t = 0
}

TEST_F(SimulateApp, TaylorFailureWritesThePartialTrajectory) {
  // x' = 1e200: the cubic law's Taylor coefficients overflow at once.
  const std::string out = Path("fail");
  ASSERT_EQ(::mkdir(out.c_str(), 0755), 0);
  WriteFile(out + "/trajectory.tsv", "old\n");
  const Result r = Run({"--xdot0", "1e200", "--t_end", "10", "--out", out});
  EXPECT_EQ(r.code, 1);
  const auto lines = r.err_lines();
  ASSERT_EQ(lines.size(), 1u) << r.err;
  EXPECT_TRUE(Contains(lines[0], "non-finite Taylor coefficients")) << lines[0];
  EXPECT_TRUE(Contains(lines[0], "slip-above")) << lines[0];
  const std::string data = Traj(out);
  EXPECT_TRUE(Contains(data, "# status: partial (")) << data;
  EXPECT_FALSE(Contains(stickslip::testing_util::DataLines(data), "nan")) << data;
  EXPECT_FALSE(Contains(stickslip::testing_util::DataLines(data), "inf")) << data;
}

// Issue 15, item 16: starts within rounding (or 1e-8) of the belt speed.
TEST_F(SimulateApp, StartsNextToTheBeltSpeedSucceed) {
  for (const char* xdot0 : {"0.25000000000000006", "0.24999999", "0.24999999999999997"}) {
    for (const char* in : {"taylor", "cvode"}) {
      const Result r =
          Run({"--integrator", in, "--xdot0", xdot0, "--t_end", "20", "--out", Path("a")});
      EXPECT_EQ(r.code, 0) << in << " --xdot0 " << xdot0 << ": " << r.err;
    }
  }
}

// Issue 15, item 17: --t_end 1e10 reaches 1e10 (it stopped at 1e9 and said
// nothing). Above the Hopf point the run settles on steady sliding.
TEST_F(SimulateApp, RunsToTEndPastOneBillion) {
  const std::string out = Path("long");
  const Result r = Run({"--v", "0.45", "--t_end", "1e10", "--dt", "1e8", "--out", out});
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string text = Traj(out);
  const size_t last = text.rfind('\n', text.size() - 2);
  ASSERT_NE(last, std::string::npos);
  EXPECT_EQ(std::stod(text.substr(last + 1)), 1e10) << text.substr(last + 1);
}

TEST_F(SimulateApp, UnknownIntegratorIsRefused) {
  const Result r = Run({"--integrator", "rk4", "--out", Path("a")});
  EXPECT_EQ(r.code, 2);
  EXPECT_TRUE(Contains(r.err, "rk4")) << r.err;
  EXPECT_TRUE(Contains(r.err, "--integrator")) << r.err;
}

TEST_F(SimulateApp, NoTemporaryFilesLeftBehind) {
  const Result r = Run({"--t_end", "2", "--out", Path("a")});
  ASSERT_EQ(r.code, 0) << r.err;
  DIR* d = ::opendir(dir_.c_str());
  ASSERT_NE(d, nullptr);
  std::vector<std::string> names;
  while (const dirent* e = ::readdir(d)) names.push_back(e->d_name);
  ::closedir(d);
  for (const auto& name : names) EXPECT_FALSE(Contains(name, ".tmp-")) << name;
}

}  // namespace
