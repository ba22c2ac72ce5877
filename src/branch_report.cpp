#include "stickslip/branch_report.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>

#include "stickslip/errors.hpp"
#include "stickslip/labels.hpp"
#include "stickslip/numbers.hpp"

namespace stickslip {

std::vector<std::pair<std::string, std::string>> SummaryFields(const ContinuationResult& r) {
  const ContinuationCounts& c = r.counts;
  const ContinuationTimes& t = r.seconds;
  auto sec = [](double x) { return Num(x, 3); };
  return {{"orbit_solves", std::to_string(c.orbit_solves)},
          {"return_maps", std::to_string(c.return_maps)},
          {"newton_iterations", std::to_string(c.newton_iterations)},
          {"rejected_steps", std::to_string(c.rejected_steps)},
          {"integrator_steps", std::to_string(c.integrator_steps)},
          {"seconds_equilibrium", sec(t.equilibrium)},
          {"seconds_stick_slip", sec(t.stick_slip)},
          {"seconds_pure_slip", sec(t.pure_slip)},
          {"seconds_switching", sec(t.switching)},
          {"seconds_discovery", sec(t.discovery)},
          {"seconds_total", sec(t.total)}};
}

namespace {
// The first field that must be a number but is not: {name, value}; name empty if none.
std::pair<std::string, double> FirstNonFinite(const BranchPoint& p) {
  const bool eq = p.kind == PointKind::kEquilibrium;
  const std::pair<const char*, double> fields[] = {{"parameter", p.p},
                                                   {"x_min", p.x_min},
                                                   {"x_max", p.x_max},
                                                   {"xdot_min", p.xdot_min},
                                                   {"xdot_max", p.xdot_max},
                                                   {"multiplier", p.multiplier},
                                                   {"amplitude", p.amplitude},
                                                   {"period", eq ? 0.0 : p.period},
                                                   {"t_stick", eq ? 0.0 : p.t_stick}};
  for (const auto& [name, x] : fields)
    if (!std::isfinite(x)) return {name, x};
  return {"", 0.0};
}
}  // namespace

void DropNonFinite(ContinuationResult* r, const std::string& param) {
  std::string first;
  std::size_t dropped = 0;
  std::vector<BranchPoint> kept;
  for (const BranchPoint& p : r->points) {
    const auto [name, x] = FirstNonFinite(p);
    if (name.empty()) {
      kept.push_back(p);
    } else if (dropped++ == 0) {
      first = name + " = " + FormatNumber(x) + " at " + param + " = " + FormatNumber(p.p) + " (" +
              PointKindName(p.kind) + ")";
    }
  }
  std::vector<SpecialPoint> special;
  for (const SpecialPoint& s : r->special) {
    if (std::isfinite(s.p) && std::isfinite(s.period) && std::isfinite(s.x_min) &&
        std::isfinite(s.x_max) && std::isfinite(s.xdot_min)) {
      special.push_back(s);
    } else if (dropped++ == 0) {
      first = std::string("non-finite values at the special point ") + SpecialLabel(s.kind);
    }
  }
  if (dropped == 0) return;
  r->points = std::move(kept);
  r->special = std::move(special);
  const std::string what = "numerical failure: " + first + "; " + std::to_string(dropped) +
                           " result(s) with non-finite numbers dropped";
  if (r->status == ContinuationStatus::kOk) r->status = ContinuationStatus::kFailed;
  r->message = r->message.empty() ? what : r->message + "; " + what;
}

TsvTable BranchTable(const ContinuationResult& r, const std::string& param,
                     const std::string& model_description, const std::vector<ExtraColumn>& extra) {
  std::vector<std::string> cols = {param,     "kind",       "branch",   "period",
                                   "x_min",   "x_max",      "xdot_min", "xdot_max",
                                   "t_stick", "multiplier", "stable",   "amplitude"};
  for (const auto& c : extra) {
    if (c.values.size() != r.points.size())
      throw InvalidArgument("extra column '" + c.name + "' has " + std::to_string(c.values.size()) +
                            " values for " + std::to_string(r.points.size()) + " points");
    cols.push_back(c.name);
  }
  // Point numbers and restart states last (labels.hpp), after the extras.
  cols.insert(cols.end(), {"pt", "x_start", "xdot_start"});
  TsvTable t(cols);
  t.AddMeta("model", model_description);
  if (r.partial())
    t.AddMeta("status",
              std::string("partial (") + ContinuationStatusName(r.status) + "): " + r.message);
  else
    t.AddMeta("status", "complete");
  for (const std::string& w : r.warnings) t.AddMeta("warning", w);
  for (const auto& kv : SummaryFields(r)) t.AddMeta(kv.first, kv.second);
  for (size_t i = 0; i < r.points.size(); ++i) {
    const BranchPoint& p = r.points[i];
    std::vector<TsvTable::Cell> row = {p.p,
                                       PointKindName(p.kind),
                                       p.branch,
                                       p.period,
                                       p.x_min,
                                       p.x_max,
                                       p.xdot_min,
                                       p.xdot_max,
                                       p.t_stick,
                                       p.multiplier,
                                       p.stable ? 1 : 0,
                                       p.amplitude};
    for (const auto& c : extra) row.emplace_back(c.values[i]);
    row.insert(row.end(), {static_cast<int>(i) + 1, p.x_start, p.xdot_start});
    t.AddRow(row);
  }
  return t;
}

TsvTable SpecialPointTable(const ContinuationResult& r, const std::string& param,
                           const std::vector<ExtraColumn>& extra) {
  std::vector<std::string> cols = {"label", param,      "period",     "x_min",
                                   "x_max", "xdot_min", "description"};
  for (const auto& c : extra) {
    if (c.values.size() != r.special.size())
      throw InvalidArgument("extra column '" + c.name + "' has " + std::to_string(c.values.size()) +
                            " values for " + std::to_string(r.special.size()) + " special points");
    cols.push_back(c.name);
  }
  cols.insert(cols.end(), {"pt", "lab", "x_start", "xdot_start"});
  const std::vector<int> rows = SpecialPointRows(r);
  const std::vector<std::string> labels = SpecialPointLabels(r);
  TsvTable t(cols);
  if (r.partial())
    t.AddMeta("status",
              std::string("partial (") + ContinuationStatusName(r.status) + "): " + r.message);
  else
    t.AddMeta("status", "complete");
  for (size_t i = 0; i < r.special.size(); ++i) {
    const SpecialPoint& s = r.special[i];
    std::vector<TsvTable::Cell> row = {
        SpecialLabel(s.kind), s.p, s.period, s.x_min, s.x_max, s.xdot_min, s.description};
    for (const auto& c : extra) row.emplace_back(c.values[i]);
    row.insert(row.end(), {rows[i], labels[i], s.x_start, s.xdot_start});
    t.AddRow(row);
  }
  return t;
}

namespace {
// Column numbers of branch.tsv (1-based, as gnuplot counts).
constexpr int kP = 1, kBranch = 3, kPeriod = 4, kXMin = 5, kXMax = 6, kXdMin = 7, kXdMax = 8,
              kMult = 10, kStable = 11;

// Curves of one quantity: per branch, stable solid and unstable dashed.
// Steady sliding (gray, titled once) is branch 0; the title goes on the
// first curve of the other branches.
std::string Curves(const std::set<int>& branches, int col, const std::string& title, int color,
                   bool with_equilibrium = true) {
  std::ostringstream os;
  bool first = true, titled = false;
  for (int b : branches) {
    const bool eq = b == 0;
    if (eq && !with_equilibrium) continue;
    for (int stable : {1, 0}) {
      std::string t = "notitle";
      if (!eq && !titled) t = "title \"" + title + "\"", titled = true;
      os << (first ? "" : ", \\\n     ") << "'branch.tsv' using " << kP << ":(($" << kBranch
         << "==" << b << " && $" << kStable << "==" << stable << ") ? $" << col
         << " : NaN) with lines lc " << (eq ? "rgb 'gray50'" : std::to_string(color)) << " lw 2 dt "
         << (stable ? 1 : 2) << " " << t;
      first = false;
    }
  }
  return os.str();
}

// Two curve lists as one; either may be empty.
std::string Join(const std::string& a, const std::string& b) {
  return a.empty() || b.empty() ? a + b : a + ", \\\n     " + b;
}

// Columns of special_points.tsv: 2 the parameter, 3 period, 4 x_min, 5 x_max, 6 xdot_min.
std::string Special(int col) {
  std::ostringstream os;
  os << "'special_points.tsv' using 2:" << col
     << " with points pt 7 ps 1.2 lc rgb 'black' notitle, \\\n"
     << "     'special_points.tsv' using 2:" << col
     << ":(strcol(1) eq 'LP' ? '' : strcol(1)) with labels offset 0,1.2 font ',11' notitle, \\\n"
     << "     'special_points.tsv' using 2:" << col
     << ":(strcol(1) eq 'LP' ? 'LP' : '') with labels offset 0,-1.2 font ',11' notitle";
  return os.str();
}
}  // namespace

std::vector<std::string> BifurcationFigures(bool estimates) {
  std::vector<std::string> f = {"bifurcation_x.png", "bifurcation_xdot.png", "period.png",
                                "multiplier.png"};
  if (estimates) f.push_back("estimates.png");
  return f;
}

std::string BifurcationScript(const ContinuationResult& r, const std::string& param,
                              const std::string& title, bool estimates) {
  std::set<int> branches;
  for (const auto& p : r.points) branches.insert(p.branch);
  std::ostringstream os;
  os << "# Bifurcation diagrams written by ss_continue; run `gnuplot "
     << "bifurcation.gp` in "
     << "this directory.\n"
     << "# Solid: stable, dashed: unstable, gray: steady sliding. GR grazing-sliding, HB Hopf,\n"
     << "# LP fold.\n"
     << "if (!exists('suffix')) suffix = ''\n"
     << "set terminal pngcairo size 1000,700 enhanced font ',12'\n"
     << "set datafile separator '\\t'\n"
     << "set datafile columnheaders\n"
     << "set key top right\n"
     << "set grid\n"
     << "set xlabel '" << param << "'\n"
     << "set title '" << title << "' noenhanced\n";
  const bool any_special = !r.special.empty();
  bool periodic = false;
  double lo = 0, hi = 1;
  for (std::size_t i = 0; i < r.points.size(); ++i) {
    periodic = periodic || r.points[i].kind != PointKind::kEquilibrium;
    lo = i == 0 ? r.points[i].p : std::min(lo, r.points[i].p);
    hi = i == 0 ? r.points[i].p : std::max(hi, r.points[i].p);
  }
  if (!(hi > lo)) lo -= 0.5, hi += 0.5;
  // gnuplot refuses a plot with no defined point: an empty frame that says so.
  auto empty = [&](const std::string& why) {
    os << "set label 1 '" << why << "' at graph 0.5,0.5 center\n"
       << "set xrange [" << FormatNumber(lo) << ":" << FormatNumber(hi) << "]\nset yrange [0:1]\n"
       << "plot NaN notitle\nunset label 1\nset autoscale\n";
  };
  auto plot = [&](const std::string& out, const std::string& ylabel, const std::string& curves,
                  const std::string& marks, bool has_data) {
    os << "set output '" << out << "'.suffix\n"
       << "set ylabel \"" << ylabel << "\"\n";
    if (has_data)
      os << "plot " << curves << (any_special && !marks.empty() ? ", \\\n     " + marks : "")
         << "\n";
    else
      empty(r.points.empty() ? "no points computed" : "no periodic orbit in this range");
    os << "unset output\n";
  };
  plot("bifurcation_x.png", "x range (min and max)",
       Join(Curves(branches, kXMax, "x max", 1), Curves(branches, kXMin, "x min", 3, false)),
       Special(5) + ", \\\n     " + Special(4), !r.points.empty());
  plot("bifurcation_xdot.png", "x' range (min and max)",
       Join(Curves(branches, kXdMax, "x' max", 1), Curves(branches, kXdMin, "x' min", 3, false)),
       Special(6), !r.points.empty());
  plot("period.png", "period", Curves(branches, kPeriod, "period", 1), Special(3), periodic);
  plot("multiplier.png", "nontrivial Floquet multiplier (equilibrium: max Re lambda)",
       Curves(branches, kMult, "multiplier", 1), "", !r.points.empty());
  if (estimates && !periodic) {
    os << "set output 'estimates.png'.suffix\n";
    empty("no periodic orbit in this range");
    os << "unset output\n";
  } else if (estimates) {
    // Extra columns of CompareEstimates: 13 r1, 15 a_ps, 17/18 seed's x bounds.
    const std::string periodic = "(strcol(2) ne 'equilibrium')";
    os << "set output 'estimates.png'.suffix\n"
       << "set terminal pngcairo size 1000,1000 enhanced font ',12'\n"
       << "set multiplot layout 2,1\n"
       << "set key bottom left\n"
       << "set title 'smallest slip velocity: computed and estimated' noenhanced\n"
       << "set ylabel \"x' min\"\n"
       << "plot 'branch.tsv' using 1:(" << periodic << " ? $" << kXdMin
       << " : NaN) with lines lw 3 lc rgb 'black' title 'computed', \\\n"
       << "     '' using 1:13 with lines lw 2 dt 2 lc rgb 'red' title 'seed (3.17): r_1', \\\n"
       << "     '' using 1:(-$15) with lines lw 2 dt 3 lc rgb 'blue' "
          "title 'averaging: -a_{ps}'\n"
       << "set title 'x range: computed and the seed''s displacement bound' noenhanced\n"
       << "set ylabel 'x'\n"
       << "plot 'branch.tsv' using 1:(" << periodic << " ? $" << kXMax
       << " : NaN) with lines lw 3 lc rgb 'black' title 'computed x max, x min', \\\n"
       << "     '' using 1:(" << periodic << " ? $" << kXMin
       << " : NaN) with lines lw 3 lc rgb 'black' notitle, \\\n"
       << "     '' using 1:18 with lines lw 2 dt 2 lc rgb 'red' title 'seed bound x max', \\\n"
       << "     '' using 1:17 with lines lw 2 dt 2 lc rgb 'dark-red' title 'seed bound x min'\n"
       << "unset multiplot\nunset output\n";
  }
  return os.str();
}

}  // namespace stickslip
