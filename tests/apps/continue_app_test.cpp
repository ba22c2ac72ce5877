// End-to-end tests of the built ss_continue: every bad input is rejected with
// exit code 2, exactly one line on stderr naming the offending option or value,
// and nothing created or changed in --out; the seed study gives the expected
// branch; SIGINT and --max_time leave a whole, partial branch.tsv (exit 1);
// hard ranges (far past the Hopf point, v -> 0) finish instead of hanging.
//
// The app runs in a child process (fork + exec) with stdout and stderr sent to
// files, under a hard time limit: a child still running at the limit is killed
// and the test fails, so a hang costs one test, not the whole suite.
#include <dirent.h>
#include <fcntl.h>
#include <grp.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <stdlib.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "app_test_util.hpp"
#include "test_paths.hpp"

namespace {

const std::string kContinueApp = STICKSLIP_BIN_DIR "/ss_continue";

using stickslip::testing_util::Contains;
using stickslip::testing_util::Exists;
using stickslip::testing_util::Listing;
using stickslip::testing_util::ReadFile;
using stickslip::testing_util::ReadTsv;
using stickslip::testing_util::Tsv;
using stickslip::testing_util::WallBound;
using stickslip::testing_util::WriteFile;

std::vector<std::string> Lines(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream is(text);
  for (std::string l; std::getline(is, l);) lines.push_back(l);
  return lines;
}

struct ContinueResult {
  int code = -1;           // exit status, -1 if killed by a signal
  int signal = 0;          // the signal that ended it, if any
  bool timed_out = false;  // killed at the time limit
  double seconds = 0;
  std::string out, err;
  std::string shown;  // the command, for messages
};

// Runs kContinueApp with args in a child process (app_test_util.hpp's RunChild);
// stdout / stderr go to out_path / err_path. With sigint_after >= 0, SIGINT
// is sent that many seconds after the child has installed its SIGINT handler.
// A child still running after timeout seconds is killed (SIGKILL).
// With run_as >= 0 (only as root), the child drops to that user id first.
ContinueResult Exec(const std::vector<std::string>& args, const std::string& out_path,
                    const std::string& err_path, double timeout, double sigint_after = -1,
                    int run_as = -1) {
  ContinueResult r;
  r.shown = "ss_continue";
  for (const auto& a : args) r.shown += " " + a;
  stickslip::testing_util::Launch l;
  l.out_path = out_path, l.err_path = err_path, l.timeout = timeout, l.run_as = run_as;
  if (sigint_after >= 0) l.signal = SIGINT, l.signal_after = sigint_after;
  l.signal_when_caught = true;
  const auto o = stickslip::testing_util::RunChild(kContinueApp, args, l);
  r.code = o.code, r.signal = o.signal, r.timed_out = o.timed_out, r.seconds = o.seconds;
  r.out = ReadFile(out_path);
  r.err = ReadFile(err_path);
  return r;
}

// The sentinel a rejected run must leave alone.
const char kSentinel[] = "# v\tkind\nsentinel: this file must not change\n";

// A fresh directory per test, removed afterwards. Layout: dir_/out is the
// --out directory (pre-filled with a sentinel branch.tsv for rejections),
// dir_/stdout.txt and dir_/stderr.txt the captured streams.
class ContinueApp : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_TRUE(Exists(kContinueApp)) << kContinueApp << " not built";
    std::string tmpl = ::testing::TempDir() + "ss_continue_test_XXXXXX";
    ASSERT_NE(::mkdtemp(tmpl.data()), nullptr);
    dir_ = tmpl;
  }
  void TearDown() override {
    if (dir_.empty()) return;
    // Undo any chmod so the tree can be removed.
    const std::string cmd = "chmod -R u+rwx '" + dir_ + "' 2>/dev/null; rm -rf '" + dir_ + "'";
    EXPECT_EQ(std::system(cmd.c_str()), 0);
  }

  std::string Path(const std::string& name) const { return dir_ + "/" + name; }
  std::string OutDir() const { return Path("out"); }

  ContinueResult Run(const std::vector<std::string>& args, double timeout = 120,
                     double sigint_after = -1) {
    ContinueResult r = Exec(args, Path("stdout.txt"), Path("stderr.txt"), timeout, sigint_after);
    EXPECT_FALSE(r.timed_out) << r.shown << ": still running after " << timeout << " s";
    return r;
  }

  // A study file in the test directory.
  std::string Study(const std::string& name, const std::string& text) {
    const std::string path = Path(name);
    WriteFile(path, text);
    return path;
  }

  // Expects a rejection: exit 2, one stderr line "ss_continue: error: ..."
  // containing every part, nothing on stdout, and --out untouched (it holds
  // only the sentinel branch.tsv, byte-identical).
  void ExpectRejected(std::vector<std::string> args, const std::vector<std::string>& parts) {
    const std::string out = OutDir();
    ASSERT_EQ(std::system(("rm -rf '" + out + "'").c_str()), 0);
    ASSERT_EQ(::mkdir(out.c_str(), 0777), 0);
    WriteFile(out + "/branch.tsv", kSentinel);
    args.push_back("--out");
    args.push_back(out);
    args.push_back("--no_plots");
    const ContinueResult r = Run(args, 60);
    EXPECT_EQ(r.code, 2) << r.shown << "\n" << r.err;
    const auto lines = Lines(r.err);
    ASSERT_EQ(lines.size(), 1u) << r.shown << "\n" << r.err;
    EXPECT_EQ(lines[0].rfind("ss_continue: error: ", 0), 0u) << r.shown << "\n" << lines[0];
    for (const auto& part : parts) EXPECT_TRUE(Contains(lines[0], part)) << r.shown;
    EXPECT_EQ(r.out, "") << r.shown;
    EXPECT_EQ(Listing(out), std::set<std::string>{"branch.tsv"}) << r.shown;
    EXPECT_EQ(ReadFile(out + "/branch.tsv"), kSentinel) << r.shown;
  }

  std::string dir_;
};

// branch.tsv split into header columns, comment lines and data rows.
struct Branch : Tsv {
  std::string first_line;
};

Branch ReadBranch(const std::string& text) {
  Branch b;
  static_cast<Tsv&>(b) = ReadTsv(text);
  b.first_line = text.substr(0, text.find('\n'));
  return b;
}

// A partial branch.tsv: whole (every row has the header's column count, the
// file ends with a newline) and marked "# status: partial (<why>)".
void ExpectWholePartialBranch(const std::string& path, const std::string& why) {
  ASSERT_TRUE(Exists(path)) << path;
  const std::string text = ReadFile(path);
  ASSERT_FALSE(text.empty());
  EXPECT_EQ(text.back(), '\n');
  const Branch b = ReadBranch(text);
  ASSERT_GE(b.columns.size(), 12u) << b.first_line;
  EXPECT_EQ(b.columns[1], "kind");
  for (size_t i = 0; i < b.rows.size(); ++i)
    EXPECT_EQ(b.rows[i].size(), b.columns.size()) << "row " << i;
  bool marked = false;
  for (const auto& c : b.comments)
    marked = marked || c.rfind("# status: partial (" + why + ")", 0) == 0;
  EXPECT_TRUE(marked) << "no '# status: partial (" << why << ")' line in " << path;
}

// ---------------------------------------------------------------------------
// Bad input: exit 2, one line, nothing written.

TEST_F(ContinueApp, VersionAndShortHelp) {
  const ContinueResult v = Run({"--version"});
  ASSERT_EQ(v.code, 0) << v.err;
  EXPECT_EQ(v.out.rfind("ss_continue 0.", 0), 0u) << v.out;
  const ContinueResult h = Run({"-h"});
  ASSERT_EQ(h.code, 0) << h.err;
  EXPECT_TRUE(Contains(h.out, "--version"));
}

// --param mu_s without a range used to fail (0.05 < mu_m); it takes mu_s's own range.
TEST_F(ContinueApp, ParamMuSRunsOnItsDefaultRange) {
  const std::string out = OutDir();
  const ContinueResult r = Run({"--param", "mu_s", "--out", out, "--no_plots", "--no_estimates"});
  ASSERT_EQ(r.code, 0) << r.err;
  const Tsv b = ReadTsv(ReadFile(out + "/branch.tsv"));
  EXPECT_EQ(b.meta.at("from"), "0.3");  // 1.2 mu_m
  EXPECT_EQ(b.meta.at("to"), "0.8");    // 2 mu_s
  EXPECT_EQ(b.meta.at("mu_s"), "continued");
}

// Physical inputs, M = 2 kg, K = 8 N/m, g = 9.81: L = 2.4525 m, t0 = 0.5 s, and
// speeds scale by L / t0 = 4.905 m/s. --param belt_speed finds HB at the closed
// form sqrt((k1 - 2 beta) / (3 k3)) (seed 3.16) times L / t0.
TEST_F(ContinueApp, BeltSpeedContinuesInPhysicalUnits) {
  const std::string out = OutDir();
  const ContinueResult r = Run({"--mass",    "2",      "--stiffness",  "8",
                                "--damping", "0.4",    "--belt_speed", "1",
                                "--speed_m", "2.4525", "--param",      "belt_speed",
                                "--from",    "1.5",    "--to",         "2.4525",
                                "--out",     out,      "--no_plots",   "--no_estimates"});
  ASSERT_EQ(r.code, 0) << r.err;
  const Tsv b = ReadTsv(ReadFile(out + "/branch.tsv"));
  EXPECT_EQ(b.meta.at("L"), "2.4525 m (M g / K)");
  EXPECT_EQ(b.meta.at("t0"), "0.5 s (sqrt(M / K))");
  const int v = b.Column("v"), speed = b.Column("belt_speed"), x = b.Column("x_max"),
            x_m = b.Column("x_max_m"), period = b.Column("period"), period_s = b.Column("period_s");
  ASSERT_TRUE(v >= 0 && speed >= 0 && x >= 0 && x_m >= 0 && period >= 0 && period_s >= 0);
  ASSERT_FALSE(b.rows.empty());
  EXPECT_NEAR(std::stod(b.rows.front()[speed]), 1.5, 1e-12);
  EXPECT_NEAR(std::stod(b.rows.back()[speed]), 2.4525, 1e-12);
  for (const auto& row : b.rows) {
    EXPECT_NEAR(std::stod(row[speed]), std::stod(row[v]) * 4.905, 1e-12);
    EXPECT_NEAR(std::stod(row[x_m]), std::stod(row[x]) * 2.4525, 1e-12);
    if (!row[period].empty()) {  // empty on steady sliding
      EXPECT_NEAR(std::stod(row[period_s]), std::stod(row[period]) * 0.5, 1e-12);
    }
  }
  const Tsv sp = ReadTsv(ReadFile(out + "/special_points.tsv"));
  const double beta = 0.4 / (2 * std::sqrt(8.0 * 2.0)), k1 = 0.45, k3 = 0.6;
  int hb = 0;
  for (const auto& row : sp.rows)
    if (row.at(0) == "HB") {
      ++hb;
      EXPECT_NEAR(std::stod(row.at(1)), std::sqrt((k1 - 2 * beta) / (3 * k3)), 1e-9);
      EXPECT_NEAR(std::stod(row.at(sp.Column("belt_speed"))),
                  std::sqrt((k1 - 2 * beta) / (3 * k3)) * 4.905, 1e-8);
    }
  EXPECT_EQ(hb, 1);
}

TEST_F(ContinueApp, BeltSpeedWithoutPhysicalInputsExits2) {
  ExpectRejected({"--param", "belt_speed"}, {"--param belt_speed", "physical"});
}

TEST_F(ContinueApp, UnknownOptionExits2) { ExpectRejected({"--gamma", "1"}, {"--gamma"}); }

TEST_F(ContinueApp, PositionalArgumentExits2) {
  ExpectRejected({"studies/seed.ini"}, {"studies/seed.ini"});
}

TEST_F(ContinueApp, UnknownParamExits2) {
  ExpectRejected({"--param", "gamma"}, {"--param", "gamma"});
}

TEST_F(ContinueApp, ParamNotOfTheLawExits2) {
  ExpectRejected({"--param", "delta", "--from", "1", "--to", "2"}, {"--param", "delta", "cubic"});
  ExpectRejected({"--law", "leine", "--param", "mu_m", "--from", "0.1", "--to", "0.2"},
                 {"mu_m", "leine"});
}

TEST_F(ContinueApp, UnknownLawExits2) { ExpectRejected({"--law", "viscous"}, {"viscous"}); }

TEST_F(ContinueApp, NonNumbersExit2) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"--beta", "abc"},       {"--beta", "1.2x"},   {"--v", "nan"},      {"--mu_s", "inf"},
      {"--from", "-inf"},      {"--to", "NaN"},      {"--from", "1e400"}, {"--to", ""},
      {"--max_step", "0.01 "}, {"--max_time", "1s"}, {"--rtol", "0x"}};
  for (const auto& [opt, value] : cases) {
    SCOPED_TRACE(opt + " '" + value + "'");
    ExpectRejected({opt, value}, {opt, "'" + value + "'"});
  }
}

TEST_F(ContinueApp, EmptyRangeExits2) {
  ExpectRejected({"--from", "0.3", "--to", "0.3"}, {"from = to = 0.3"});
}

TEST_F(ContinueApp, RangeEndOutsideTheModelExits2) {
  // v = -0.1 at the start of the range: the model there is invalid.
  ExpectRejected({"--param", "v", "--from", "-0.1", "--to", "0.5"}, {"v = -0.1", "> 0"});
  // mu_s = 0.2 < mu_m = 0.25 at the end of the range.
  ExpectRejected({"--param", "mu_s", "--from", "0.4", "--to", "0.2"}, {"mu_s = 0.2", "mu_m"});
}

TEST_F(ContinueApp, MissingStudyFileExits2) {
  const std::string path = Path("no_such_study.ini");
  ExpectRejected({"--study", path}, {path, "No such file"});
}

TEST_F(ContinueApp, StudyDirectoryExits2) {
  ExpectRejected({"--study", kStudies}, {kStudies, "directory"});
}

TEST_F(ContinueApp, UnreadableStudyFileExits2) {
  const std::string path = Study("locked.ini", "beta = 0.05\n");
  ASSERT_EQ(::chmod(path.c_str(), 0), 0);
  FILE* f = std::fopen(path.c_str(), "r");
  if (f == nullptr) {
    ExpectRejected({"--study", path}, {path, "cannot read", "Permission denied"});
    return;
  }
  std::fclose(f);
  // Root reads a mode-000 file. Run the app as nobody instead, if possible.
  constexpr int kNobody = 65534;
  if (::geteuid() != 0)
    GTEST_SKIP() << "chmod 000 does not block reading here: the unreadable-file case cannot be "
                    "produced";
  ASSERT_EQ(::chmod(dir_.c_str(), 0755), 0);
  const std::string out = OutDir();
  ASSERT_EQ(::mkdir(out.c_str(), 0777), 0);
  ASSERT_EQ(::chmod(out.c_str(), 0777), 0);
  WriteFile(out + "/branch.tsv", kSentinel);
  const ContinueResult r = Exec({"--study", path, "--out", out, "--no_plots"}, Path("stdout.txt"),
                                Path("stderr.txt"), 60, -1, kNobody);
  if (r.code == 125 || r.code == 126 || r.code == 127)
    GTEST_SKIP() << "running as root, where chmod 000 does not block reads, and the app cannot "
                    "be run as nobody (exit "
                 << r.code << "): the unreadable-file case cannot be produced";
  EXPECT_EQ(r.code, 2) << r.err;
  const auto lines = Lines(r.err);
  ASSERT_EQ(lines.size(), 1u) << r.err;
  EXPECT_TRUE(Contains(lines[0], "ss_continue: error: cannot read study file '" + path + "'"));
  EXPECT_TRUE(Contains(lines[0], "Permission denied"));
  EXPECT_EQ(Listing(out), std::set<std::string>{"branch.tsv"});
  EXPECT_EQ(ReadFile(out + "/branch.tsv"), kSentinel);
}

TEST_F(ContinueApp, MalformedStudyLineNamesTheLine) {
  const std::string path = Study("bad.ini", "# a study\nbeta = 0.05\nv 0.25\n");
  ExpectRejected({"--study", path}, {path + ":3", "key = value"});
}

TEST_F(ContinueApp, UnknownStudyKeyExits2) {
  const std::string path = Study("bad.ini", "beta = 0.05\n\ngamma = 1\n");
  ExpectRejected({"--study", path}, {path + ":3", "unknown key 'gamma'"});
}

TEST_F(ContinueApp, UnknownStudySectionExits2) {
  const std::string path = Study("bad.ini", "beta = 0.05\n[plot]\nx = 1\n");
  ExpectRejected({"--study", path}, {path + ":2", "[plot]"});
}

TEST_F(ContinueApp, RepeatedStudyKeyExits2) {
  const std::string path = Study("bad.ini", "beta = 0.05\nbeta = 0.06\n");
  ExpectRejected({"--study", path}, {path + ":2", "beta"});
}

TEST_F(ContinueApp, BadNumberInStudyNamesTheLine) {
  const std::string path = Study("bad.ini", "law = cubic\n[continue]\nfrom = 0.1.2\n");
  ExpectRejected({"--study", path}, {"from", path + ":3", "'0.1.2'"});
}

TEST_F(ContinueApp, InvalidModelInStudyNamesTheLine) {
  const std::string path = Study("bad.ini", "beta = 0.05\nmu_m = 0.5\n");
  ExpectRejected({"--study", path}, {"mu_m = 0.5", "mu_s = 0.4", path + ":2"});
}

TEST_F(ContinueApp, InvalidModelsExit2) {
  struct Case {
    std::vector<std::string> args;
    std::vector<std::string> parts;
  };
  const std::vector<Case> cases = {
      {{"--mu_m", "0.4"}, {"mu_m = 0.4", "mu_s = 0.4", "--mu_m"}},
      {{"--mu_m", "0.5"}, {"mu_m = 0.5", "--mu_m"}},
      {{"--v_m", "0"}, {"v_m = 0", "--v_m"}},
      {{"--v_m", "-0.5"}, {"v_m = -0.5", "--v_m"}},
      // v is not the continued parameter here, so the given v must be valid.
      {{"--param", "beta", "--from", "0.01", "--to", "0.1", "--v", "0"}, {"v = 0", "--v"}},
      {{"--param", "mu_s", "--from", "0.3", "--to", "0.5", "--v", "-0.25"}, {"v = -0.25", "--v"}},
      {{"--beta", "-0.01"}, {"beta = -0.01", "--beta"}},
      {{"--law", "coulomb", "--mu_k", "0.4"}, {"mu_k = 0.4", "mu_s = 0.4", "--mu_k"}},
      {{"--law", "coulomb", "--mu_k", "0.6"}, {"mu_k = 0.6", "--mu_k"}},
      {{"--law", "stribeck", "--v_s", "0"}, {"v_s = 0", "--v_s"}},
      {{"--law", "leine", "--delta", "-1"}, {"delta = -1", "--delta"}},
      {{"--mu_s", "0"}, {"mu_s = 0", "--mu_s"}},
      // Issue 23, N10: a subnormal v_m overflowed k3 and was blamed on k5.
      {{"--v_m", "1e-310"}, {"v_m = 1e-310", "--v_m"}},
      // Issue 23, old #20: the continued parameter's given value is validated too.
      {{"--param", "v", "--v", "-1"}, {"v = -1", "--v", "continued"}},
      {{"--param", "v_m", "--from", "0.4", "--to", "0.6", "--v_m", "0"},
       {"v_m = 0", "--v_m", "continued"}},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.args[0] + " " + c.args[1]);
    ExpectRejected(c.args, c.parts);
  }
}

// Issue 23, N14: control characters in a value or a path are escaped in the
// message (\x1b, \x07, \n), never echoed raw.
TEST_F(ContinueApp, ControlCharactersInInputAreEscaped) {
  ExpectRejected({"--law", "cu\x1b[2Jbic"}, {"'cu\\x1b[2Jbic'", "--law"});
  ExpectRejected({"--beta", "0.1\x07"}, {"'0.1\\x07'", "--beta"});
  ExpectRejected({"--study", Path("no\x1b\nfile.ini")}, {"no\\x1b\\nfile.ini"});
  const ContinueResult r =
      Run({"--integrator", "tay\tlor\x7f", "--no_plots", "--out", OutDir()}, 60);
  EXPECT_EQ(r.code, 2);
  EXPECT_TRUE(Contains(r.err, "'tay\\tlor\\x7f'"));
  for (const char c : r.err.substr(0, r.err.size() - 1))
    EXPECT_FALSE(static_cast<unsigned char>(c) < 0x20 || c == 0x7f) << int(c) << " in " << r.err;
}

TEST_F(ContinueApp, PhysicalInputsMixedWithScaledExit2) {
  ExpectRejected({"--mass", "1", "--damping", "0.1", "--stiffness", "1", "--belt_speed", "0.25",
                  "--speed_m", "0.5", "--beta", "0.05"},
                 {"--beta", "physical"});
}

TEST_F(ContinueApp, ToleranceOutOfRangeExits2) {
  ExpectRejected({"--rtol", "1"}, {"rtol = 1", "--rtol"});
  ExpectRejected({"--atol", "0"}, {"atol = 0", "--atol"});
  ExpectRejected({"--method", "rk4"}, {"rk4", "--method"});
  ExpectRejected({"--max_steps", "5"}, {"max_steps = 5"});
}

TEST_F(ContinueApp, BadRunOptionsExit2) {
  ExpectRejected({"--max_step", "0.9"}, {"max_step = 0.9"});
  ExpectRejected({"--max_step", "0"}, {"max_step = 0"});
  ExpectRejected({"--max_time", "-1"}, {"'-1'", "--max_time"});
}

// The app has no --min_step: a --max_step at or below the internal min_step
// (1e-7) must be reported as a bad --max_step, not as "min_step = 1e-07 must
// be in (0, max_step)".
TEST_F(ContinueApp, TinyMaxStepNamesMaxStep) {
  ExpectRejected({"--max_step", "1e-7"}, {"max_step = 1e-07"});
}

// --out: a path under a regular file, a regular file, a system path.
TEST_F(ContinueApp, UnwritableOutExits2) {
  const std::string file = Path("regular");
  WriteFile(file, "a regular file\n");
  for (const std::string& out : {file + "/x", file}) {
    SCOPED_TRACE(out);
    const ContinueResult r = Run({"--out", out, "--no_plots"}, 60);
    EXPECT_EQ(r.code, 2) << r.err;
    const auto lines = Lines(r.err);
    ASSERT_EQ(lines.size(), 1u) << r.err;
    EXPECT_TRUE(Contains(lines[0], "ss_continue: error: "));
    EXPECT_TRUE(Contains(lines[0], "--out"));
    EXPECT_TRUE(Contains(lines[0], "'" + out + "'"));
    EXPECT_EQ(ReadFile(file), "a regular file\n");
    EXPECT_EQ(Listing(dir_), (std::set<std::string>{"regular", "stdout.txt", "stderr.txt"}));
  }
  if (Exists("/etc/passwd")) {
    const std::string before = ReadFile("/etc/passwd");
    const ContinueResult r = Run({"--out", "/etc/passwd/x", "--no_plots"}, 60);
    EXPECT_EQ(r.code, 2) << r.err;
    ASSERT_EQ(Lines(r.err).size(), 1u) << r.err;
    EXPECT_TRUE(Contains(r.err, "'/etc/passwd/x'"));
    EXPECT_EQ(ReadFile("/etc/passwd"), before);
  }
}

TEST_F(ContinueApp, ReadOnlyOutExits2) {
  const std::string out = OutDir();
  ASSERT_EQ(::mkdir(out.c_str(), 0555), 0);
  int run_as = -1;
  if (::access(out.c_str(), W_OK) == 0) {  // root: run the app as nobody
    if (::geteuid() != 0) GTEST_SKIP() << "a mode 0555 directory is writable here";
    run_as = 65534;
    ASSERT_EQ(::chmod(dir_.c_str(), 0755), 0);
  }
  const ContinueResult r =
      Exec({"--out", out, "--no_plots"}, Path("stdout.txt"), Path("stderr.txt"), 60, -1, run_as);
  if (run_as >= 0 && (r.code == 125 || r.code == 126 || r.code == 127))
    GTEST_SKIP() << "running as root, where mode 0555 does not block writes, and the app cannot "
                    "be run as nobody (exit "
                 << r.code << ")";
  EXPECT_EQ(r.code, 2) << r.err;
  ASSERT_EQ(Lines(r.err).size(), 1u) << r.err;
  EXPECT_TRUE(Contains(r.err, "--out"));
  EXPECT_TRUE(Contains(r.err, "not writable"));
  EXPECT_TRUE(Listing(out).empty());
}

// A rejected run must not even create a missing --out directory.
TEST_F(ContinueApp, RejectionCreatesNoOutDirectory) {
  const std::string out = Path("new_out");
  const ContinueResult r = Run({"--param", "gamma", "--out", out, "--no_plots"}, 60);
  EXPECT_EQ(r.code, 2);
  EXPECT_FALSE(Exists(out));
}

// Pre-existing outputs survive every kind of rejection byte for byte.
TEST_F(ContinueApp, RejectionsLeaveExistingOutputsByteIdentical) {
  const std::string out = OutDir();
  ASSERT_EQ(::mkdir(out.c_str(), 0777), 0);
  const std::string branch = out + "/branch.tsv", special = out + "/special_points.tsv";
  WriteFile(branch, kSentinel);
  WriteFile(special, "# label\tv\nGR\t0.39\n");
  struct stat before;
  ASSERT_EQ(::stat(branch.c_str(), &before), 0);
  const std::string bad_study = Study("bad.ini", "beta = oops\n");
  const std::vector<std::vector<std::string>> bad = {
      {"--unknown"},          {"--param", "gamma"},
      {"--beta", "nan"},      {"--from", "1", "--to", "1"},
      {"--study", bad_study}, {"--mu_m", "0.5"},
      {"--rtol", "1"},        {"--law", "coulomb", "--mu_k", "0.5"}};
  for (auto args : bad) {
    args.insert(args.end(), {"--out", out, "--no_plots"});
    const ContinueResult r = Run(args, 60);
    EXPECT_EQ(r.code, 2) << r.shown << "\n" << r.err;
    EXPECT_EQ(Lines(r.err).size(), 1u) << r.shown << "\n" << r.err;
  }
  EXPECT_EQ(ReadFile(branch), kSentinel);
  EXPECT_EQ(ReadFile(special), "# label\tv\nGR\t0.39\n");
  EXPECT_EQ(Listing(out), (std::set<std::string>{"branch.tsv", "special_points.tsv"}));
  struct stat after;
  ASSERT_EQ(::stat(branch.c_str(), &after), 0);
  EXPECT_EQ(after.st_ino, before.st_ino);  // not replaced by a rename either
  EXPECT_EQ(after.st_mtime, before.st_mtime);
}

TEST_F(ContinueApp, HelpExitsZero) {
  const ContinueResult r = Run({"--help"}, 60);
  EXPECT_EQ(r.code, 0);
  EXPECT_EQ(r.err, "");
  for (const char* opt : {"--study", "--param", "--from", "--to", "--out", "--max_step",
                          "--max_time", "--no_plots", "--rtol"})
    EXPECT_TRUE(Contains(r.out, opt));
}

// ---------------------------------------------------------------------------
// The good path: the seed study's branch.

TEST_F(ContinueApp, SeedStudyBranchHasOneGrazingAndOneHopfPoint) {
  const std::string out = OutDir();
  const ContinueResult r = Run({"--study", kStudies + "/seed.ini", "--param", "v", "--from", "0.05",
                                "--to", "0.5", "--out", out, "--no_plots"});
  ASSERT_EQ(r.code, 0) << r.err;
  const Branch b = ReadBranch(ReadFile(out + "/branch.tsv"));
  // Metadata first, then the header line without '#' (pandas, csv.DictReader).
  EXPECT_EQ(b.first_line.rfind("# tool: ss_continue ", 0), 0u) << b.first_line;
  ASSERT_GE(b.columns.size(), 2u);
  EXPECT_EQ(b.columns[0], "v");
  EXPECT_EQ(b.columns[1], "kind");
  EXPECT_EQ(b.meta.at("continued"), "v");
  EXPECT_EQ(b.meta.at("from"), "0.05");
  EXPECT_EQ(b.meta.at("to"), "0.5");
  EXPECT_EQ(b.meta.at("beta"), "0.05");
  EXPECT_EQ(b.meta.at("rtol"), "1e-11");
  ASSERT_FALSE(b.rows.empty());
  for (size_t i = 0; i < b.rows.size(); ++i)
    ASSERT_EQ(b.rows[i].size(), b.columns.size()) << "row " << i;
  EXPECT_EQ(b.rows[0][0], "0.05");
  EXPECT_EQ(std::strtod(b.rows[0][0].c_str(), nullptr), 0.05);
  bool complete = false;
  for (const auto& c : b.comments) complete = complete || c == "# status: complete";
  EXPECT_TRUE(complete);
  const int x_min = b.Column("x_min"), x_max = b.Column("x_max"), kind = b.Column("kind");
  ASSERT_GE(x_min, 0);
  ASSERT_GE(x_max, 0);
  std::set<std::string> kinds;
  for (size_t i = 0; i < b.rows.size(); ++i) {
    kinds.insert(b.rows[i][kind]);
    for (int col : {x_min, x_max}) {
      const std::string& cell = b.rows[i][col];
      EXPECT_EQ(cell.find("nan"), std::string::npos) << "row " << i << " col " << col;
      EXPECT_EQ(cell.find("inf"), std::string::npos) << "row " << i << " col " << col;
    }
  }
  EXPECT_EQ(kinds, (std::set<std::string>{"stick-slip", "pure-slip", "equilibrium"}));

  int gr = 0, hb = 0, other = 0;
  const Tsv special = ReadTsv(ReadFile(out + "/special_points.tsv"));
  ASSERT_GE(special.columns.size(), 2u);
  EXPECT_EQ(special.columns[0], "label");
  EXPECT_EQ(special.columns[1], "v");
  EXPECT_EQ(special.meta.at("status"), "complete");
  for (const auto& row : special.rows) {
    const std::string label = row.at(0);
    (label == "GR" ? gr : label == "HB" ? hb : other)++;
  }
  EXPECT_EQ(gr, 1);
  EXPECT_EQ(hb, 1);
  EXPECT_EQ(other, 0);
  EXPECT_TRUE(Exists(out + "/bifurcation.gp"));
  EXPECT_FALSE(Exists(out + "/bifurcation_x.png"));  // --no_plots
}

// ---------------------------------------------------------------------------
// Interruption and time limit: exit 1, a whole branch marked partial.

// A run of several seconds: the seed's branch with 10^4 steps.
// Long enough to be interrupted: CVODE (Taylor takes 0.2 s for this).
const std::vector<std::string> kLongRun = {"--study",   kStudies + "/seed.ini", "--max_step",
                                           "0.0001",    "--integrator",         "cvode",
                                           "--no_plots"};

TEST_F(ContinueApp, SigintWritesWholePartialBranch) {
  std::vector<std::string> args = kLongRun;
  args.insert(args.end(), {"--out", OutDir()});
  const WallBound bound;
  const ContinueResult r = Run(args, 120, /*sigint_after=*/0.3);
  ASSERT_EQ(r.signal, 0) << "killed by signal " << r.signal;
  ASSERT_EQ(r.code, 1) << "the run ended before SIGINT? " << r.err;
  EXPECT_LT(r.seconds, bound.Of(30.0)) << "SIGINT honoured late";
  EXPECT_TRUE(Contains(r.err, "interrupted by signal " + std::to_string(SIGINT)));
  ExpectWholePartialBranch(OutDir() + "/branch.tsv", "cancelled");
  EXPECT_TRUE(Exists(OutDir() + "/special_points.tsv"));
  for (const auto& name : Listing(OutDir()))  // no temporary left behind
    EXPECT_TRUE(name == "branch.tsv" || name == "special_points.tsv" || name == "bifurcation.gp")
        << name;
}

TEST_F(ContinueApp, MaxTimeWritesWholePartialBranch) {
  std::vector<std::string> args = kLongRun;
  args.insert(args.end(), {"--max_time", "0.05", "--out", OutDir()});
  const WallBound bound;
  const ContinueResult r = Run(args, 120);
  ASSERT_EQ(r.code, 1) << r.err;
  EXPECT_LT(r.seconds, bound.Of(30.0)) << "--max_time 0.05 honoured late";
  const auto lines = Lines(r.err);
  ASSERT_FALSE(lines.empty());
  EXPECT_TRUE(Contains(lines.back(), "ss_continue: error: partial branch written (cancelled)"));
  ExpectWholePartialBranch(OutDir() + "/branch.tsv", "cancelled");
}

// A pathological model: v = v_m = 1e-6 (k3 ~ 1e17, stick phases ~1e5 long,
// slip stiff). The search for the first periodic orbit runs for minutes (over
// 60 s on CVODE Adams); --max_time and SIGINT must still stop it promptly
// (cancellation reaches into the flow).
const std::vector<std::string> kPathological = {
    "--integrator", "cvode",  "--v_m", "1e-6", "--v", "1e-6",       "--param",
    "beta",         "--from", "0.01",  "--to", "0.3", "--no_plots", "--no_estimates"};

TEST_F(ContinueApp, MaxTimeStopsAPathologicalOrbit) {
  std::vector<std::string> args = kPathological;
  args.insert(args.end(), {"--max_time", "0.5", "--out", OutDir()});
  const WallBound bound;
  const ContinueResult r = Run(args, 60);
  ASSERT_FALSE(r.timed_out);
  ASSERT_EQ(r.code, 1) << r.err;
  EXPECT_LT(r.seconds, bound.Of(15.0)) << "--max_time 0.5 honoured late";
  ExpectWholePartialBranch(OutDir() + "/branch.tsv", "cancelled");
}

TEST_F(ContinueApp, SigintStopsAPathologicalOrbit) {
  std::vector<std::string> args = kPathological;
  args.insert(args.end(), {"--out", OutDir()});
  const WallBound bound;
  const ContinueResult r = Run(args, 60, /*sigint_after=*/0.3);
  ASSERT_FALSE(r.timed_out);
  ASSERT_EQ(r.signal, 0) << "killed by signal " << r.signal;
  ASSERT_EQ(r.code, 1) << r.err;
  EXPECT_LT(r.seconds, bound.Of(15.0)) << "SIGINT honoured late";
  ExpectWholePartialBranch(OutDir() + "/branch.tsv", "cancelled");
}

// A partial result replaces an older complete one whole, never half of it.
TEST_F(ContinueApp, PartialRunReplacesOldBranchWhole) {
  const std::string out = OutDir();
  ASSERT_EQ(::mkdir(out.c_str(), 0777), 0);
  WriteFile(out + "/branch.tsv", kSentinel);
  std::vector<std::string> args = kLongRun;
  args.insert(args.end(), {"--max_time", "0.05", "--out", out});
  const ContinueResult r = Run(args, 120);
  ASSERT_EQ(r.code, 1) << r.err;
  ExpectWholePartialBranch(out + "/branch.tsv", "cancelled");
}

// ---------------------------------------------------------------------------
// Hard ranges finish: exit 0, or exit 1 with a partial branch and one clear
// final line. Never a hang (the runner kills after 120 s and fails the test).

void ExpectFinished(const ContinueResult& r, const std::string& out) {
  ASSERT_FALSE(r.timed_out);
  ASSERT_EQ(r.signal, 0) << r.shown << ": killed by signal " << r.signal;
  ASSERT_TRUE(r.code == 0 || r.code == 1) << r.shown << ": exit " << r.code << "\n" << r.err;
  if (r.code == 1) {
    const auto lines = Lines(r.err);
    ASSERT_FALSE(lines.empty());
    EXPECT_TRUE(Contains(lines.back(), "ss_continue: error: partial branch written"));
    const Branch b = ReadBranch(ReadFile(out + "/branch.tsv"));
    for (const auto& row : b.rows) EXPECT_EQ(row.size(), b.columns.size());
  } else {
    EXPECT_TRUE(Contains(ReadFile(out + "/branch.tsv"), "# status: complete"));
  }
}

TEST_F(ContinueApp, RangeFarPastHopfPointFinishes) {
  const ContinueResult r = Run({"--study", kStudies + "/seed.ini", "--from", "0.05", "--to", "5",
                                "--out", OutDir(), "--no_plots"});
  ExpectFinished(r, OutDir());
  if (r.code == 0) {  // the end of the range is on stable steady sliding
    const Branch b = ReadBranch(ReadFile(OutDir() + "/branch.tsv"));
    bool at_end = false;
    for (const auto& row : b.rows) at_end = at_end || (row[0] == "5" && row[1] == "equilibrium");
    EXPECT_TRUE(at_end);
  }
}

TEST_F(ContinueApp, TinyBeltSpeedFinishes) {
  const ContinueResult r = Run({"--study", kStudies + "/seed.ini", "--from", "1e-4", "--to", "0.5",
                                "--out", OutDir(), "--no_plots"});
  ExpectFinished(r, OutDir());
  if (r.code == 0) {
    const Branch b = ReadBranch(ReadFile(OutDir() + "/branch.tsv"));
    ASSERT_FALSE(b.rows.empty());
    EXPECT_EQ(std::strtod(b.rows[0][0].c_str(), nullptr), 1e-4) << b.rows[0][0];
    EXPECT_EQ(b.rows[0][1], "stick-slip");
  }
}

TEST_F(ContinueApp, DownwardRangeFinishes) {
  const ContinueResult r = Run({"--study", kStudies + "/seed.ini", "--from", "5", "--to", "1e-4",
                                "--out", OutDir(), "--no_plots"});
  ExpectFinished(r, OutDir());
}

TEST_F(ContinueApp, StribeckWideRangeFinishes) {
  const ContinueResult r = Run({"--study", kStudies + "/stribeck.ini", "--from", "1e-4", "--to",
                                "5", "--out", OutDir(), "--no_plots"});
  ExpectFinished(r, OutDir());
}

}  // namespace

namespace {
// A given base value of the continued parameter is validated too (issue 23,
// old #20), as is any other parameter's.
TEST_F(ContinueApp, ContinuedParameterBaseValueIsValidated) {
  const ContinueResult given = Run({"--param", "v", "--v", "-1", "--from", "0.05", "--to", "0.5",
                                    "--out", OutDir(), "--no_plots"});
  EXPECT_EQ(given.code, 2) << given.err;
  EXPECT_NE(given.err.find("v = -1"), std::string::npos) << given.err;
  const ContinueResult bad = Run({"--param", "beta", "--v", "-1", "--from", "0.01", "--to", "0.2",
                                  "--out", OutDir(), "--no_plots"});
  EXPECT_EQ(bad.code, 2);
  EXPECT_NE(bad.err.find("v = -1"), std::string::npos) << bad.err;
}
}  // namespace

namespace {
// The model line of branch.tsv states no value for the continued parameter
// (its base value, here the default v = 0.25, is never used): it gives the range,
// and the other parameters as they are.
TEST_F(ContinueApp, ModelLineGivesTheContinuedParameterItsRange) {
  const std::string out = OutDir();
  const ContinueResult r = Run({"--param", "v", "--from", "0.3", "--to", "0.35", "--out", out,
                                "--no_plots", "--no_estimates"});
  ASSERT_EQ(r.code, 0) << r.err;
  const Tsv b = ReadTsv(ReadFile(out + "/branch.tsv"));
  EXPECT_EQ(b.meta.at("model"),
            "law=cubic beta=0.05 v=[0.3, 0.35] mu_s=0.4 mu_m=0.25 v_m=0.5 k5=0");
  EXPECT_EQ(b.meta.at("v"), "continued");
}
}  // namespace
