#include "stickslip/report.hpp"

#include <fcntl.h>
#include <poll.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <csignal>
#include <cstring>

#include "stickslip/errors.hpp"

namespace stickslip {

namespace {

std::string ErrnoText(int err) { return std::strerror(err); }

// Directory part and file part of a path ("." if there is no slash).
void SplitPath(const std::string& path, std::string* dir, std::string* base) {
  const auto slash = path.find_last_of('/');
  if (slash == std::string::npos) {
    *dir = ".";
    *base = path;
  } else {
    *dir = slash == 0 ? "/" : path.substr(0, slash);
    *base = path.substr(slash + 1);
  }
}

bool HasControl(const std::string& s) { return s.find_first_of("\t\n\r") != std::string::npos; }

}  // namespace

void WriteFileAtomically(const std::string& path, const std::string& content) {
  std::string dir, base;
  SplitPath(path, &dir, &base);
  if (base.empty() || base == "." || base == "..")
    throw InvalidArgument("cannot write '" + path + "': not a file name");
  auto fail = [&](const std::string& what, int err) {
    throw Error("cannot write '" + path + "': " + ErrnoText(err) + " (" + what + ")");
  };

  // A fresh name beside the target: hidden, unique per process and call.
  static std::atomic<unsigned long> counter{0};
  std::string tmp;
  int fd = -1;
  for (int attempt = 0; attempt < 100 && fd < 0; ++attempt) {
    tmp = (dir == "/" ? "" : dir) + "/." + base + ".tmp-" + std::to_string(::getpid()) + "-" +
          std::to_string(counter++);
    fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd < 0 && errno != EEXIST) fail("creating a temporary file in '" + dir + "'", errno);
  }
  if (fd < 0) fail("creating a temporary file in '" + dir + "'", EEXIST);

  auto abandon = [&](const std::string& what, int err) {
    if (fd >= 0) ::close(fd);
    ::unlink(tmp.c_str());
    fail(what, err);
  };
  const char* p = content.data();
  std::size_t left = content.size();
  while (left > 0) {
    const ssize_t n = ::write(fd, p, left);
    if (n < 0) {
      if (errno == EINTR) continue;
      abandon("writing", errno);
    }
    p += n;
    left -= static_cast<std::size_t>(n);
  }
  if (::fsync(fd) != 0 && errno != EINVAL) abandon("flushing", errno);
  const int closed = ::close(fd);
  fd = -1;
  if (closed != 0) abandon("closing", errno);
  if (::rename(tmp.c_str(), path.c_str()) != 0) abandon("renaming the temporary file", errno);
}

std::string FormatNumber(double x) {
  if (std::isnan(x)) return "nan";
  if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, x);  // shortest round trip
  return std::string(buf, r.ptr);
}

TsvTable::TsvTable(std::vector<std::string> columns) : columns_(std::move(columns)) {
  if (columns_.empty()) throw InvalidArgument("TsvTable: no columns");
  for (const auto& c : columns_)
    if (c.empty() || HasControl(c)) throw InvalidArgument("TsvTable: bad column name '" + c + "'");
}

void TsvTable::AddComment(const std::string& text) {
  if (text.find_first_of("\n\r") != std::string::npos)
    throw InvalidArgument("TsvTable: comment has a line break");
  comments_.push_back(text);
}

void TsvTable::AddMeta(const std::string& key, const std::string& value) {
  if (key.empty() || key.find(':') != std::string::npos)
    throw InvalidArgument("TsvTable: bad metadata key '" + key + "'");
  AddComment(key + ": " + value);
}

void TsvTable::PrependMeta(const std::vector<std::pair<std::string, std::string>>& lines) {
  std::vector<std::string> old;
  old.swap(comments_);
  for (const auto& [key, value] : lines) AddMeta(key, value);
  comments_.insert(comments_.end(), old.begin(), old.end());
}

void TsvTable::AddRow(const std::vector<Cell>& cells) {
  if (cells.size() != columns_.size())
    throw InvalidArgument("TsvTable: row has " + std::to_string(cells.size()) +
                          " cells, table has " + std::to_string(columns_.size()) + " columns");
  for (std::size_t i = 0; i < cells.size(); ++i) {
    if (cells[i].is_text() && HasControl(cells[i].text()))
      throw InvalidArgument("TsvTable: cell in column '" + columns_[i] +
                            "' has a tab or line break");
    if (i > 0) body_ += '\t';
    body_ += cells[i].text();
  }
  body_ += '\n';
  ++rows_;
}

std::string TsvTable::str() const {
  std::string out;
  for (const auto& c : comments_) out += "# " + c + "\n";
  for (std::size_t i = 0; i < columns_.size(); ++i) {
    if (i > 0) out += '\t';
    out += columns_[i];
  }
  return out + '\n' + body_;
}

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
  if (pid == 0) {
    // Child: only async-signal-safe calls. An ignored SIGPIPE would survive
    // exec; restore the default. Report a failed chdir/exec through
    // exec_pipe as {stage, errno}.
    ::signal(SIGPIPE, SIG_DFL);
    int report[2] = {0, 0};
    const int devnull = ::open("/dev/null", O_RDWR | O_CLOEXEC);
    if (devnull >= 0) {
      ::dup2(devnull, STDIN_FILENO);
      ::dup2(devnull, STDOUT_FILENO);
    }
    ::dup2(err_pipe[1], STDERR_FILENO);
    if (dir && ::chdir(dir) != 0) {
      report[0] = 1;
      report[1] = errno;
    } else {
      ::execvp(argv[0], argv);
      report[0] = 2;
      report[1] = errno;
    }
    if (::write(exec_pipe[1], report, sizeof report) < 0) {
    }
    ::_exit(127);
  }
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

}  // namespace stickslip
