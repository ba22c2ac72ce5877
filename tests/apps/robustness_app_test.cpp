// The randomized robustness sweep over the apps (the library's is in
// robustness_test.cpp): concurrent runs on one --out, and SIGINT, SIGTERM or
// --max_time at random moments, in every phase (continuation, estimates,
// writing, gnuplot). Seeded, so a failure repeats.
//
// What must hold: a run ends by itself (exit 0 or 1), promptly after the
// signal or the limit; every file in --out is whole (a TSV has its status
// line and ends with a newline, a PNG passes PngError); the set is one run's
// (byte-equal to that run's reference set); no staging directory is left.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstdlib>
#include <map>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "app_test_util.hpp"
#include "cli/gnuplot.hpp"

namespace {

const std::string kContinue = STICKSLIP_BIN_DIR "/ss_continue";

using stickslip::cli::PngError;
using stickslip::testing_util::Contains;
using stickslip::testing_util::Launch;
using stickslip::testing_util::Listing;
using stickslip::testing_util::Outcome;
using stickslip::testing_util::ReadFile;
using stickslip::testing_util::RunChild;
using stickslip::testing_util::Start;
using stickslip::testing_util::Wait;
using stickslip::testing_util::WallBound;

using stickslip::testing_util::HaveGnuplot;

class RobustnessApp : public stickslip::testing_util::AppTest {
 protected:
  void SetUp() override { AppTest::SetUp(); }
  std::string Path(const std::string& name) const { return dir_ + "/" + name; }

  // Every file of a directory, by name; in text files the '#' lines (metadata
  // such as the command line or a time) are left out, the data identify the run.
  std::map<std::string, std::string> Files(const std::string& dir) const {
    std::map<std::string, std::string> files;
    for (const auto& n : Listing(dir)) {
      const std::string text = ReadFile(dir + "/" + n);
      if (n.size() > 4 && n.compare(n.size() - 4, 4, ".png") == 0) {
        files[n] = text;
        continue;
      }
      std::istringstream lines(text);
      for (std::string line; std::getline(lines, line);)
        if (line.empty() || line[0] != '#') files[n] += line + "\n";
    }
    return files;
  }

  // Each file whole; hidden names (staging directories) are a failure.
  void ExpectWhole(const std::string& dir, const std::string& context) const {
    for (const auto& name : Listing(dir)) {
      SCOPED_TRACE(context + ": " + name);
      EXPECT_NE(name[0], '.') << "left behind";
      const std::string path = dir + "/" + name;
      if (name.size() > 4 && name.compare(name.size() - 4, 4, ".png") == 0) {
        EXPECT_EQ(PngError(path), "");
      } else if (name.size() > 4 && name.compare(name.size() - 4, 4, ".tsv") == 0) {
        const std::string text = ReadFile(path);
        ASSERT_FALSE(text.empty());
        EXPECT_EQ(text.back(), '\n');
        EXPECT_TRUE(Contains(text, "status: ") || name == "special_points.tsv");
      }
    }
  }
};

// Two runs with different models on one --out, started a random moment
// apart: after both, the directory holds exactly one run's set.
TEST_F(RobustnessApp, ConcurrentRunsOnOneOutLeaveOneWholeSet) {
  if (!HaveGnuplot()) GTEST_SKIP() << "no gnuplot";
  // The sets differ in their files too (estimates.png only with the estimates).
  const std::vector<std::vector<std::string>> models = {{"--beta", "0.05"},
                                                        {"--beta", "0.06", "--no_estimates"}};
  std::vector<std::map<std::string, std::string>> reference;
  for (std::size_t m = 0; m < models.size(); ++m) {
    std::vector<std::string> args = models[m];
    args.insert(args.end(), {"--out", Path("out")});  // the same command line as below
    const Outcome r = RunChild(kContinue, args, Launch{});
    ASSERT_EQ(r.code, 0);
    reference.push_back(Files(Path("out")));
    ASSERT_EQ(std::system(("rm -rf '" + Path("out") + "'").c_str()), 0);
  }
  std::mt19937 rng(20261121);
  std::uniform_real_distribution<double> offset(0.0, 0.4);
  for (int round = 0; round < 6; ++round) {
    const std::string out = Path("out");
    ASSERT_EQ(std::system(("rm -rf '" + out + "'").c_str()), 0);
    std::vector<pid_t> pids;
    for (std::size_t m = 0; m < models.size(); ++m) {
      std::vector<std::string> args = models[m];
      args.insert(args.end(), {"--out", out});
      if (m > 0) ::usleep(static_cast<useconds_t>(offset(rng) * 1e6));
      pids.push_back(Start(kContinue, args, Launch{}));
    }
    for (pid_t pid : pids) {
      const Outcome r = Wait(pid, Launch{});
      EXPECT_EQ(r.code, 0) << "round " << round;
    }
    const auto files = Files(out);
    ExpectWhole(out, "round " + std::to_string(round));
    EXPECT_TRUE(files == reference[0] || files == reference[1])
        << "round " << round << ": files of both runs mixed";
  }
}

// SIGINT, SIGTERM or --max_time at a random moment: the run ends by itself,
// promptly, leaving whole files (or none, for a signal before its handler).
TEST_F(RobustnessApp, SignalsAndTimeLimitsAtRandomMomentsLeaveWholeFiles) {
  std::mt19937 rng(1521);
  std::uniform_real_distribution<double> when(0.0, 1.5);
  for (int trial = 0; trial < 12; ++trial) {
    const std::string out = Path("out" + std::to_string(trial));
    const double t = when(rng);
    Launch l;
    l.timeout = 60;
    std::vector<std::string> args = {"--out", out};
    std::string what;
    if (trial % 3 == 2) {
      args.insert(args.end(), {"--max_time", std::to_string(t)});
      what = "--max_time " + std::to_string(t);
    } else {
      l.signal = trial % 3 == 0 ? SIGINT : SIGTERM;
      l.signal_after = t;
      // Past the first 50 ms, t counts from the handler's installation: a
      // process start (1 s for a sanitizer build under load) is not a phase.
      l.signal_when_caught = t >= 0.05;
      what = std::string(trial % 3 == 0 ? "SIGINT" : "SIGTERM") + " at " + std::to_string(t);
    }
    SCOPED_TRACE(what);
    const WallBound bound;
    const Outcome r = RunChild(kContinue, args, l);
    ASSERT_FALSE(r.timed_out);
    // A signal can only come before the handler when sent at the start.
    if (r.signal != 0) {
      EXPECT_EQ(r.signal, l.signal);
      EXPECT_FALSE(l.signal_when_caught) << "killed after its handler was installed";
      EXPECT_TRUE(Listing(out).empty());
      continue;
    }
    EXPECT_TRUE(r.code == 0 || r.code == 1) << "exit " << r.code;
    EXPECT_LT(r.seconds, t + bound.Of(10.0)) << "honoured late";
    ExpectWhole(out, what);
  }
}

}  // namespace
