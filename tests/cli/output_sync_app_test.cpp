// The order of the system calls that make an app's output set durable
// (docs/reliability.md, "After a power loss"), seen with strace: every staged
// file is fsynced before the first rename into --out, and --out itself is
// fsynced after the last. Skipped where strace is missing or cannot trace.
#include <gtest/gtest.h>

#include <cstdlib>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "app_test_util.hpp"

namespace {

using stickslip::testing_util::AppTest;
using stickslip::testing_util::ReadFile;
using stickslip::testing_util::ShellQuoted;

// The text between the first '<' after `from` and the next '>' (strace -y's fd path).
std::string FdPath(const std::string& line, std::size_t from) {
  const auto a = line.find('<', from);
  const auto b = a == std::string::npos ? a : line.find('>', a);
  return b == std::string::npos ? "" : line.substr(a + 1, b - a - 1);
}

class OutputSync : public AppTest {};

TEST_F(OutputSync, FilesAreSyncedBeforeTheRenamesAndTheDirectoryAfter) {
  if (std::system("strace -V >/dev/null 2>&1") != 0) GTEST_SKIP() << "no strace";
  const std::string out = dir_ + "/o", trace = dir_ + "/trace";
  const int code =
      RunApp("/usr/bin", "strace",
             "-f -y -e trace=fsync,fdatasync,rename,renameat,renameat2 -o " + ShellQuoted(trace) +
                 " " + ShellQuoted(std::string(STICKSLIP_BIN_DIR) + "/ss_continue") + " --study " +
                 ShellQuoted(STICKSLIP_SOURCE_DIR "/studies/seed.ini") + " --no_plots --out " +
                 ShellQuoted(out));
  const std::string text = ReadFile(trace);
  if (code != 0 && text.find("rename") == std::string::npos)
    GTEST_SKIP() << "strace cannot trace here: " << err_;
  ASSERT_EQ(code, 0) << err_;
  const std::set<std::string> names = {"branch.tsv", "special_points.tsv", "bifurcation.gp"};
  std::set<std::string> synced, renamed;  // staged files synced; names renamed into out
  bool dir_synced_after_last_rename = false;
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);) {
    // Calls that returned 0 (strace pads before " = 0"; a split call's halves are skipped).
    if (line.size() < 4 || line.compare(line.size() - 4, 4, " = 0") != 0 ||
        line.find("resumed>") != std::string::npos)
      continue;
    const auto fsync = line.find("fsync("), fdatasync = line.find("fdatasync(");
    const auto call = fsync != std::string::npos ? fsync : fdatasync;
    if (call != std::string::npos) {
      const std::string path = FdPath(line, call);
      if (path == out) dir_synced_after_last_rename = renamed.size() == names.size();
      for (const auto& n : names)
        if (path.find("/.ss_continue-") != std::string::npos && path.size() > n.size() &&
            path.compare(path.size() - n.size() - 1, n.size() + 1, "/" + n) == 0) {
          EXPECT_TRUE(renamed.empty()) << "a file synced after a rename into --out: " << line;
          synced.insert(n);
        }
    } else if (line.find("rename") != std::string::npos) {
      for (const auto& n : names)
        if (line.find("\"" + out + "/" + n + "\"") != std::string::npos) {
          EXPECT_EQ(synced.size(), names.size())
              << "renamed before every file was synced: " << line;
          renamed.insert(n);
        }
    }
  }
  EXPECT_EQ(synced, names) << text;
  EXPECT_EQ(renamed, names) << text;
  EXPECT_TRUE(dir_synced_after_last_rename) << "--out not fsynced after the renames:\n" << text;
}

}  // namespace
