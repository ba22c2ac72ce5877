// End-to-end tests of the built ss_chart: bad input is rejected with exit code
// 2, one stderr line naming the problem and nothing written; --help and
// --version; the seed study writes curves.tsv and codim2.tsv with the
// metadata lines of branch.tsv.
#include <gtest/gtest.h>
#include <stdlib.h>
#include <sys/wait.h>

#include <cstdlib>
#include <string>
#include <vector>

#include "app_test_util.hpp"
#include "test_paths.hpp"

namespace {

using stickslip::testing_util::Contains;
using stickslip::testing_util::Exists;
using stickslip::testing_util::ReadFile;

struct Result {
  int code = -1;
  std::string out, err;
};

class ChartApp : public stickslip::testing_util::AppTest {
 protected:
  std::string Out() const { return dir_ + "/out"; }

  // Runs the app (killed after 120 s) with stdout and stderr captured.
  Result Run(const std::vector<std::string>& args) {
    std::string words;
    for (const auto& a : args) words += " " + stickslip::testing_util::ShellQuoted(a);
    Result r;
    r.code = RunApp(STICKSLIP_BIN_DIR, "ss_chart", words, "KILL", 120);
    r.out = out_, r.err = err_;
    return r;
  }

  // Exit 2, one line "ss_chart: error: ..." with every part, and no --out.
  void ExpectRejected(std::vector<std::string> args, const std::vector<std::string>& parts) {
    args.insert(args.end(), {"--out", Out(), "--no_plots"});
    const Result r = Run(args);
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_EQ(r.err.rfind("ss_chart: error: ", 0), 0u) << r.err;
    EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << "not one line: " << r.err;
    for (const auto& p : parts) EXPECT_TRUE(Contains(r.err, p));
    EXPECT_FALSE(Exists(Out())) << "--out was created";
  }
};

TEST_F(ChartApp, EqualAxesExit2) {
  ExpectRejected({"--param", "v", "--param2", "v"}, {"param = param2 = 'v'", "must differ"});
}

TEST_F(ChartApp, UnknownParameterExits2) {
  ExpectRejected({"--param2", "gamma"}, {"param2 = 'gamma'", "no parameter"});
  ExpectRejected({"--param", "delta"}, {"'delta'", "does not apply to the cubic law"});
}

TEST_F(ChartApp, EmptyOrInvertedRectangleExits2) {
  ExpectRejected({"--from", "0.3", "--to", "0.3"}, {"from = 0.3", "empty"});
  ExpectRejected({"--from2", "0.2", "--to2", "0.1"}, {"from2 = 0.2", "inverted"});
}

TEST_F(ChartApp, RectangleLeavingTheDomainExits2) {
  ExpectRejected({"--from2", "-0.1", "--to2", "0.1"}, {"leaves the model's domain", "beta = -0.1"});
  ExpectRejected({"--param2", "mu_s", "--from2", "0.2", "--to2", "0.5"},
                 {"leaves the model's domain", "mu_m = 0.25 must be < mu_s"});
  ExpectRejected({"--k5", "0.24", "--to", "1.5"}, {"k5 = 0.24 makes mu(v)"});
}

TEST_F(ChartApp, BadNumbersAndOptionsExit2) {
  ExpectRejected({"--to2", "abc"}, {"--to2", "'abc'"});
  ExpectRejected({"--grid", "1"}, {"--grid", "[2, 1000]"});
  ExpectRejected({"--k5", "-1"}, {"k5 = -1 must be >= 0"});
  ExpectRejected({"--gamma", "1"}, {"gamma"});
}

TEST_F(ChartApp, DegenerateRangesAndStepsExit2) {
  ExpectRejected({"--from", "0.05", "--to", "0.0500000000000001"},
                 {"--to: ", "to = 0.0500000000000001 is too close to from = 0.05"});
  ExpectRejected({"--max_step", "1e-9"}, {"max_step = 1e-09", "[5e-05, 0.2]"});
}

// N11: a range end outside the model's domain names its option and value.
TEST_F(ChartApp, RangeEndErrorsNameTheOption) {
  ExpectRejected({"--to2", "5e6"}, {"--to2: ", "beta = 5000000 is outside [0, 1000000]"});
  const Result r = Run({"--to2", "5e6", "--out", Out(), "--no_plots"});
  EXPECT_FALSE(Contains(r.err, "1062500") || Contains(r.err, "1093750")) << r.err;
  ExpectRejected({"--from2", "-0.1"}, {"--from2: ", "beta = -0.1"});
  ExpectRejected({"--k5", "0.24", "--to", "1.5"}, {"--to: ", "v = 1.5"});
}

// A curve cut short (here at max-points) makes the chart partial: exit 1, and
// every file says so.
TEST_F(ChartApp, CutShortChartExits1) {
  const Result r = Run({"--from", "0.466", "--to", "0.5", "--from2", "0", "--to2", "0.03",
                        "--max_step", "5e-5", "--no_plots", "--out", Out()});
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_TRUE(Contains(r.err, "partial"));
  EXPECT_TRUE(Contains(r.err, "HB curve from v = 0.466"));
  EXPECT_TRUE(Contains(ReadFile(Out() + "/curves.tsv"), "# status: partial: HB curve"));
  EXPECT_TRUE(Contains(ReadFile(Out() + "/codim2.tsv"), "# status: partial: HB curve"));
}

TEST_F(ChartApp, HelpAndVersion) {
  Result r = Run({"--help"});
  EXPECT_EQ(r.code, 0);
  EXPECT_TRUE(Contains(r.out, "usage: ss_chart"));
  EXPECT_TRUE(Contains(r.out, "--param2"));
  r = Run({"--version"});
  EXPECT_EQ(r.code, 0);
  EXPECT_EQ(r.out.rfind("ss_chart 0.", 0), 0u) << r.out;
}

TEST_F(ChartApp, SeedStudyWritesCurvesWithMetadata) {
  const Result r = Run({"--study", kStudies + "/seed_chart.ini", "--out", Out(), "--no_plots"});
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string curves = ReadFile(Out() + "/curves.tsv");
  // Metadata lines first, then the header line without '#'.
  EXPECT_EQ(curves.rfind("# ", 0), 0u);
  EXPECT_TRUE(Contains(curves, "\nv\tbeta\tcurve\tid\tperiod\tamplitude\tmultiplier\tl1\ttype\t"));
  EXPECT_LT(curves.find("\n# status: complete\n"), curves.find("\nv\tbeta\tcurve\t"));
  EXPECT_TRUE(Contains(curves, "# model: law=cubic "));
  EXPECT_TRUE(Contains(curves, "\tHB\t1\t"));
  EXPECT_TRUE(Contains(curves, "\tGR\t2\t"));
  EXPECT_FALSE(Contains(stickslip::testing_util::DataLines(curves), "nan"));
  EXPECT_TRUE(Contains(ReadFile(Out() + "/codim2.tsv"), "\nlabel\tv\tbeta\tdescription\n"));
  EXPECT_FALSE(Exists(Out() + "/chart.png"));
}

}  // namespace

namespace {
// The two axes' base values (here the defaults v = 0.25, beta = 0.05) are never
// used: the metadata name them as axes, like the range and model lines.
TEST_F(ChartApp, MetadataStatesNoValueForTheAxes) {
  const Result r = Run({"--study", kStudies + "/seed_chart.ini", "--out", Out(), "--no_plots"});
  ASSERT_EQ(r.code, 0) << r.err;
  for (const char* file : {"/curves.tsv", "/codim2.tsv"}) {
    const stickslip::testing_util::Tsv t = stickslip::testing_util::ReadTsv(ReadFile(Out() + file));
    EXPECT_EQ(t.meta.at("v"), "axis") << file;
    EXPECT_EQ(t.meta.at("beta"), "axis") << file;
    EXPECT_EQ(t.meta.at("mu_s"), "0.4") << file;
    EXPECT_EQ(t.meta.at("range"), "v = [0.02, 0.6], beta = [0, 0.25]") << file;
  }
}
}  // namespace
