// End-to-end regression tests of the apps' reliability promises
// (docs/reliability.md): what is refused before the
// run, full disks, closed or failing stdout, signals and time limits in every
// phase, study files that are not text, and a missing gnuplot. Each test
// names the item it guards.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstdlib>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "app_test_util.hpp"
#include "cli/gnuplot.hpp"

namespace {

const std::string kContinue = STICKSLIP_BIN_DIR "/ss_continue";
const std::string kSimulate = STICKSLIP_BIN_DIR "/ss_simulate";

using stickslip::cli::PngError;
using stickslip::testing_util::Contains;
using stickslip::testing_util::Exists;
using stickslip::testing_util::Launch;
using stickslip::testing_util::Listing;
using stickslip::testing_util::Outcome;
using stickslip::testing_util::ReadFile;
using stickslip::testing_util::RunChild;
using stickslip::testing_util::WallBound;
using stickslip::testing_util::WriteFile;

using stickslip::testing_util::HaveGnuplot;

class Reliability : public stickslip::testing_util::AppTest {
 protected:
  void SetUp() override {
    AppTest::SetUp();
    ASSERT_EQ(::mkdir(Path("w").c_str(), 0777), 0);
  }
  std::string Path(const std::string& name) const { return dir_ + "/" + name; }
  // Runs app; stdout and stderr land in out_ and err_ unless l says otherwise.
  Outcome Run(const std::string& app, const std::vector<std::string>& args, Launch l = {}) {
    if (l.out_path == "/dev/null" && !l.closed_stdout) l.out_path = Path("stdout.txt");
    l.err_path = Path("stderr.txt");
    const Outcome r = RunChild(app, args, l);
    out_ = ReadFile(Path("stdout.txt"));
    err_ = ReadFile(Path("stderr.txt"));
    EXPECT_FALSE(r.timed_out) << app << ": still running after " << l.timeout << " s";
    EXPECT_EQ(r.signal, 0) << app << ": killed by signal " << r.signal << "; " << err_;
    return r;
  }
  // Expects exit 2 naming `part`, and the work directory as it was.
  void ExpectRefused(const std::string& app, const std::vector<std::string>& args,
                     const std::string& part) {
    const std::set<std::string> before = Listing(Path("w"));
    const Outcome r = Run(app, args, Launch{});
    EXPECT_EQ(r.code, 2) << err_;
    EXPECT_TRUE(Contains(err_, part));
    EXPECT_EQ(Listing(Path("w")), before);
  }
};

// Item 1: only regular files or new names are written; a symlink is refused.
TEST_F(Reliability, SimulateRefusesToReplaceWhatIsNotARegularFile) {
  const std::string fifo = Path("w/trajectory.tsv"), link = Path("w/trajectory.gp");
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0644), 0);
  ExpectRefused(kSimulate, {"--out", Path("w")}, "not a regular file");
  struct stat st;
  ASSERT_EQ(::lstat(fifo.c_str(), &st), 0);
  EXPECT_TRUE(S_ISFIFO(st.st_mode));
  ASSERT_EQ(::unlink(fifo.c_str()), 0);
  ASSERT_EQ(::symlink(Path("nowhere").c_str(), link.c_str()), 0);
  ExpectRefused(kSimulate, {"--out", Path("w")}, "symbolic link");
  ASSERT_EQ(::lstat(link.c_str(), &st), 0);
  EXPECT_TRUE(S_ISLNK(st.st_mode));
  if (::stat("/dev/null", &st) == 0 && S_ISCHR(st.st_mode)) {
    ExpectRefused(kSimulate, {"--out", "/dev/null"}, "/dev/null");
    ASSERT_EQ(::stat("/dev/null", &st), 0);
    EXPECT_TRUE(S_ISCHR(st.st_mode));
  }
}

// Item 2: a figure cut short (file size limit standing in for a full disk)
// is caught before the rename: exit 1, the old files kept, no stray file.
TEST_F(Reliability, FigureCutShortKeepsTheOldFiles) {
  if (!HaveGnuplot()) GTEST_SKIP() << "no gnuplot";
  for (const std::string name : {"trajectory.tsv", "trajectory.gp", "trajectory.png"})
    WriteFile(Path("w/" + name), "old\n");
  Launch l;
  l.fsize_limit = 20000;  // the TSV (about 5 kB) fits, the PNG (about 40 kB) does not
  const Outcome r = Run(kSimulate, {"--t_end", "1", "--out", Path("w")}, l);
  EXPECT_EQ(r.code, 1) << err_;
  EXPECT_TRUE(Contains(err_, "nothing replaced"));
  for (const std::string name : {"trajectory.tsv", "trajectory.gp", "trajectory.png"})
    EXPECT_EQ(ReadFile(Path("w/" + name)), "old\n") << name;
  EXPECT_EQ(Listing(Path("w")),
            (std::set<std::string>{"trajectory.tsv", "trajectory.gp", "trajectory.png"}));
}

// Item 2 for ss_continue: the same with its set of four figures; an old,
// whole set stays as it was.
TEST_F(Reliability, ContinueFiguresCutShortKeepTheOldSet) {
  if (!HaveGnuplot()) GTEST_SKIP() << "no gnuplot";
  const std::vector<std::string> args = {"--no_estimates", "--out", Path("w")};
  ASSERT_EQ(Run(kContinue, args, Launch{}).code, 0) << err_;
  std::map<std::string, std::string> before;
  for (const auto& n : Listing(Path("w"))) before[n] = ReadFile(Path("w/" + n));
  Launch l;
  // branch.tsv (about 19 kB at max_step 0.02) fits, no figure (36 to 52 kB) does.
  l.fsize_limit = 32000;
  const Outcome r = Run(
      kContinue, {"--beta", "0.06", "--max_step", "0.02", "--no_estimates", "--out", Path("w")}, l);
  EXPECT_EQ(r.code, 1) << err_;
  EXPECT_TRUE(Contains(err_, "nothing replaced"));
  std::map<std::string, std::string> after;
  for (const auto& n : Listing(Path("w"))) after[n] = ReadFile(Path("w/" + n));
  EXPECT_TRUE(after == before) << "the old set changed";
}

// Item 4: output-path problems are found before the run.
TEST_F(Reliability, OutputPathProblemsAreFoundBeforeTheRun) {
  ASSERT_EQ(::mkdir(Path("w/branch.tsv").c_str(), 0777), 0);
  ExpectRefused(kContinue, {"--out", Path("w")}, "a directory stands there");
  ExpectRefused(kSimulate, {"--out", Path("w/" + std::string(256, 'n'))}, "File name too long");
  ExpectRefused(kSimulate, {"--out", Path("w/a\nb")}, "control character");
}

// Item 5: a valid range without a periodic orbit gives valid figures, exit 0.
TEST_F(Reliability, RangeWithoutPeriodicOrbitDrawsValidFigures) {
  if (!HaveGnuplot()) GTEST_SKIP() << "no gnuplot";
  const Outcome r = Run(kContinue, {"--from", "0.45", "--to", "0.5", "--out", Path("w")});
  ASSERT_EQ(r.code, 0) << err_;
  for (const std::string f : {"bifurcation_x.png", "bifurcation_xdot.png", "period.png",
                              "multiplier.png", "estimates.png"})
    EXPECT_EQ(PngError(Path("w/" + f)), "") << f;
}

// Items 6 and 7: scales that over- or underflow are refused at validation,
// naming the value, before the output directory is made.
TEST_F(Reliability, ModelScalesThatOverflowAreRefused) {
  const std::string out = Path("w/new");
  ExpectRefused(kContinue, {"--v_m", "1e-103", "--out", out}, "v_m = 1e-103");
  ExpectRefused(kContinue, {"--mu_s", "1e300", "--mu_m", "1e299", "--out", out}, "mu_s = 1e+300");
  ExpectRefused(kContinue, {"--law", "stribeck", "--v_s", "1e-310", "--out", out}, "v_s = 1e-310");
  ExpectRefused(kSimulate, {"--v_m", "1e-100", "--out", out}, "v_m = 1e-100");
}

// Item 8: a value of a parameter the law does not use is still validated.
TEST_F(Reliability, ParametersOfAnotherLawAreValidated) {
  ExpectRefused(kContinue, {"--v_s", "-1", "--out", Path("w")}, "v_s = -1");
  ExpectRefused(kSimulate, {"--delta", "-2", "--out", Path("w")}, "delta = -2");
}

// Item 9: a cancelled run names where the branch stopped, which is the last
// periodic row of branch.tsv.
TEST_F(Reliability, CancelledRunNamesWhereTheBranchStopped) {
  // CVODE: a run long enough to be cut at any load (Taylor ends it in 0.1 s).
  const Outcome r = Run(kContinue, {"--integrator", "cvode", "--max_step", "5e-5", "--max_time",
                                    "0.5", "--no_plots", "--no_estimates", "--out", Path("w")});
  ASSERT_EQ(r.code, 1) << err_;
  std::istringstream rows(ReadFile(Path("w/branch.tsv")));
  std::string line, last;
  bool header = true;  // the first line without '#' names the columns
  while (std::getline(rows, line)) {
    if (line.empty() || line[0] == '#') continue;
    if (!header && line.find("\tequilibrium\t") == std::string::npos)
      last = line.substr(0, line.find('\t'));
    header = false;
  }
  if (last.empty())  // a heavily loaded machine: cut before the first orbit, and saying so
    EXPECT_TRUE(Contains(err_, "cancelled before the first periodic orbit"));
  else
    EXPECT_TRUE(Contains(err_, "cancelled at v = " + last + " "));
  EXPECT_FALSE(Contains(err_, "cancelled at v = 0.5 "));
}

// Items 10 and 15: a closed or failing stdout does not kill the run; the
// files are written and the failure is reported (exit 1).
TEST_F(Reliability, StdoutFailuresAreReportedAfterTheFilesAreWritten) {
  Launch closed;
  closed.closed_stdout = true;
  Outcome r = Run(kContinue, {"--no_plots", "--out", Path("w")}, closed);
  EXPECT_EQ(r.code, 1) << err_;
  EXPECT_TRUE(Contains(err_, "cannot write to standard output"));
  EXPECT_TRUE(Contains(ReadFile(Path("w/branch.tsv")), "status: complete"));
  if (!Exists("/dev/full")) return;
  Launch full;
  full.out_path = "/dev/full";
  r = Run(kContinue, {"--help"}, full);
  EXPECT_EQ(r.code, 1);
  EXPECT_TRUE(Contains(err_, "cannot write to standard output"));
  r = Run(kSimulate, {"--help"}, full);
  EXPECT_EQ(r.code, 1);
}

// Items 11 and 12: ss_simulate has --max_time and SIGINT handling, writes
// the trajectory so far marked partial when stopped, and prints plain progress lines off a
// terminal.
TEST_F(Reliability, SimulateStopsOnTimeLimitAndSignal) {
  const std::vector<std::string> slow = {"--v_m", "1e-6", "--xdot0", "0",     "--t_end",
                                         "1e4",   "--dt", "0.01",    "--out", Path("w")};
  std::vector<std::string> timed = slow;
  timed.insert(timed.end(), {"--max_time", "2.5"});
  const WallBound bound;
  Outcome r = Run(kSimulate, timed, Launch{});
  EXPECT_EQ(r.code, 1) << err_;
  EXPECT_LT(r.seconds, bound.Of(20.0));
  EXPECT_TRUE(Contains(err_, "time limit of 2.5 s"));
  EXPECT_TRUE(Contains(err_, "ss_simulate: t = "));  // a progress line
  EXPECT_FALSE(Contains(err_, "ETA"));               // plain: stderr is a file
  Launch sigint;
  sigint.signal = SIGINT;
  sigint.signal_after = 0.5;
  r = Run(kSimulate, slow, sigint);
  EXPECT_EQ(r.code, 1) << err_;
  EXPECT_TRUE(Contains(err_, "SIGINT"));
  // The trajectory so far, marked partial (the exit-code table of every app).
  EXPECT_EQ(Listing(Path("w")), std::set<std::string>{"trajectory.tsv"});
  EXPECT_TRUE(Contains(ReadFile(Path("w/trajectory.tsv")), "# status: partial (cancelled"));
}

// Item 12 and issue 14: a slow phase with nothing else to report (the grid
// search of --mu_s 1e6 --mu_m 1) still prints a line, and --max_time ends it.
TEST_F(Reliability, SlowGridSearchShowsProgressAndStopsOnTime) {
  const WallBound bound;
  const Outcome r = Run(kContinue, {"--mu_s", "1e6", "--mu_m", "1", "--max_time", "3", "--no_plots",
                                    "--out", Path("w")});
  EXPECT_EQ(r.code, 1) << err_;
  EXPECT_LT(r.seconds, bound.Of(20.0));
  EXPECT_TRUE(Contains(err_, "ss_continue: still continuing (searching for a periodic orbit)"));
  EXPECT_TRUE(Contains(ReadFile(Path("w/branch.tsv")), "status: partial (cancelled)"));
}

// Issue 14: on a terminal, progress lines carry the rate and an ETA
// (util-linux `script` gives the app a pseudo-terminal).
TEST_F(Reliability, ProgressOnATerminalHasRateAndEta) {
  if (std::system("script --version >/dev/null 2>&1") != 0) GTEST_SKIP() << "no script(1)";
  const std::string cmd =
      "script -qec '" + kContinue +
      " --integrator cvode --max_step 1e-4 --max_time 2.5 --no_plots --no_estimates --out " +
      Path("w") + " >/dev/null' /dev/null > " + Path("tty.txt") + " 2>&1";
  ASSERT_NE(std::system(cmd.c_str()), -1);
  const std::string tty = ReadFile(Path("tty.txt"));
  EXPECT_TRUE(Contains(tty, "points/s"));
  EXPECT_TRUE(Contains(tty, "ETA"));
}

// Item 13: the memory bound on --max_step is stated up front.
TEST_F(Reliability, MaxStepBeyondTheMemoryBoundIsRefused) {
  ExpectRefused(kContinue, {"--max_step", "1.1e-7", "--out", Path("w")}, "max_step");
  ExpectRefused(kContinue, {"--max_step", "1e-6", "--out", Path("w")}, "memory bound");
}

// Items 14 and 20: study files are regular text files of bounded size.
TEST_F(Reliability, StudyFilesMustBeBoundedRegularText) {
  const std::string fifo = Path("study.fifo"), big = Path("big.ini"), nul = Path("nul.ini");
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0644), 0);
  WriteFile(big, std::string(2 << 20, '#'));
  WriteFile(nul, std::string("beta = 0.1\nv = 0.2\0junk\n", 24));
  ExpectRefused(kContinue, {"--study", fifo, "--out", Path("w")}, "not a regular file");
  ExpectRefused(kContinue, {"--study", big, "--out", Path("w")}, "more than");
  ExpectRefused(kSimulate, {"--study", nul, "--out", Path("w")}, "nul.ini:2: a NUL byte");
  if (Exists("/dev/zero"))
    ExpectRefused(kSimulate, {"--study", "/dev/zero", "--out", Path("w")}, "not a regular file");
}

// Issue 14: a missing gnuplot exits 3; the data files and script are written.
TEST_F(Reliability, MissingGnuplotExitsThreeWithTheData) {
  Launch l;
  l.path_env = "/nonexistent";
  Outcome r = Run(kContinue, {"--out", Path("w")}, l);
  EXPECT_EQ(r.code, 3) << err_;
  EXPECT_TRUE(Contains(err_, "gnuplot not found"));
  EXPECT_EQ(Listing(Path("w")),
            (std::set<std::string>{"branch.tsv", "special_points.tsv", "bifurcation.gp"}));
  r = Run(kSimulate, {"--t_end", "1", "--out", Path("w")}, l);
  EXPECT_EQ(r.code, 3) << err_;
  EXPECT_TRUE(Exists(Path("w/trajectory.tsv")));
  EXPECT_TRUE(Exists(Path("w/trajectory.gp")));
  EXPECT_FALSE(Exists(Path("w/trajectory.png")));
}

}  // namespace
