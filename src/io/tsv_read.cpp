// A TSV read back for a restart (tsv_read.hpp).
#include "io/tsv_read.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <sstream>

namespace stickslip::io_detail {

namespace {

using Part = RestartError::Part;

// The most flow steps per run a restart reads back (a sanity bound, 2^40).
constexpr long long kMaxFlowSteps = 1LL << 40;

std::vector<std::string> Split(const std::string& line) {
  std::vector<std::string> cells;
  std::size_t a = 0;
  for (std::size_t b; (b = line.find('\t', a)) != std::string::npos; a = b + 1)
    cells.push_back(line.substr(a, b - a));
  cells.push_back(line.substr(a));
  return cells;
}

// The whole file, if it is a regular file of at most kMaxFileBytes: a FIFO is
// opened without blocking and refused, as are devices (/dev/zero) and sockets.
std::string Slurp(const std::string& path) {
  auto fail = [&path](const std::string& why) {
    return RestartError(Part::kRun, "cannot read '" + path + "': " + why);
  };
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) throw fail(std::strerror(errno));
  struct Closer {
    int fd;
    ~Closer() { ::close(fd); }
  } closer{fd};
  struct stat st;
  if (::fstat(fd, &st) != 0) throw fail(std::strerror(errno));
  if (S_ISDIR(st.st_mode)) throw fail("it is a directory");
  if (!S_ISREG(st.st_mode)) throw fail("not a regular file (FIFO, device or socket)");
  constexpr long long kMax = LabelledPoint::kMaxFileBytes;
  const std::string cap = std::to_string(kMax) + " bytes (64 MiB)";
  if (st.st_size > kMax) throw fail(std::to_string(st.st_size) + " bytes, more than " + cap);
  std::string text;
  char buf[65536];
  for (ssize_t got; (got = ::read(fd, buf, sizeof buf)) != 0;) {
    if (got < 0) {
      if (errno == EINTR) continue;
      throw fail(std::strerror(errno));
    }
    text.append(buf, static_cast<size_t>(got));
    if (static_cast<long long>(text.size()) > kMax)
      throw fail("it grew past " + cap + " while read");
  }
  return text;
}

}  // namespace

int Table::Column(const std::string& name) const {
  for (std::size_t j = 0; j < header.size(); ++j)
    if (header[j] == name) return static_cast<int>(j);
  throw RestartError(Part::kRun, "'" + path + "' has no column '" + name +
                                     "' (written before labelled points? run ss_continue again)");
}

const std::string& Table::Meta(const std::string& key) const {
  const auto it = meta.find(key);
  if (it == meta.end())
    throw RestartError(Part::kRun, "'" + path + "' has no '# " + key + ":' line");
  return it->second;
}

double Table::Number(const std::string& text, const std::string& what) const {
  char* end = nullptr;
  errno = 0;
  const double x = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0' || errno == ERANGE)
    throw RestartError(Part::kRun,
                       "'" + path + "' is corrupt: " + what + " = '" + text + "' is no number");
  return x;
}

double Table::Finite(const std::string& text, const std::string& what) const {
  const double x = Number(text, what);
  if (!std::isfinite(x))
    throw RestartError(Part::kRun,
                       "'" + path + "' is corrupt: " + what + " = '" + text + "' is not finite");
  return x;
}

long long Table::Whole(const std::string& text, const std::string& what, long long lo,
                       long long hi) const {
  const double x = Number(text, what);
  // lo and hi are exact in a double for the bounds used (at most 2^53).
  if (!(x >= static_cast<double>(lo) && x <= static_cast<double>(hi) && x == std::floor(x)))
    throw RestartError(Part::kRun, "'" + path + "' is corrupt: " + what + " = '" + text +
                                       "' is not a whole number from " + std::to_string(lo) +
                                       " to " + std::to_string(hi));
  return static_cast<long long>(x);
}

Table ReadTable(const std::string& path) {
  std::istringstream in(Slurp(path));
  Table t;
  t.path = path;
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("#", 0) == 0) {
      const auto colon = line.find(": ");
      if (colon != std::string::npos && t.header.empty())
        t.meta.emplace(line.substr(2, colon - 2), line.substr(colon + 2));
    } else if (t.header.empty()) {
      t.header = Split(line);
    } else if (!line.empty()) {
      t.rows.push_back(Split(line));
      if (t.rows.back().size() != t.header.size())
        throw RestartError(Part::kRun, "'" + path + "' is corrupt: row " +
                                           std::to_string(t.rows.size()) + " has " +
                                           std::to_string(t.rows.back().size()) + " cells for " +
                                           std::to_string(t.header.size()) + " columns");
    }
  }
  if (t.header.empty()) throw RestartError(Part::kRun, "'" + path + "' has no header line");
  return t;
}

FlowOptions ReadFlowOptions(const Table& t) {
  FlowOptions flow;
  const std::string integrator = t.Meta("integrator");
  if (integrator == "taylor") {
    flow.integrator = Integrator::kTaylor;
  } else if (integrator == "cvode adams" || integrator == "cvode bdf") {
    flow.integrator = Integrator::kCvode;
    flow.method = integrator == "cvode bdf" ? Method::kBdf : Method::kAdams;
  } else {
    throw RestartError(Part::kRun, "'" + t.path + "': unknown integrator '" + integrator + "'");
  }
  flow.rtol = t.MetaFinite("rtol");
  flow.atol = t.MetaFinite("atol");
  flow.max_steps = static_cast<long>(t.MetaWhole("max_steps", 1, kMaxFlowSteps));
  return flow;
}

const std::vector<std::string>& PointRow(const Table& t, const std::string& point, bool number,
                                         std::string* type, int* pt) {
  if (number) {
    *pt = std::stoi(point);
    if (*pt > static_cast<int>(t.rows.size()))
      throw RestartError(Part::kPoint, "no point " + point + " in '" + t.path + "' (it has " +
                                           std::to_string(t.rows.size()) + " points)");
    *type = t.rows[*pt - 1][t.Column("kind")];
    return t.rows[*pt - 1];
  }
  const int lab = t.Column("lab");
  std::string have;
  for (const auto& row : t.rows) {
    have += (have.empty() ? "" : ", ") + row[lab];
    if (row[lab] != point) continue;
    *type = row[t.Column("label")];
    *pt = static_cast<int>(t.Whole(row[t.Column("pt")], "pt", 1, std::numeric_limits<int>::max()));
    return row;
  }
  throw RestartError(Part::kPoint, "no point " + point + " in '" + t.path +
                                       "' (its labels: " + (have.empty() ? "none" : have) + ")");
}

}  // namespace stickslip::io_detail
