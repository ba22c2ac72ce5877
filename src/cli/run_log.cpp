#include "cli/run_log.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>
#include <map>
#include <sstream>
#include <string>

#include "cli/estimates_text.hpp"
#include "continuation/labels.hpp"
#include "stickslip/io/report.hpp"
#include "stickslip/io/system_branch_report.hpp"

namespace stickslip::cli {
namespace {

// x to 10 significant digits (the SI copies beside the dimensionless values).
std::string Sig(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.10g", x);
  return buf;
}

// The unit inside an axis label's brackets ("belt speed V [m/s]" -> "m/s").
std::string UnitOf(const std::string& label) {
  const auto a = label.find('['), b = label.find(']');
  if (a == std::string::npos || b == std::string::npos || b < a) return "";
  return label.substr(a + 1, b - a - 1);
}

// " (belt_speed 0.0123 m/s)" for a physical run's parameter, else "".
std::string PhysicalParameter(const std::optional<Scales>& s, const std::string& param, double p) {
  if (!s) return "";
  const auto axis = AxisOf(param, *s);
  if (!axis) return "";
  return " (" + axis->physical + " " + Sig(p / axis->factor) + " " + UnitOf(axis->label) + ")";
}

// Column widths of the per-point table (AUTO-07p prints similar columns).
std::string Pad(std::string s, std::size_t width) {
  if (s.size() < width) s.append(width - s.size(), ' ');
  return s;
}

// One table row, without the padding an empty last cell leaves.
void Row(std::ostream& os, std::string line) {
  line.erase(line.find_last_not_of(' ') + 1);
  os << line << "\n";
}

void BranchTableHeader(std::ostream& os, const std::string& param, bool si) {
  Row(os, "  " + Pad("pt", 6) + Pad("kind", 12) + Pad(param, 16) + Pad("period", 11) +
              Pad("x_min", 11) + Pad("x_max", 11) + Pad("multiplier", 13) + Pad("stability", 10) +
              Pad("lab", 8) + (si ? "SI: (parameter) period [x range]" : ""));
}

}  // namespace

void PrintBranchLog(std::ostream& os, const ContinuationResult& r, LogDetail detail,
                    const std::optional<Scales>& scales) {
  const std::string param = r.param.name();
  const std::vector<int> rows = SpecialPointRows(r);
  const std::vector<std::string> labs = SpecialPointLabels(r);
  if (detail == LogDetail::kEveryPoint) {
    std::map<int, std::string> lab_at;  // pt -> "GR1" (several: "GR1,LP1")
    for (std::size_t i = 0; i < rows.size(); ++i)
      lab_at[rows[i]] += (lab_at[rows[i]].empty() ? "" : ",") + labs[i];
    os << "points:\n";
    BranchTableHeader(os, param, scales.has_value());
    for (std::size_t i = 0; i < r.points.size(); ++i) {
      const BranchPoint& p = r.points[i];
      const int pt = static_cast<int>(i) + 1;
      const bool orbit = p.kind != PointKind::kEquilibrium;
      std::ostringstream line;
      line << "  " << Pad(std::to_string(pt), 6) << Pad(Name(p.kind), 12) << Pad(Fixed(p.p, 10), 16)
           << Pad(orbit ? Fixed(p.period, 6) : "-", 11) << Pad(Fixed(p.extrema.x_min, 6), 11)
           << Pad(Fixed(p.extrema.x_max, 6), 11) << Pad(Fixed(p.multiplier, 6), 13)
           << Pad(p.stable ? "stable" : "unstable", 10)
           << Pad(lab_at.count(pt) ? lab_at[pt] : "", 8);
      if (scales) {
        line << PhysicalParameter(scales, param, p.p);
        if (orbit) line << " " << Sig(p.period * scales->t0) << " s";
        line << " [" << Sig(p.extrema.x_min * scales->L) << ", " << Sig(p.extrema.x_max * scales->L)
             << "] m";
      }
      Row(os, line.str());
    }
  }
  os << "special points (restart one with --restart DIR --point LAB or PT):\n";
  if (r.special.empty()) os << "  none\n";
  for (std::size_t i = 0; i < r.special.size(); ++i) {
    const SpecialPoint& s = r.special[i];
    os << "  " << labs[i] << "  pt " << rows[i] << "  " << param << " = " << Fixed(s.p, 12)
       << PhysicalParameter(scales, param, s.p) << "  period " << Fixed(s.period, 6);
    if (scales) os << " (" << Sig(s.period * scales->t0) << " s)";
    os << "  x in [" << Fixed(s.extrema.x_min, 6) << ", " << Fixed(s.extrema.x_max, 6) << "]";
    if (scales)
      os << " ([" << Sig(s.extrema.x_min * scales->L) << ", " << Sig(s.extrema.x_max * scales->L)
         << "] m)";
    os << "  " << s.description << "\n";
  }
}

void PrintSystemLog(std::ostream& os, const System& s, const SystemRun& r, LogDetail detail) {
  const std::string param = s.ParameterName(r.parameter), x = StateColumn(s, 0);
  if (detail == LogDetail::kEveryPoint)
    os << "points:\n  " << Pad("pt", 6) << Pad("branch", 8) << Pad("kind", 12) << Pad(param, 16)
       << Pad("m", 4) << Pad("period", 11) << Pad(x + "_min", 11) << Pad(x + "_max", 11)
       << Pad("|mu|max", 11) << Pad("stability", 10) << "lab\n";
  int pt = 0;
  std::map<SpecialKind, int> count;
  std::vector<std::string> special;
  // One row: its label counted in branch.tsv's order; the table's line with
  // --verbose (an orbit's m: its section's turns or returns).
  auto row = [&](int branch, const std::string& kind, double p, int m, double period,
                 const Eigen::VectorXd* lo, const Eigen::VectorXd* hi, double mu, bool stable,
                 SpecialKind label, const std::string& description) {
    ++pt;
    std::string lab;
    if (label != SpecialKind::kNone)
      lab = std::string(Name(label)) + std::to_string(++count[label]);
    const bool orbit = lo && lo->size() > 0 && hi->size() > 0;
    if (detail == LogDetail::kEveryPoint)
      Row(os, "  " + Pad(std::to_string(pt), 6) + Pad(std::to_string(branch), 8) + Pad(kind, 12) +
                  Pad(Fixed(p, 10), 16) + Pad(m > 0 ? std::to_string(m) : "-", 4) +
                  Pad(m > 0 ? Fixed(period, 6) : "-", 11) +
                  Pad(orbit ? Fixed((*lo)[0], 6) : "-", 11) +
                  Pad(orbit ? Fixed((*hi)[0], 6) : "-", 11) + Pad(Fixed(mu, 6), 11) +
                  Pad(stable ? "stable" : "unstable", 10) + lab);
    if (!lab.empty())
      special.push_back(
          "  " + lab + "  pt " + std::to_string(pt) + "  " + param + " = " + FormatNumber(p) +
          (orbit ? "  " + x + "_max " + FormatNumber((*hi)[0]) : "") + "  " + description);
  };
  for (const SteadyRow& q : r.steady.rows)  // |mu|max: the largest real part
    row(0, "equilibrium", q.p, 0, 0, nullptr, nullptr, q.state.max_real, q.state.stable(), q.label,
        q.description);
  for (std::size_t i = 0; i < r.pieces.size(); ++i) {
    const PoincareSection& sec = r.pieces[i].section;
    const int m = sec.kind == SectionKind::kTime ? sec.turns : sec.returns;
    for (const OrbitRow& q : r.pieces[i].rows) {
      double mu = 0;
      for (const auto& z : q.multipliers) mu = std::max(mu, std::abs(z));
      row(r.numbers[i], q.sticks > 0 ? "stick-slip" : "pure-slip", q.p, std::max(m, 1), q.period,
          &q.lo, &q.hi, mu, q.stable, q.label, q.description);
    }
  }
  os << "special points (restart one with --restart DIR --point LAB or PT):\n";
  if (special.empty()) os << "  none\n";
  for (const std::string& line : special) os << line << "\n";
}

}  // namespace stickslip::cli
