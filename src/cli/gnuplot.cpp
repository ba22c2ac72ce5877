#include "cli/gnuplot.hpp"

#include <fcntl.h>
#include <poll.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <csignal>
#include <cstring>

namespace stickslip::cli {

namespace {

std::string ErrnoText(int err) { return std::strerror(err); }

}  // namespace

namespace {

// The last non-empty line of a text, without trailing spaces.
std::string LastLine(const std::string& text) {
  std::size_t end = text.size();
  while (end > 0) {
    const std::size_t start = text.rfind('\n', end - 1);
    const std::size_t b = start == std::string::npos ? 0 : start + 1;
    std::string line = text.substr(b, end - b);
    while (!line.empty() && (line.back() == '\r' || line.back() == ' ')) line.pop_back();
    if (!line.empty()) return line;
    if (start == std::string::npos) break;
    end = start;
  }
  return "";
}

// Reads the child's stderr until EOF, polling `cancelled`; kills the child on
// cancel. Returns true if cancelled.
bool DrainOrCancel(int fd, pid_t pid, const std::function<bool()>& cancelled, std::string* text) {
  char buf[4096];
  bool killed = false;
  int waited_ms = 0;
  for (;;) {
    if (!killed && cancelled && cancelled()) {
      ::kill(pid, SIGTERM);
      killed = true;
    }
    if (killed && waited_ms >= 1000) ::kill(pid, SIGKILL);
    struct pollfd pfd = {fd, POLLIN, 0};
    const int ready = ::poll(&pfd, 1, 50);
    if (killed) waited_ms += 50;
    if (ready < 0 && errno != EINTR) break;
    if (ready <= 0) continue;
    const ssize_t n = ::read(fd, buf, sizeof buf);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    if (text->size() < (1u << 20)) text->append(buf, static_cast<std::size_t>(n));
  }
  return killed;
}

// The forked child: only async-signal-safe calls. An ignored SIGPIPE would
// survive exec; restore the default. Reports a failed chdir/exec through
// report_fd as {stage, errno}.
[[noreturn]] void ExecChild(char** argv, const char* dir, int err_fd, int report_fd) {
  ::signal(SIGPIPE, SIG_DFL);
  int report[2] = {0, 0};
  const int devnull = ::open("/dev/null", O_RDWR | O_CLOEXEC);
  if (devnull >= 0) {
    ::dup2(devnull, STDIN_FILENO);
    ::dup2(devnull, STDOUT_FILENO);
  }
  ::dup2(err_fd, STDERR_FILENO);
  if (dir && ::chdir(dir) != 0) {
    report[0] = 1;
    report[1] = errno;
  } else {
    ::execvp(argv[0], argv);
    report[0] = 2;
    report[1] = errno;
  }
  if (::write(report_fd, report, sizeof report) < 0) {
  }
  ::_exit(127);
}

}  // namespace

GnuplotResult RunGnuplot(const std::string& script_path, const std::string& workdir,
                         const std::function<bool()>& cancelled) {
  auto failed = [](const std::string& msg, GnuplotStatus st = GnuplotStatus::kFailed) {
    return GnuplotResult{st, msg};
  };
  std::string script = script_path;
  if (!script.empty() && script[0] != '/') {
    char cwd[4096];
    if (!::getcwd(cwd, sizeof cwd)) return failed("gnuplot: cannot get the current directory");
    script = std::string(cwd) + "/" + script;
  }
  int err_pipe[2], exec_pipe[2];
  if (::pipe2(err_pipe, O_CLOEXEC) != 0) return failed("gnuplot: pipe: " + ErrnoText(errno));
  if (::pipe2(exec_pipe, O_CLOEXEC) != 0) {
    ::close(err_pipe[0]);
    ::close(err_pipe[1]);
    return failed("gnuplot: pipe: " + ErrnoText(errno));
  }
  // Everything the child needs, prepared before fork.
  std::string prog = "gnuplot";
  char* argv[] = {prog.data(), script.data(), nullptr};
  const char* dir = workdir.empty() ? nullptr : workdir.c_str();

  const pid_t pid = ::fork();
  if (pid < 0) {
    const int e = errno;
    for (int fd : {err_pipe[0], err_pipe[1], exec_pipe[0], exec_pipe[1]}) ::close(fd);
    return failed("gnuplot: fork: " + ErrnoText(e));
  }
  if (pid == 0) ExecChild(argv, dir, err_pipe[1], exec_pipe[1]);
  ::close(err_pipe[1]);
  ::close(exec_pipe[1]);
  int report[2] = {0, 0};
  ssize_t got;
  do {
    got = ::read(exec_pipe[0], report, sizeof report);
  } while (got < 0 && errno == EINTR);
  ::close(exec_pipe[0]);
  std::string err_text;
  const bool killed = DrainOrCancel(err_pipe[0], pid, cancelled, &err_text);
  ::close(err_pipe[0]);
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) return failed("gnuplot: waitpid: " + ErrnoText(errno));
  }
  if (killed) return failed("gnuplot cancelled", GnuplotStatus::kCancelled);
  if (got == static_cast<ssize_t>(sizeof report)) {
    if (report[0] == 1)
      return failed("gnuplot: cannot enter directory '" + workdir + "': " + ErrnoText(report[1]));
    if (report[1] == ENOENT)
      return failed("gnuplot not found on PATH (install gnuplot)", GnuplotStatus::kMissing);
    return failed("cannot run gnuplot: " + ErrnoText(report[1]));
  }
  if (WIFEXITED(status) && WEXITSTATUS(status) == 0) return {};
  const std::string last = LastLine(err_text);
  std::string why = WIFEXITED(status) ? "exit code " + std::to_string(WEXITSTATUS(status))
                                      : "killed by signal " + std::to_string(WTERMSIG(status));
  return failed("gnuplot failed on '" + script_path + "' (" + why + ")" +
                (last.empty() ? "" : ": " + last));
}

bool RunGnuplot(const std::string& script_path, const std::string& workdir, std::string* error) {
  const GnuplotResult r = RunGnuplot(script_path, workdir, std::function<bool()>());
  if (!r.ok() && error) *error = r.message;
  return r.ok();
}

std::string PngError(const std::string& path) {
  static const unsigned char kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  // The IEND chunk: length 0, type, CRC.
  static const unsigned char kEnd[12] = {0, 0, 0, 0, 'I', 'E', 'N', 'D', 0xae, 0x42, 0x60, 0x82};
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return "'" + path + "': " + ErrnoText(errno);
  struct stat st;
  unsigned char head[8], tail[12];
  std::string err;
  if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
    err = "not a regular file";
  } else if (st.st_size == 0) {
    err = "empty";
  } else if (st.st_size < 20 || ::pread(fd, head, 8, 0) != 8 ||
             std::memcmp(head, kSignature, 8) != 0) {
    err = "not a PNG image";
  } else if (::pread(fd, tail, 12, st.st_size - 12) != 12 || std::memcmp(tail, kEnd, 12) != 0) {
    err = "truncated PNG image (no IEND chunk at the end)";
  }
  ::close(fd);
  return err.empty() ? "" : "'" + path + "': " + err;
}

namespace {
// The first `n` and the last `n` bytes of a regular file (fewer if shorter);
// an error text if it cannot be read, is not regular or is empty.
std::string HeadTail(const std::string& path, std::size_t n, std::string* head, std::string* tail) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return ErrnoText(errno);
  struct stat st;
  std::string err;
  if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
    err = "not a regular file";
  } else if (st.st_size == 0) {
    err = "empty";
  } else {
    const std::size_t size = static_cast<std::size_t>(st.st_size), k = std::min(n, size);
    head->assign(k, '\0');
    tail->assign(k, '\0');
    if (::pread(fd, head->data(), k, 0) != static_cast<ssize_t>(k) ||
        ::pread(fd, tail->data(), k, static_cast<off_t>(size - k)) != static_cast<ssize_t>(k))
      err = "cannot be read";
  }
  ::close(fd);
  return err;
}

// `text` without trailing white space.
std::string TrimEnd(std::string text) {
  while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back()))) text.pop_back();
  return text;
}

bool EndsWith(const std::string& text, const std::string& end) {
  return text.size() >= end.size() && text.compare(text.size() - end.size(), end.size(), end) == 0;
}
}  // namespace

std::string PdfError(const std::string& path) {
  std::string head, tail;
  std::string err = HeadTail(path, 64, &head, &tail);
  if (err.empty() && head.compare(0, 5, "%PDF-") != 0) err = "not a PDF document";
  if (err.empty() && !EndsWith(TrimEnd(tail), "%%EOF"))
    err = "truncated PDF document (no %%EOF at the end)";
  return err.empty() ? "" : "'" + path + "': " + err;
}

std::string SvgError(const std::string& path) {
  std::string head, tail;
  std::string err = HeadTail(path, 256, &head, &tail);
  if (err.empty() && head.compare(0, 5, "<?xml") != 0 && head.compare(0, 4, "<svg") != 0)
    err = "not an SVG image";
  if (err.empty() && !EndsWith(TrimEnd(tail), "</svg>"))
    err = "truncated SVG image (no </svg> at the end)";
  return err.empty() ? "" : "'" + path + "': " + err;
}

std::string FigureError(const std::string& path) {
  if (EndsWith(path, ".pdf")) return PdfError(path);
  if (EndsWith(path, ".svg")) return SvgError(path);
  return PngError(path);
}

}  // namespace stickslip::cli
