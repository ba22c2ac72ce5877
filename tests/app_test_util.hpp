// Small file helpers shared by the end-to-end tests of the apps.
#pragma once

#include <dirent.h>
#include <fcntl.h>
#include <grp.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "wall_bound.hpp"

namespace stickslip::testing_util {

// Whether gnuplot runs here (figure tests skip without it).
inline bool HaveGnuplot() { return std::system("gnuplot --version >/dev/null 2>&1") == 0; }

inline ::testing::AssertionResult Contains(const std::string& text, const std::string& part) {
  if (text.find(part) != std::string::npos) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "'" << text << "' does not contain '" << part << "'";
}

inline bool Exists(const std::string& path) {
  struct stat st;
  return ::stat(path.c_str(), &st) == 0;
}

inline std::string ReadFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream os;
  os << in.rdbuf();
  return os.str();
}

inline void WriteFile(const std::string& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

// A self-describing TSV (report.hpp): "# key: value" lines, then the header
// line (no '#'), then rows; read the way csv.DictReader reads it after the
// '#' lines are dropped.
struct Tsv {
  std::vector<std::string> comments;        // whole '#' lines
  std::map<std::string, std::string> meta;  // "# key: value" lines
  std::vector<std::string> columns;         // the first line without '#'
  std::vector<std::vector<std::string>> rows;
  int Column(const std::string& name) const {
    for (size_t i = 0; i < columns.size(); ++i)
      if (columns[i] == name) return static_cast<int>(i);
    return -1;
  }
};

inline std::vector<std::string> SplitTabs(const std::string& line) {
  std::vector<std::string> cells;
  std::istringstream is(line);
  for (std::string cell; std::getline(is, cell, '\t');) cells.push_back(cell);
  if (!line.empty() && line.back() == '\t') cells.push_back("");
  return cells;
}

// The lines of a TSV's text that are not '#' lines: its header and cells (a
// check for "nan" must not see the metadata's paths, e.g. a checkout's).
inline std::string DataLines(const std::string& text) {
  std::istringstream is(text);
  std::string out;
  for (std::string line; std::getline(is, line);)
    if (line.rfind("#", 0) != 0) out += line + "\n";
  return out;
}

inline Tsv ReadTsv(const std::string& text) {
  Tsv t;
  std::istringstream is(text);
  for (std::string line; std::getline(is, line);) {
    if (!line.empty() && line[0] == '#') {
      t.comments.push_back(line);
      const auto colon = line.find(": ");
      if (line.rfind("# ", 0) == 0 && colon != std::string::npos)
        t.meta[line.substr(2, colon - 2)] = line.substr(colon + 2);
    } else if (t.columns.empty()) {
      t.columns = SplitTabs(line);
    } else {
      t.rows.push_back(SplitTabs(line));
    }
  }
  return t;
}

// Names in a directory, "." and ".." left out.
inline std::set<std::string> Listing(const std::string& dir) {
  std::set<std::string> names;
  if (DIR* d = ::opendir(dir.c_str())) {
    while (const dirent* e = ::readdir(d)) {
      const std::string n = e->d_name;
      if (n != "." && n != "..") names.insert(n);
    }
    ::closedir(d);
  }
  return names;
}

// A shell word: s in single quotes.
inline std::string ShellQuoted(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

// How to run an app in a child process.
struct Launch {
  std::string out_path = "/dev/null", err_path = "/dev/null";  // stdout, stderr
  bool closed_stdout = false;  // stdout: a pipe whose reading end is closed
  double timeout = 120;        // then SIGKILL
  int signal = 0;              // sent signal_after seconds after the start
  double signal_after = 0;
  long fsize_limit = -1;  // RLIMIT_FSIZE in bytes, with SIGXFSZ at its default
  std::string path_env;   // PATH for the child, if not empty
  // Count signal_after from the moment the child catches `signal` (its
  // handler installed; or from 5 s if that cannot be seen): a signal sent
  // earlier would just kill it.
  bool signal_when_caught = false;
  int run_as = -1;  // as root: the child drops to this user and group id first
};

// Whether a process has a handler for signal sig: the SigCgt mask of
// /proc/PID/status (Linux). False if that cannot be read.
inline bool CatchesSignal(pid_t pid, int sig) {
  std::ifstream in("/proc/" + std::to_string(pid) + "/status");
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("SigCgt:", 0) != 0) continue;
    const unsigned long long mask = std::strtoull(line.c_str() + 7, nullptr, 16);
    return (mask >> (sig - 1)) & 1;
  }
  return false;
}

struct Outcome {
  int code = -1;   // exit status, -1 if ended by a signal
  int signal = 0;  // the signal that ended it
  bool timed_out = false;
  double seconds = 0;
  pid_t pid = 0;
};

// Starts app with args; returns at once with the pid (Outcome::pid), see Wait.
inline pid_t Start(const std::string& app, const std::vector<std::string>& args, const Launch& l) {
  std::vector<std::string> argv_s = {app};
  argv_s.insert(argv_s.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (auto& a : argv_s) argv.push_back(a.data());
  argv.push_back(nullptr);
  int pipe_fds[2] = {-1, -1};
  if (l.closed_stdout && ::pipe(pipe_fds) != 0) return -1;
  const pid_t pid = ::fork();
  if (pid == 0) {  // only async-signal-safe calls until exec
    const int out = l.closed_stdout
                        ? pipe_fds[1]
                        : ::open(l.out_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const int err = ::open(l.err_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (out < 0 || err < 0 || ::dup2(out, 1) < 0 || ::dup2(err, 2) < 0) ::_exit(126);
    if (l.closed_stdout) ::close(pipe_fds[0]);
    if (l.fsize_limit >= 0) {
      struct rlimit lim = {static_cast<rlim_t>(l.fsize_limit), static_cast<rlim_t>(l.fsize_limit)};
      if (::setrlimit(RLIMIT_FSIZE, &lim) != 0) ::_exit(125);
    }
    if (!l.path_env.empty()) ::setenv("PATH", l.path_env.c_str(), 1);
    if (l.run_as >= 0 &&
        (::setgroups(0, nullptr) != 0 || ::setgid(l.run_as) != 0 || ::setuid(l.run_as) != 0))
      ::_exit(125);
    for (int s : {SIGINT, SIGTERM, SIGPIPE, SIGXFSZ}) ::signal(s, SIG_DFL);
    ::execv(argv[0], argv.data());
    ::_exit(127);
  }
  if (l.closed_stdout) {
    ::close(pipe_fds[0]);
    ::close(pipe_fds[1]);
  }
  return pid;
}

// Waits for a started child, sending l.signal on time and SIGKILL at l.timeout.
inline Outcome Wait(pid_t pid, const Launch& l) {
  Outcome r;
  r.pid = pid;
  const auto start = std::chrono::steady_clock::now();
  bool sent = false, armed = !l.signal_when_caught;
  double armed_at = 0;
  int status = 0;
  for (;;) {
    if (::waitpid(pid, &status, WNOHANG) == pid) break;
    const double t =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (l.signal != 0 && !armed && (CatchesSignal(pid, l.signal) || t > 5.0)) {
      armed = true;
      armed_at = t;
    }
    if (l.signal != 0 && armed && !sent && t >= armed_at + l.signal_after) {
      ::kill(pid, l.signal);
      sent = true;
    }
    if (t > l.timeout) {
      ::kill(pid, SIGKILL);
      ::waitpid(pid, &status, 0);
      r.timed_out = true;
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (WIFEXITED(status)) r.code = WEXITSTATUS(status);
  if (WIFSIGNALED(status)) r.signal = WTERMSIG(status);
  return r;
}

inline Outcome RunChild(const std::string& app, const std::vector<std::string>& args,
                        const Launch& l) {
  const pid_t pid = Start(app, args, l);
  if (pid < 0) {
    ADD_FAILURE() << "fork failed";
    return {};
  }
  return Wait(pid, l);
}

// The fixture of the apps' end-to-end tests: a fresh directory per test
// (dir_), removed after it, and RunApp, which runs an app of the build tree
// through the shell with stdout and stderr captured into out_ and err_
// (RunOut: without a shell, with --out and --no_plots).
class AppTest : public ::testing::Test {
 protected:
  void SetUp() override {
    std::string tmpl = ::testing::TempDir() + "ss_app_test_XXXXXX";
    ASSERT_NE(::mkdtemp(tmpl.data()), nullptr);
    dir_ = tmpl;
  }
  void TearDown() override {
    if (!dir_.empty()) {
      EXPECT_EQ(std::system(("rm -rf " + ShellQuoted(dir_)).c_str()), 0);
    }
  }
  // Runs `bin_dir/app args` (args: shell words) under `timeout -s signal
  // seconds` (--preserve-status: a signal's exit code is the app's own);
  // returns its exit code, -1 if it ended by a signal.
  int RunApp(const std::string& bin_dir, const std::string& app, const std::string& args,
             const std::string& signal = "KILL", int seconds = 300) {
    const std::string cmd = "timeout --preserve-status -s " + signal + " " +
                            std::to_string(seconds) + " " + ShellQuoted(bin_dir + "/" + app) + " " +
                            args + " >" + ShellQuoted(dir_ + "/stdout") + " 2>" +
                            ShellQuoted(dir_ + "/stderr");
    const int status = std::system(cmd.c_str());
    out_ = ReadFile(dir_ + "/stdout");
    err_ = ReadFile(dir_ + "/stderr");
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  }
  // A fresh directory under dir_, for each run of a test that runs apps
  // more than once.
  std::string NewDir() {
    const std::string d = dir_ + "/run" + std::to_string(++runs_);
    EXPECT_EQ(::mkdir(d.c_str(), 0755), 0) << d;
    return d;
  }
  struct AppRun {
    Outcome outcome;
    std::string out, err;
  };
  // Runs the app `app` of the build tree (no shell) with argv words args, then
  // "--out dir/out" and --no_plots (unless plots); stdout and stderr go to
  // dir/stdout and dir/stderr and into the result.
  AppRun RunOut(const std::string& app, const std::string& dir, std::vector<std::string> args,
                bool plots = false) {
    Launch l;
    l.out_path = dir + "/stdout", l.err_path = dir + "/stderr";
    args.insert(args.end(), {"--out", dir + "/out"});
    if (!plots) args.push_back("--no_plots");
    AppRun r;
    r.outcome = RunChild(std::string(STICKSLIP_BIN_DIR) + "/" + app, args, l);
    r.out = ReadFile(l.out_path), r.err = ReadFile(l.err_path);
    return r;
  }
  std::string dir_, out_, err_;

 private:
  int runs_ = 0;
};

}  // namespace stickslip::testing_util
