#include "stickslip/io/report.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>

#include "numerics/numbers.hpp"
#include "numerics/tolerances.hpp"
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

void WriteFileAtomically(const std::string& path, const std::string& content,
                         Durability durability) {
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
  for (int attempt = 0; attempt < Tolerances::kTempFileAttempts && fd < 0; ++attempt) {
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
  if (durability == Durability::kSynced && ::fsync(fd) != 0 && errno != EINVAL)
    abandon("flushing", errno);
  const int closed = ::close(fd);
  fd = -1;
  if (closed != 0) abandon("closing", errno);
  if (::rename(tmp.c_str(), path.c_str()) != 0) abandon("renaming the temporary file", errno);
}

void SyncFiles(const std::vector<std::string>& paths) {
  std::vector<int> fds;
  auto close_all = [&] {
    for (int fd : fds) ::close(fd);
  };
  auto fail = [&](const std::string& path, const std::string& what, int err) {
    close_all();
    throw Error("cannot sync '" + path + "': " + ErrnoText(err) + " (" + what + ")");
  };
  for (const auto& path : paths) {
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) fail(path, "opening", errno);
    fds.push_back(fd);
#ifdef SYNC_FILE_RANGE_WRITE
    // Starts writeback without waiting: the fsyncs below then find the data of
    // every file on its way and the blocks of all of them allocated, so the
    // first fsync's journal commit carries the whole set.
    ::sync_file_range(fd, 0, 0, SYNC_FILE_RANGE_WRITE);
#endif
  }
  for (std::size_t i = 0; i < fds.size(); ++i)
    if (::fsync(fds[i]) != 0 && errno != EINVAL) fail(paths[i], "flushing", errno);
  close_all();
}

std::string FormatNumber(double x) { return RoundTrip(x); }

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
    if (!cells[i].finite())  // no nan or inf is written (an empty cell: does not apply)
      throw InvalidArgument("TsvTable: " + cells[i].text() + " in column '" + columns_[i] +
                            "', row " + std::to_string(rows_ + 1) + ": not a finite number");
  }
  for (std::size_t i = 0; i < cells.size(); ++i) {
    if (i > 0) body_ += '\t';
    body_ += cells[i].text();
  }
  body_ += '\n';
  ++rows_;
}

std::string TsvTable::str() const {
  std::string out;
  std::size_t size = body_.size() + 1;
  for (const auto& c : comments_) size += c.size() + 3;
  for (const auto& c : columns_) size += c.size() + 1;
  out.reserve(size);  // one allocation, no copies as it grows
  for (const auto& c : comments_) out += "# " + c + "\n";
  for (std::size_t i = 0; i < columns_.size(); ++i) {
    if (i > 0) out += '\t';
    out += columns_[i];
  }
  return out + '\n' + body_;
}

}  // namespace stickslip
