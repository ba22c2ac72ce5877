// End-to-end tests of the built ss_basin: the stribeck scene's basins.tsv
// (metadata, one row per start, both basins present), bad input (exit 2, one
// line naming the option, nothing written), --max_time and SIGINT (exit 1, a
// whole basins.tsv marked partial), the progress line, --help.
#include <gtest/gtest.h>
#include <stdlib.h>
#include <sys/wait.h>

#include <cstdlib>
#include <sstream>
#include <string>

#include "app_test_util.hpp"
#include "test_paths.hpp"

namespace {

using stickslip::testing_util::Contains;
using stickslip::testing_util::Exists;
using stickslip::testing_util::ReadFile;

const std::string kApp = STICKSLIP_BIN_DIR "/ss_basin";

class BasinApp : public stickslip::testing_util::AppTest {
 protected:
  // Runs the app under `timeout` (signal, seconds); returns its exit code.
  int Run(const std::string& args, const std::string& signal = "KILL", int seconds = 300) {
    return RunApp(STICKSLIP_BIN_DIR, "ss_basin", args, signal, seconds);
  }
  std::string Out() const { return dir_ + "/out"; }
};

int Count(const std::string& text, const std::string& part) {
  int n = 0;
  for (size_t at = text.find(part); at != std::string::npos; at = text.find(part, at + 1)) ++n;
  return n;
}

TEST_F(BasinApp, StribeckSceneWritesBothBasinsAndTheOrbits) {
  ASSERT_EQ(
      Run("--study " + kStudies + "/stribeck_basin.ini --nx 9 --ny 9 --no_plots --out " + Out()), 0)
      << err_;
  const std::string tsv = ReadFile(Out() + "/basins.tsv");
  // Metadata lines first, then the header line without '#'.
  EXPECT_EQ(tsv.rfind("# ", 0), 0u);
  EXPECT_LT(tsv.find("# status: complete"), tsv.find("\nx\txdot\tfate\torbit\tt_settle\n"));
  EXPECT_TRUE(Contains(tsv, "# model: law=stribeck"));
  EXPECT_TRUE(Contains(tsv, "# status: complete"));
  EXPECT_TRUE(Contains(tsv, "# orbit: stick-slip, stable"));
  EXPECT_TRUE(Contains(tsv, "# orbit: pure-slip 0, unstable"));
  EXPECT_TRUE(Contains(tsv, "# smallest disturbance: pure-slip 0: x 0.44"));
  EXPECT_EQ(
      Count(tsv, "\tsteady-sliding\t") + Count(tsv, "\tstick-slip\t") + Count(tsv, "\tundecided\t"),
      81);
  EXPECT_GT(Count(tsv, "\tsteady-sliding\t"), 0);
  EXPECT_GT(Count(tsv, "\tstick-slip\t"), 0);
  EXPECT_TRUE(Contains(ReadFile(Out() + "/orbits.tsv"), "pure-slip"));
  EXPECT_TRUE(Contains(ReadFile(Out() + "/basins.gp"), "basins.png"));
}

TEST_F(BasinApp, BadInputExits2AndWritesNothing) {
  const std::string cases[][2] = {{"--nx 0", "--nx"},
                                  {"--t_cap -5", "--t_cap"},
                                  {"--x_min 1", "give all four"},
                                  {"--x_min 1 --x_max 0 --xdot_min 0 --xdot_max 1", "--x_min = 1"},
                                  {"--v abc", "--v"},
                                  {"--max_time -1", "--max_time"}};
  for (const auto& c : cases) {
    SCOPED_TRACE(c[0]);
    EXPECT_EQ(Run(c[0] + " --out " + Out()), 2);
    EXPECT_TRUE(Contains(err_, c[1]));
    EXPECT_EQ(Count(err_, "\n"), 1);
    EXPECT_FALSE(Exists(Out() + "/basins.tsv"));
  }
}

TEST_F(BasinApp, MaxTimeAndSigintLeaveAWholePartialFile) {
  // 360000 starts: about 10 s, well past the signal at 3 s (300 x 300 now ends before it).
  const std::string big = "--study " + kStudies + "/stribeck_basin.ini --nx 600 --ny 600 " +
                          "--no_plots --out " + Out();
  EXPECT_EQ(Run(big + " --max_time 1"), 1);
  EXPECT_TRUE(Contains(err_, "partial"));
  std::string tsv = ReadFile(Out() + "/basins.tsv");
  EXPECT_TRUE(Contains(tsv, "# status: partial (cancelled)"));
  EXPECT_EQ(tsv.back(), '\n');
  EXPECT_EQ(Run(big, "INT", 3), 1);
  EXPECT_TRUE(Contains(err_, "interrupted by signal 2"));
  EXPECT_TRUE(Contains(err_, " of 360000 starts after "));  // the progress line
  tsv = ReadFile(Out() + "/basins.tsv");
  EXPECT_TRUE(Contains(tsv, "# status: partial (cancelled)"));
}

// timeout(1) sends its signal to the app and then to the app's process
// group: two copies of one interrupt, here 50 ms apart. The app takes them
// as one (exit 1, a whole partial file); only a later second signal ends it
// at once (run_control.cpp).
TEST_F(BasinApp, ATwiceDeliveredInterruptIsOneInterrupt) {
  const std::string cmd = "cd " + dir_ + " && { " + kApp + " --study " + kStudies +
                          "/stribeck_basin.ini --nx 600 --ny 600 --no_plots --out " + Out() +
                          " > stdout 2> stderr & p=$!; sleep 2; kill -INT $p; sleep 0.05; "
                          "kill -INT $p; wait $p; echo $? > rc; }";
  ASSERT_EQ(std::system(cmd.c_str()), 0);
  EXPECT_EQ(ReadFile(dir_ + "/rc"), "1\n") << ReadFile(dir_ + "/stderr");
  EXPECT_TRUE(Contains(ReadFile(dir_ + "/stderr"), "interrupted by signal 2"));
  const std::string tsv = ReadFile(Out() + "/basins.tsv");
  EXPECT_TRUE(Contains(tsv, "# status: partial (cancelled)"));
  EXPECT_EQ(tsv.back(), '\n');
}

TEST_F(BasinApp, HelpNamesTheOutputsAndVersionPrintsIt) {
  EXPECT_EQ(Run("--help"), 0);
  EXPECT_TRUE(Contains(out_, "basins.tsv"));
  EXPECT_TRUE(Contains(out_, "[basin]"));
  EXPECT_EQ(Run("--version"), 0);
  EXPECT_EQ(out_.rfind("ss_basin 0.", 0), 0u) << out_;
}

}  // namespace
