#include "stickslip/io/restart.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <vector>

#include "stickslip/continuation/continuation.hpp"
#include "stickslip/io/report.hpp"
#include "stickslip/model/forced.hpp"

namespace stickslip {

namespace {

using Part = RestartError::Part;

// A TSV as TsvTable writes it: '# key: value' lines, a header, rows.
struct Table {
  std::string path;
  std::map<std::string, std::string> meta;
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;

  int Column(const std::string& name) const {
    for (std::size_t j = 0; j < header.size(); ++j)
      if (header[j] == name) return static_cast<int>(j);
    throw RestartError(Part::kRun, "'" + path + "' has no column '" + name +
                                       "' (written before labelled points? run ss_continue again)");
  }
  const std::string& Meta(const std::string& key) const {
    const auto it = meta.find(key);
    if (it == meta.end())
      throw RestartError(Part::kRun, "'" + path + "' has no '# " + key + ":' line");
    return it->second;
  }
};

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

Table Read(const std::string& path) {
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

double Number(const Table& t, const std::string& text, const std::string& what) {
  char* end = nullptr;
  errno = 0;
  const double x = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0' || errno == ERANGE)
    throw RestartError(Part::kRun,
                       "'" + t.path + "' is corrupt: " + what + " = '" + text + "' is no number");
  return x;
}

// The model and the solver options from the metadata (cli/about.cpp's RunMetadata).
void ReadModel(const Table& t, LabelledPoint* lp) {
  const std::string& tool = t.Meta("tool");
  if (tool.rfind("ss_continue", 0) != 0 && tool.rfind(kPythonTool, 0) != 0)
    throw RestartError(Part::kRun, "'" + t.path + "' was not written by ss_continue");
  try {
    lp->params.law = LawFromName(t.Meta("law"));
  } catch (const InvalidArgument& e) {
    throw RestartError(Part::kRun, "'" + t.path + "': " + e.what());
  }
  const std::string continued = t.Meta("continued");
  const auto model = t.meta.find("model");  // run_forced.cpp: "forced oscillator, ..."
  lp->forced = model != t.meta.end() && model->second.rfind("forced oscillator", 0) == 0;
  if (lp->forced ? !FromName(continued, &lp->forced_param) : !IsParameterName(continued))
    throw RestartError(Part::kRun, "'" + t.path + "': continued '" + continued + "' is no " +
                                       (lp->forced ? "axis of a forced run" : "parameter"));
  if (!lp->forced) lp->param = ParameterAxis(continued);
  for (const std::string& name : ParameterNames(lp->params.law))
    if (name != continued) SetParameter(lp->params, name, Number(t, t.Meta(name), name));
  if (lp->forced && continued != "force") lp->force = Number(t, t.Meta("force"), "force");
  if (lp->forced && continued != "omega") lp->omega = Number(t, t.Meta("omega"), "omega");
  const std::string integrator = t.Meta("integrator");
  if (integrator == "taylor") {
    lp->flow.integrator = Integrator::kTaylor;
  } else if (integrator == "cvode adams" || integrator == "cvode bdf") {
    lp->flow.integrator = Integrator::kCvode;
    lp->flow.method = integrator == "cvode bdf" ? Method::kBdf : Method::kAdams;
  } else {
    throw RestartError(Part::kRun, "'" + t.path + "': unknown integrator '" + integrator + "'");
  }
  lp->flow.rtol = Number(t, t.Meta("rtol"), "rtol");
  lp->flow.atol = Number(t, t.Meta("atol"), "atol");
  lp->flow.max_steps = static_cast<long>(Number(t, t.Meta("max_steps"), "max_steps"));
  const auto from = t.meta.find("from"), to = t.meta.find("to");
  if (from != t.meta.end() && to != t.meta.end()) {
    lp->run_from = Number(t, from->second, "from");
    lp->run_to = Number(t, to->second, "to");
    if (!(std::isfinite(lp->run_from) && std::isfinite(lp->run_to)))
      throw RestartError(Part::kRun, "'" + t.path + "' is corrupt: '# from: " + from->second +
                                         "' and '# to: " + to->second + "' must be finite");
  }
}

// The row's parameter value and state.
void ReadRow(const Table& t, const std::vector<std::string>& row, LabelledPoint* lp) {
  const std::string name = lp->ParamName();
  lp->p = Number(t, row[t.Column(name)], name);
  if (lp->forced) {  // the forcing or a belt parameter of the forced model
    ForcedParams fp;
    fp.base = lp->params, fp.force = lp->force, fp.omega = lp->omega;
    SetAxis(fp, lp->forced_param, lp->p);
    lp->params = fp.base, lp->force = fp.force, lp->omega = fp.omega;
  } else {
    lp->param.Set(lp->params, lp->p);
  }
  const std::string x = lp->forced ? "x0" : "x_start", xdot = lp->forced ? "xdot0" : "xdot_start";
  lp->state = Vec2(Number(t, row[t.Column(x)], x), Number(t, row[t.Column(xdot)], xdot));
  lp->period = Number(t, row[t.Column("period")], "period");
  // Only steady sliding (an equilibrium row) has no period.
  const bool periodic = lp->type != Name(PointKind::kEquilibrium);
  if (periodic && !(std::isfinite(lp->period) && lp->period > 0))
    throw RestartError(Part::kRun, "'" + t.path + "': the point " + lp->label + " has period = " +
                                       row[t.Column("period")] + ", not a finite number > 0");
  if (lp->forced) lp->m = static_cast<int>(Number(t, row[t.Column("m")], "m"));
  std::string err = lp->forced ? ValidationError(ForcedParams{lp->params, lp->force, lp->omega})
                               : ValidationError(lp->params);
  if (err.empty() && lp->forced && !(lp->m >= 1 && lp->m <= LabelledPoint::kMaxM))
    err = "m out of range";
  if (err.empty()) err = lp->flow.ValidationError();
  if (!err.empty() || !std::isfinite(lp->p) || !lp->state.allFinite())
    throw RestartError(Part::kRun, "'" + t.path + "': the point " + lp->label + " is invalid" +
                                       (err.empty() ? "" : ": " + err));
}

}  // namespace

LabelledPoint ReadLabelledPoint(const std::string& dir, const std::string& point) {
  LabelledPoint lp;
  lp.label = point;
  const bool number = std::regex_match(point, std::regex("[1-9][0-9]{0,8}"));
  if (!number &&
      !std::regex_match(point, std::regex("(GR|HB|LP|PD|NS|SW|AD|CR|SL)[1-9][0-9]{0,8}")))
    throw RestartError(Part::kPoint,
                       "'" + point +
                           "' is neither a label (GR1, HB1, LP1, PD1, CR1, ...) nor a point "
                           "number (1, 2, ... of branch.tsv)");
  const Table t = Read(dir + (number ? "/branch.tsv" : "/special_points.tsv"));
  ReadModel(t, &lp);
  if (number) {
    lp.pt = std::stoi(point);
    if (lp.pt > static_cast<int>(t.rows.size()))
      throw RestartError(Part::kPoint, "no point " + point + " in '" + t.path + "' (it has " +
                                           std::to_string(t.rows.size()) + " points)");
    const auto& row = t.rows[lp.pt - 1];
    lp.type = row[t.Column("kind")];
    ReadRow(t, row, &lp);
    return lp;
  }
  const int lab = t.Column("lab");
  std::string have;
  for (const auto& row : t.rows) {
    have += (have.empty() ? "" : ", ") + row[lab];
    if (row[lab] != point) continue;
    lp.type = row[t.Column("label")];
    lp.pt = static_cast<int>(Number(t, row[t.Column("pt")], "pt"));
    ReadRow(t, row, &lp);
    return lp;
  }
  throw RestartError(Part::kPoint, "no point " + point + " in '" + t.path +
                                       "' (its labels: " + (have.empty() ? "none" : have) + ")");
}

}  // namespace stickslip
