// Output primitives: the TSV layout (metadata lines, then a header without
// '#'), the atomic write's error path, the PNG check, gnuplot cancellation,
// and figures of results with nothing to draw.
#include "stickslip/io/report.hpp"

#include <dirent.h>
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdlib>
#include <set>
#include <string>

#include "app_test_util.hpp"
#include "cli/gnuplot.hpp"
#include "stickslip/errors.hpp"
#include "stickslip/io/branch_report.hpp"

namespace stickslip {
namespace {

using cli::GnuplotResult;
using cli::GnuplotStatus;
using cli::PngError;
using cli::RunGnuplot;
using testing_util::Listing;
using testing_util::ReadFile;
using testing_util::WriteFile;

// A fresh directory, removed with everything in it at the end of the scope.
struct Scratch {
  std::string dir;
  Scratch() : dir(::testing::TempDir() + "report_test_XXXXXX") {
    EXPECT_NE(::mkdtemp(dir.data()), nullptr);
  }
  ~Scratch() { EXPECT_EQ(std::system(("rm -rf '" + dir + "'").c_str()), 0); }
};

using stickslip::testing_util::HaveGnuplot;

// A write that fails after the temporary file exists (RLIMIT_FSIZE: the
// kernel refuses bytes past the limit with EFBIG) must remove that file and
// leave the old one. Done in a forked child, whose limit does not touch us.
TEST(Report, AtomicWriteFailingMidwayRemovesItsTemporaryFile) {
  const Scratch scratch;
  const std::string dir = scratch.dir, path = dir + "/branch.tsv";
  WriteFile(path, "old\n");
  const pid_t pid = ::fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    std::signal(SIGXFSZ, SIG_IGN);  // EFBIG instead of death
    struct rlimit lim = {1000, 1000};
    if (::setrlimit(RLIMIT_FSIZE, &lim) != 0) ::_exit(3);
    try {
      WriteFileAtomically(path, std::string(5000, 'x'));
    } catch (const Error& e) {
      const std::string what = e.what();
      ::_exit(what.find(path) != std::string::npos ? 0 : 4);
    }
    ::_exit(5);  // no exception: the failure went unnoticed
  }
  int status = 0;
  ASSERT_EQ(::waitpid(pid, &status, 0), pid);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0) << "3: setrlimit, 4: message without the path, 5: no error";
  EXPECT_EQ(Listing(dir), std::set<std::string>{"branch.tsv"});  // no .branch.tsv.tmp-...
  EXPECT_EQ(ReadFile(path), "old\n");
}

TEST(Report, PngErrorAcceptsOnlyWholeImages) {
  const Scratch scratch;
  const std::string& dir = scratch.dir;
  const std::string sig("\x89PNG\r\n\x1a\n", 8);
  const std::string iend("\0\0\0\0IEND\xae\x42\x60\x82", 12);
  WriteFile(dir + "/whole.png", sig + std::string(100, 'd') + iend);
  WriteFile(dir + "/empty.png", "");
  WriteFile(dir + "/truncated.png", sig + std::string(100, 'd'));
  WriteFile(dir + "/text.png", std::string(200, 't'));
  EXPECT_EQ(PngError(dir + "/whole.png"), "");
  EXPECT_NE(PngError(dir + "/empty.png").find("empty"), std::string::npos);
  EXPECT_NE(PngError(dir + "/truncated.png").find("truncated"), std::string::npos);
  EXPECT_NE(PngError(dir + "/text.png").find("not a PNG"), std::string::npos);
  EXPECT_NE(PngError(dir + "/missing.png"), "");
}

TEST(Report, CancelledGnuplotIsKilledPromptly) {
  if (!HaveGnuplot()) GTEST_SKIP() << "no gnuplot";
  const Scratch scratch;
  const std::string& dir = scratch.dir;
  WriteFile(dir + "/slow.gp", "pause 60\n");
  const testing_util::WallBound bound;
  const auto start = std::chrono::steady_clock::now();
  auto seconds = [&] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };
  const GnuplotResult r = RunGnuplot(dir + "/slow.gp", dir, [&] { return seconds() > 0.3; });
  EXPECT_EQ(r.status, GnuplotStatus::kCancelled) << r.message;
  EXPECT_LT(seconds(), bound.Of(10.0));
}

TEST(Report, MissingGnuplotHasItsOwnStatus) {
  const char* old = std::getenv("PATH");
  const std::string saved = old ? old : "";
  ::setenv("PATH", "/nonexistent", 1);
  const GnuplotResult r = RunGnuplot("x.gp", "", std::function<bool()>());
  ::setenv("PATH", saved.c_str(), 1);
  EXPECT_EQ(r.status, GnuplotStatus::kMissing) << r.message;
}

// A result with no periodic orbit, or no point at all (cancelled at once),
// still gives a script gnuplot draws whole: an empty frame that says so.
TEST(Report, FiguresOfEmptyResultsAreDrawn) {
  if (!HaveGnuplot()) GTEST_SKIP() << "no gnuplot";
  ContinuationResult equilibrium_only;
  for (int i = 0; i <= 4; ++i) {
    BranchPoint p;
    p.p = 0.45 + 0.01 * i;
    p.period = std::nan("");
    p.t_stick = std::nan("");
    p.extrema.x_min = p.extrema.x_max = 0.25;
    p.multiplier = -0.01;
    p.stable = true;
    equilibrium_only.points.push_back(p);
  }
  ContinuationResult nothing;
  nothing.status = ContinuationStatus::kCancelled;
  for (const ContinuationResult* r : {&equilibrium_only, &nothing}) {
    for (bool estimates : {false, true}) {
      const Scratch scratch;
      const std::string& dir = scratch.dir;
      std::vector<ExtraColumn> extra;
      if (estimates)
        for (int c = 0; c < 7; ++c)
          extra.push_back(
              {"e" + std::to_string(c), std::vector<double>(r->points.size(), std::nan(""))});
      WriteFileAtomically(dir + "/branch.tsv", BranchTable(*r, "m", extra).str());
      WriteFileAtomically(dir + "/special_points.tsv", SpecialPointTable(*r).str());
      WriteFileAtomically(dir + "/b.gp", BifurcationScript(*r, "t", estimates));
      std::string err;
      ASSERT_TRUE(RunGnuplot(dir + "/b.gp", dir, &err)) << err;
      for (const auto& f : BifurcationFigures(estimates))
        EXPECT_EQ(PngError(dir + "/" + f), "") << f;
    }
  }
}

TEST(Report, NonFiniteResultsAreDroppedAndTheRunFails) {
  ContinuationResult r;
  BranchPoint good;
  good.p = 0.1;
  good.period = 5;
  good.kind = PointKind::kStickSlip;
  BranchPoint bad = good;
  bad.p = 0.2;
  bad.multiplier = std::nan("");
  BranchPoint eq;  // nan period and t_stick belong to the equilibrium
  eq.p = 0.3;
  eq.period = eq.t_stick = std::nan("");
  r.points = {good, bad, eq};
  DropNonFinite(&r);
  ASSERT_EQ(r.points.size(), 2u);
  EXPECT_EQ(r.points[0].p, 0.1);
  EXPECT_EQ(r.points[1].p, 0.3);
  EXPECT_EQ(r.status, ContinuationStatus::kFailed);
  EXPECT_NE(r.message.find("multiplier = nan at v = 0.2"), std::string::npos) << r.message;
  const std::string table = BranchTable(r, "m").str();
  EXPECT_EQ(table.find("\tinf"), std::string::npos);
  EXPECT_EQ(table.find("0.2\t"), std::string::npos);
}

TEST(Report, TableStartsWithMetadataThenAHeaderWithoutHash) {
  TsvTable t({"v", "kind"});
  t.AddMeta("status", "complete");
  t.AddRow({0.25, "stick-slip"});
  t.PrependMeta({{"tool", "ss_continue 0.1.0"}, {"beta", "0.05"}});
  EXPECT_EQ(t.str(),
            "# tool: ss_continue 0.1.0\n# beta: 0.05\n# status: complete\n"
            "v\tkind\n0.25\tstick-slip\n");
}

// No nan or inf is written: a value that does not apply is an empty cell, and
// a number that is not finite is refused, naming its column and row, with
// the table left as it was.
TEST(Report, NotApplicableIsAnEmptyCellAndNonFiniteIsRefused) {
  TsvTable t({"v", "period"});
  t.AddRow({0.25, TsvTable::Cell::OrEmpty(std::nan(""))});
  t.AddRow({0.5, TsvTable::Cell::OrEmpty(2.5)});
  t.AddRow({0.75, ""});
  for (double bad : {std::nan(""), HUGE_VAL, -HUGE_VAL}) {
    try {
      t.AddRow({1.0, bad});
      ADD_FAILURE() << "accepted " << bad;
    } catch (const InvalidArgument& e) {
      EXPECT_NE(std::string(e.what()).find("column 'period', row 4: not a finite number"),
                std::string::npos)
          << e.what();
    }
  }
  EXPECT_THROW(t.AddRow({1.0, TsvTable::Cell::OrEmpty(HUGE_VAL)}), InvalidArgument);
  EXPECT_EQ(t.rows(), 3u);
  EXPECT_EQ(t.str(), "v\tperiod\n0.25\t\n0.5\t2.5\n0.75\t\n");
}

// Steady sliding's period and t_stick and an extra column's NaN are empty
// cells of branch.tsv and special_points.tsv.
TEST(Report, BranchTablesWriteNotApplicableAsEmptyCells) {
  ContinuationResult r;
  BranchPoint orbit;
  orbit.p = 0.1, orbit.period = 5, orbit.t_stick = 1, orbit.kind = PointKind::kStickSlip;
  BranchPoint eq;
  eq.p = 0.3, eq.period = eq.t_stick = std::nan("");
  r.points = {orbit, eq};
  SpecialPoint sp;
  sp.p = 0.2, sp.period = 4;
  r.special = {sp};
  const std::vector<ExtraColumn> extra = {{"r1", {0.5, std::nan("")}}};
  const std::string branch = BranchTable(r, "m", extra).str();
  const std::string special = SpecialPointTable(r, {{"period_s", {std::nan("")}}}).str();
  for (const std::string& text : {branch, special}) {
    EXPECT_EQ(text.find("nan"), std::string::npos) << text;
    EXPECT_EQ(text.find("inf"), std::string::npos) << text;
  }
  const testing_util::Tsv b = testing_util::ReadTsv(branch);
  ASSERT_EQ(b.rows.size(), 2u);
  for (const char* c : {"period", "t_stick", "r1"}) {
    ASSERT_GE(b.Column(c), 0) << c;
    EXPECT_NE(b.rows[0][b.Column(c)], "") << c;
    EXPECT_EQ(b.rows[1][b.Column(c)], "") << c;
  }
  const testing_util::Tsv s = testing_util::ReadTsv(special);
  ASSERT_EQ(s.rows.size(), 1u);
  EXPECT_EQ(s.rows[0][s.Column("period")], "4");
  EXPECT_EQ(s.rows[0][s.Column("period_s")], "");
}

TEST(Report, MetadataKeyWithColonOrLineBreakIsRejected) {
  TsvTable t({"v"});
  EXPECT_THROW(t.AddMeta("a:b", "1"), InvalidArgument);
  EXPECT_THROW(t.AddMeta("", "1"), InvalidArgument);
  EXPECT_THROW(t.AddMeta("key", "two\nlines"), InvalidArgument);
}

}  // namespace
}  // namespace stickslip
