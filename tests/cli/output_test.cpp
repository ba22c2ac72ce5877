// cli::OutputSet: what it refuses up front, and that a run's files reach
// their names together or not at all.
#include "cli/output.hpp"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <set>
#include <string>
#include <vector>

#include "app_test_util.hpp"
#include "cli/study.hpp"
#include "stickslip/errors.hpp"

namespace stickslip::cli {
namespace {

using testing_util::Exists;
using testing_util::Listing;
using testing_util::ReadFile;
using testing_util::WriteFile;

using stickslip::testing_util::HaveGnuplot;

class Output : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = ::testing::TempDir() + "output_test_XXXXXX";
    ASSERT_NE(::mkdtemp(dir_.data()), nullptr);
  }
  void TearDown() override { EXPECT_EQ(std::system(("rm -rf '" + dir_ + "'").c_str()), 0); }
  std::string dir_;
};

TEST_F(Output, RefusesWhatIsNotARegularFileOrANewName) {
  ASSERT_EQ(::mkdir((dir_ + "/d").c_str(), 0777), 0);
  ASSERT_EQ(::mkfifo((dir_ + "/f").c_str(), 0644), 0);
  WriteFile(dir_ + "/regular", "x\n");
  ASSERT_EQ(::symlink((dir_ + "/regular").c_str(), (dir_ + "/link").c_str()), 0);
  for (const std::string& name :
       std::vector<std::string>{"d", "f", "link", "a/b", "a\nb", std::string(250, 'n')})
    EXPECT_THROW(OutputSet(dir_, {name}, "--out", "t"), UsageError) << name;
  EXPECT_THROW(OutputSet(dir_ + "/x\ny", {"a"}, "--out", "t"), UsageError);
  EXPECT_THROW(OutputSet(dir_ + "/regular", {"a"}, "--out", "t"), UsageError);
  EXPECT_THROW(OutputSet(dir_ + "/missing/deeper", {"a"}, "--out", "t"), UsageError);
  EXPECT_NO_THROW(OutputSet(dir_, {"regular", "new"}, "--out", "t"));
  EXPECT_EQ(ReadFile(dir_ + "/link"), "x\n");
}

TEST_F(Output, CreatesNothingBeforeTheFirstWrite) {
  const std::string out = dir_ + "/new";
  {
    OutputSet set(out, {"a.tsv"}, "--out", "t");
    EXPECT_FALSE(Exists(out));
    set.Write("a.tsv", "1\n");
    EXPECT_FALSE(Exists(out + "/a.tsv"));  // staged only
    set.Commit();
  }
  EXPECT_EQ(Listing(out), std::set<std::string>{"a.tsv"});
  EXPECT_EQ(ReadFile(out + "/a.tsv"), "1\n");
}

TEST_F(Output, UncommittedSetLeavesTheOldFilesAndNoTrace) {
  WriteFile(dir_ + "/a.tsv", "old\n");
  {
    OutputSet set(dir_, {"a.tsv", "b.tsv"}, "--out", "t");
    set.Write("a.tsv", "new\n");
    set.Write("b.tsv", "new\n");
  }  // not committed: as after a failed figure
  EXPECT_EQ(Listing(dir_), std::set<std::string>{"a.tsv"});
  EXPECT_EQ(ReadFile(dir_ + "/a.tsv"), "old\n");
}

TEST_F(Output, CommitRemovesStaleFiguresOnly) {
  WriteFile(dir_ + "/a.png", "old figure\n");
  WriteFile(dir_ + "/other.txt", "not ours\n");
  OutputSet set(dir_, {"a.tsv", "a.png"}, "--out", "t");
  set.Write("a.tsv", "1\n");
  set.Commit({"a.png"});
  EXPECT_EQ(Listing(dir_), (std::set<std::string>{"a.tsv", "other.txt"}));
}

// gnuplot exits 0 but the figure is not a whole PNG (as on a full disk):
// the status is kFailed, naming the figure, and nothing is staged for it.
TEST_F(Output, DrawRejectsAFigureThatIsNotAWholePng) {
  if (!HaveGnuplot()) GTEST_SKIP() << "no gnuplot";
  WriteFile(dir_ + "/p.png", "old\n");
  {
    OutputSet set(dir_, {"p.gp", "p.png"}, "--out", "t");
    set.Write("p.gp", "set print 'p.png'\nprint 'not an image'\n");
    const GnuplotResult g = set.Draw("p.gp", {"p.png"}, nullptr);
    EXPECT_EQ(g.status, GnuplotStatus::kFailed);
    EXPECT_NE(g.message.find("p.png"), std::string::npos) << g.message;
  }
  EXPECT_EQ(ReadFile(dir_ + "/p.png"), "old\n");
  EXPECT_EQ(Listing(dir_), std::set<std::string>{"p.png"});
}

// A directory that appears at a target during the run: Commit fails, naming
// the file and the reason (the app exits 1), never a silent success.
TEST_F(Output, CommitFailsWhenADirectoryStandsAtATarget) {
  OutputSet set(dir_, {"a.tsv", "b.tsv"}, "--out", "t");
  set.Write("a.tsv", "1\n");
  set.Write("b.tsv", "2\n");
  ASSERT_EQ(::mkdir((dir_ + "/b.tsv").c_str(), 0777), 0);
  try {
    set.Commit();
    ADD_FAILURE() << "Commit succeeded with a directory at b.tsv";
  } catch (const Error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("cannot move 'b.tsv'"), std::string::npos) << what;
    EXPECT_NE(what.find("Is a directory"), std::string::npos) << what;
  }
}

// The staging directory of a killed run (its process gone) is removed by the
// next run; one whose process lives is left alone.
TEST_F(Output, LeftoversOfAKilledRunAreRemoved) {
  const pid_t child = ::fork();
  if (child == 0) ::_exit(0);
  ASSERT_GT(child, 0);
  ASSERT_EQ(::waitpid(child, nullptr, 0), child);  // a pid whose process is gone
  const std::string dead = dir_ + "/.t-" + std::to_string(child) + "-abcdef";
  const std::string live = dir_ + "/.t-1-abcdef";  // init lives
  for (const auto& d : {dead, live}) {
    ASSERT_EQ(::mkdir(d.c_str(), 0700), 0);
    WriteFile(d + "/a.png.part", "half\n");
  }
  OutputSet set(dir_, {"a.tsv"}, "--out", "t");
  set.Write("a.tsv", "1\n");
  set.Commit();
  EXPECT_EQ(Listing(dir_), (std::set<std::string>{"a.tsv", ".t-1-abcdef"}));
}

}  // namespace
}  // namespace stickslip::cli
