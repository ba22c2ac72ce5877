#include "cli/output.hpp"

#include <dirent.h>
#include <fcntl.h>
#include <limits.h>
#include <signal.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>

#include "cli/study.hpp"
#include "stickslip/errors.hpp"
#include "stickslip/io/figure_style.hpp"
#include "stickslip/io/report.hpp"

namespace stickslip::cli {

namespace {

constexpr std::size_t kStagingLength = 40;   // "/.<prog>-<pid>-XXXXXX/", prog kept short
constexpr std::size_t kTempNameLength = 32;  // ".<name>.tmp-<pid>-<counter>" beyond name

bool HasControl(const std::string& s) {
  return std::any_of(s.begin(), s.end(), [](char c) { return static_cast<unsigned char>(c) < 32; });
}

std::string Parent(const std::string& dir) {
  std::string d = dir;
  while (d.size() > 1 && d.back() == '/') d.pop_back();
  const auto slash = d.find_last_of('/');
  if (slash == std::string::npos) return ".";
  return slash == 0 ? "/" : d.substr(0, slash);
}

// A writable, searchable directory, or the reason it is not.
std::string DirectoryProblem(const std::string& dir) {
  struct stat st;
  if (::stat(dir.c_str(), &st) != 0) return std::strerror(errno);
  if (!S_ISDIR(st.st_mode)) return "not a directory";
  if (::access(dir.c_str(), W_OK | X_OK) != 0)
    return std::string("not writable: ") + std::strerror(errno);
  return "";
}

}  // namespace

const std::vector<std::string>& KnownOutputNames() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> n = {"branch.tsv",
                                  "special_points.tsv",
                                  "bifurcation.gp",
                                  "resonance.gp",  // an older version's forced figure
                                  "curves.tsv",
                                  "codim2.tsv",
                                  "regions.tsv",
                                  "chart.gp",
                                  "response.tsv",
                                  "forced_chart.gp",  // an older version's forced chart
                                  "basins.tsv",
                                  "orbits.tsv",
                                  "basins.gp",
                                  "basins_forced.tsv",
                                  "attractors.tsv",
                                  "basins_forced.gp",
                                  "basin_stability.tsv",
                                  "basin_stability.gp",
                                  "trajectory.tsv",
                                  "section.tsv",
                                  "trajectory.gp",
                                  "orbit_diagram.tsv",
                                  "lyapunov.tsv",
                                  "orbit_diagram.gp",
                                  "orbits.gp"};
    for (const char* stem :
         {"bifurcation_x", "bifurcation_xdot", "period", "multiplier", "estimates", "resonance",
          "chart", "forced_chart", "basins", "basins_forced", "basin_stability", "trajectory",
          "section", "orbit_diagram", "orbits"})
      for (FigureFormat f : {FigureFormat::kPng, FigureFormat::kPdf, FigureFormat::kSvg})
        n.push_back(FigureFile(stem, f));
    return n;
  }();
  return names;
}

OutputSet::OutputSet(std::string dir, std::vector<std::string> names, const std::string& source,
                     const std::string& prog)
    : dir_(std::move(dir)), names_(std::move(names)), prog_(prog.substr(0, 16)) {
  auto bad = [&](const std::string& why) {
    return UsageError("invalid value '" + dir_ + "' for " + source + ": " + why);
  };
  if (dir_.empty()) throw bad("empty");
  if (HasControl(dir_)) throw bad("a line break or control character in the path");
  struct stat st;
  if (::stat(dir_.c_str(), &st) == 0) {
    const std::string why = DirectoryProblem(dir_);
    if (!why.empty()) throw bad(why);
  } else if (errno == ENOENT) {
    const std::string why = DirectoryProblem(Parent(dir_));
    if (!why.empty()) throw bad("cannot create it in '" + Parent(dir_) + "': " + why);
  } else {
    throw bad(std::strerror(errno));
  }
  for (const auto& name : names_) CheckName(name, source);
}

void OutputSet::CheckName(const std::string& name, const std::string& source) const {
  const std::string path = dir_ + "/" + name;
  auto bad = [&](const std::string& why) {
    return UsageError("cannot write '" + path + "' (from " + source + "): " + why);
  };
  if (name.empty() || name.find('/') != std::string::npos || HasControl(name) || name == "." ||
      name == "..")
    throw bad("not a plain file name");
  // Room for the temporary name of the atomic write, ".<name>.tmp-<pid>-<n>".
  if (name.size() + kTempNameLength > NAME_MAX)
    throw bad("file name longer than " + std::to_string(NAME_MAX - kTempNameLength) + " bytes");
  if (path.size() + kStagingLength + kTempNameLength >= PATH_MAX)
    throw bad("path longer than " + std::to_string(PATH_MAX - kStagingLength - kTempNameLength) +
              " bytes");
  struct stat st;
  if (::lstat(path.c_str(), &st) != 0) {
    if (errno == ENOENT) return;
    throw bad(std::strerror(errno));
  }
  if (S_ISREG(st.st_mode)) return;
  if (S_ISLNK(st.st_mode)) throw bad("a symbolic link stands there (never followed nor replaced)");
  if (S_ISDIR(st.st_mode)) throw bad("a directory stands there");
  throw bad("not a regular file (device, FIFO or socket); only regular files are replaced");
}

OutputSet::~OutputSet() { Discard(); }

void OutputSet::Discard() {
  if (staging_.empty()) return;
  for (const auto& name : staged_) ::unlink((staging_ + "/" + name).c_str());
  // Anything else a failed gnuplot left behind.
  if (DIR* d = ::opendir(staging_.c_str())) {
    while (const dirent* e = ::readdir(d)) {
      const std::string n = e->d_name;
      if (n != "." && n != "..") ::unlink((staging_ + "/" + n).c_str());
    }
    ::closedir(d);
  }
  ::rmdir(staging_.c_str());
  staged_.clear();
  staging_.clear();
}

// Removes the staging directories `.<prog>-<pid>-XXXXXX` in dir whose
// process is gone (a run killed by SIGKILL or a power cut leaves one).
void OutputSet::SweepLeftovers() const {
  DIR* d = ::opendir(dir_.c_str());
  if (!d) return;
  const std::string prefix = "." + prog_ + "-";
  std::vector<std::string> dead;
  while (const dirent* e = ::readdir(d)) {
    const std::string n = e->d_name;
    if (n.compare(0, prefix.size(), prefix) != 0) continue;
    char* end = nullptr;
    const long pid = std::strtol(n.c_str() + prefix.size(), &end, 10);
    if (pid <= 0 || *end != '-' || std::strlen(end) != 7) continue;
    if (::kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH) dead.push_back(n);
  }
  ::closedir(d);
  for (const auto& n : dead) {
    const std::string path = dir_ + "/" + n;
    struct stat st;
    if (::lstat(path.c_str(), &st) != 0 || !S_ISDIR(st.st_mode)) continue;
    if (DIR* s = ::opendir(path.c_str())) {
      while (const dirent* e = ::readdir(s)) {
        const std::string f = e->d_name;
        if (f != "." && f != "..") ::unlink((path + "/" + f).c_str());
      }
      ::closedir(s);
    }
    ::rmdir(path.c_str());
  }
}

std::string OutputSet::Staging() {
  if (!staging_.empty()) return staging_;
  if (::mkdir(dir_.c_str(), 0777) != 0 && errno != EEXIST)
    throw Error("cannot create '" + dir_ + "': " + std::strerror(errno));
  SweepLeftovers();
  std::string templ = dir_ + "/." + prog_ + "-" + std::to_string(::getpid()) + "-XXXXXX";
  if (::mkdtemp(templ.data()) == nullptr)
    throw Error("cannot create a staging directory in '" + dir_ + "': " + std::strerror(errno));
  staging_ = templ;
  return staging_;
}

void OutputSet::Write(const std::string& name, const std::string& content) {
  if (std::find(names_.begin(), names_.end(), name) == names_.end())
    throw InvalidArgument("OutputSet: '" + name + "' was not declared");
  const std::string path = Staging() + "/" + name;
  try {
    WriteFileAtomically(path, content, Durability::kDeferred);  // synced in Commit
  } catch (const Error& e) {
    throw Error("cannot write '" + dir_ + "/" + name + "': " + e.what());
  }
  if (std::find(staged_.begin(), staged_.end(), name) == staged_.end()) staged_.push_back(name);
}

namespace {
// gnuplot's svg terminal puts the text after a subscript in a tspan of its
// own, whose leading space renderers drop ("μs= 0.4"); xml:space="preserve"
// on the root keeps it (gnuplot writes each text element on one line).
void PreserveSvgSpaces(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  std::string s = text.str();
  const auto at = s.find("<svg");
  if (at == std::string::npos || s.find("xml:space", at) < s.find('>', at)) return;
  s.insert(at + 4, " xml:space=\"preserve\"");
  WriteFileAtomically(path, s, Durability::kDeferred);  // synced in Commit
}
}  // namespace

std::string OutputSet::Read(const std::string& name) {
  if (std::find(staged_.begin(), staged_.end(), name) == staged_.end())
    throw Error("OutputSet: '" + name + "' was not written");
  std::ifstream in(Staging() + "/" + name, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  if (!in && !in.eof()) throw Error("cannot read '" + dir_ + "/" + name + "'");
  return text.str();
}

GnuplotResult OutputSet::Draw(const std::string& script, const std::vector<std::string>& figures,
                              const std::function<bool()>& cancelled) {
  GnuplotResult r = RunGnuplot(Staging() + "/" + script, Staging(), cancelled);
  for (const auto& f : figures) {
    if (!r.ok()) break;
    const std::string err = FigureError(Staging() + "/" + f);
    if (!err.empty())
      r = {GnuplotStatus::kFailed,
           "figure " + f + " not drawn whole (disk full?): " + err.substr(err.find("': ") + 3)};
    else if (f.size() > 4 && f.compare(f.size() - 4, 4, ".svg") == 0)
      try {
        PreserveSvgSpaces(Staging() + "/" + f);
      } catch (const Error& e) {
        r = {GnuplotStatus::kFailed, "figure " + f + ": " + e.what()};
      }
  }
  for (const auto& f : figures) {
    if (r.ok()) {
      if (std::find(staged_.begin(), staged_.end(), f) == staged_.end()) staged_.push_back(f);
    } else {
      ::unlink((Staging() + "/" + f).c_str());
    }
  }
  return r;
}

void OutputSet::Commit(const std::vector<std::string>& stale) {
  const std::string where = Staging();
  // Durable as a set: every staged file's data first (together: one journal
  // commit), then the renames, then the directory once (docs/reliability.md).
  std::vector<std::string> staged_paths;
  for (const auto& name : staged_) staged_paths.push_back(where + "/" + name);
  try {
    SyncFiles(staged_paths);
  } catch (const Error& e) {
    throw Error("cannot write into '" + dir_ + "': " + e.what());
  }
  const int lock = ::open(dir_.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (lock < 0) throw Error("cannot open '" + dir_ + "': " + std::strerror(errno));
  while (::flock(lock, LOCK_EX) != 0 && errno == EINTR) {
  }
  std::string error;
  for (const auto& name : staged_) {
    const std::string from = where + "/" + name, to = dir_ + "/" + name;
    if (error.empty() && ::rename(from.c_str(), to.c_str()) != 0)
      error = "cannot move '" + name + "' into '" + dir_ + "': " + std::strerror(errno);
  }
  // Stale beside this set: `stale`, and every file an app of this project
  // writes that this run did not (another app's, another mode's or another
  // --format's); regular files only, a symlink is never followed.
  std::vector<std::string> remove = stale;
  for (const auto& name : KnownOutputNames())
    if (std::find(staged_.begin(), staged_.end(), name) == staged_.end()) remove.push_back(name);
  if (error.empty()) staged_.clear();
  for (const auto& name : remove) {
    if (!error.empty()) break;
    const std::string path = dir_ + "/" + name;
    struct stat st;
    if (::lstat(path.c_str(), &st) == 0 && S_ISREG(st.st_mode)) ::unlink(path.c_str());
  }
  // The renames and removals are durable once the directory is synced.
  if (error.empty() && ::fsync(lock) != 0 && errno != EINVAL)
    error = "cannot sync '" + dir_ + "': " + std::strerror(errno);
  ::close(lock);  // releases the lock
  if (!error.empty()) throw Error(error);
  Discard();  // the staging directory, now empty
}

}  // namespace stickslip::cli
