// The bifurcation diagram's gnuplot script (bifurcation.gp); see branch_report.hpp.
#include <algorithm>
#include <cmath>
#include <functional>
#include <set>
#include <sstream>
#include <tuple>

#include "continuation/labels.hpp"
#include "numerics/numbers.hpp"
#include "stickslip/errors.hpp"
#include "stickslip/io/branch_report.hpp"
#include "stickslip/io/figure_style.hpp"

namespace stickslip {

namespace {
// Column numbers of branch.tsv (1-based, as gnuplot counts).
constexpr int kP = 1, kBranch = 3, kPeriod = 4, kXMin = 5, kXMax = 6, kXdMin = 7, kXdMax = 8,
              kMult = 10, kStable = 11;

// The line style of a kind, stable or not (figure_style.hpp).
int Style(PointKind k, bool stable) {
  const int base = k == PointKind::kStickSlip  ? kStyleStickSlip
                   : k == PointKind::kPureSlip ? kStylePureSlip
                                               : kStyleEquilibrium;
  return stable ? base : base + 1;
}

// The gnuplot unit variable of a column (FigureUnitVariables): lengths ul,
// speeds uv, the period ut; the multiplier has none.
std::string Unit(int col) {
  return col == kXMin || col == kXMax     ? "ul"
         : col == kXdMin || col == kXdMax ? "uv"
         : col == kPeriod                 ? "ut"
                                          : "1";
}

// Curves of one column: per branch, kind and stability its own line style
// (stable solid, unstable dashed), no titles (Key() gives them); the
// parameter and the column in the figure's units.
std::string Curves(const ContinuationResult& r, int col, bool periodic, bool equilibrium) {
  std::set<std::tuple<int, int, int>> seen;  // branch, kind, stable
  for (const auto& p : r.points) seen.insert({p.branch, int(p.kind), p.stable ? 1 : 0});
  std::ostringstream os;
  for (const auto& [b, k, st] : seen) {
    const PointKind kind = static_cast<PointKind>(k);
    if ((kind == PointKind::kEquilibrium ? !equilibrium : !periodic)) continue;
    os << (os.tellp() > 0 ? ", \\\n     " : "") << "'branch.tsv' using ($" << kP
       << "*up):((strcol(2) eq '" << Name(kind) << "' && $" << kBranch << "==" << b << " && $"
       << kStable << "==" << st << ") ? $" << col << "*" << Unit(col) << " : NaN) with lines ls "
       << Style(kind, st == 1) << " notitle";
  }
  return os.str();
}

// One key entry per kind and stability present (drawn from NaN: no data).
std::string Key(const ContinuationResult& r, bool periodic, bool equilibrium) {
  std::set<std::pair<int, int>> seen;
  for (const auto& p : r.points) seen.insert({int(p.kind), p.stable ? 1 : 0});
  const char* names[] = {"stick-slip", "pure slip", "steady sliding"};
  std::ostringstream os;
  for (const auto& [k, st] : seen) {
    const PointKind kind = static_cast<PointKind>(k);
    if ((kind == PointKind::kEquilibrium ? !equilibrium : !periodic)) continue;
    os << ", \\\n     NaN with lines ls " << Style(kind, st == 1) << " title '" << names[k]
       << (st ? ", stable" : ", unstable") << "'";
  }
  return os.str();
}

// Marks and labels of special points at (p, y(s)): labels above, a label whose
// point is within kNearLabel of the range of the previous one goes to the other
// side, then further out, so neighbours (GR next to LP) do not overlap.
constexpr double kNearLabel = 0.06;
std::string Marks(const ContinuationResult& r, double lo, double hi,
                  const std::function<double(const SpecialPoint&)>& y,
                  const std::function<bool(const SpecialPoint&)>& use,
                  const std::string& y_unit = "1") {
  std::vector<SpecialPoint> sp;
  for (const auto& s : r.special)
    if (use(s)) sp.push_back(s);
  std::sort(sp.begin(), sp.end(), [](auto& a, auto& b) { return a.p < b.p; });
  const double offsets[] = {1.1, -1.1, 2.2, -2.2};
  std::ostringstream os;
  int level = 0;
  for (std::size_t i = 0; i < sp.size(); ++i) {
    const bool near = i > 0 && sp[i].p - sp[i - 1].p < kNearLabel * (hi - lo);
    level = near ? (level + 1) % 4 : 0;
    os << "set label " << 100 + i << " '" << SpecialLabel(sp[i].kind) << "' at "
       << "up*" << FormatNumber(sp[i].p) << "," << y_unit << "*" << FormatNumber(y(sp[i]))
       << " center offset 0," << offsets[level] << " boxed front font ',10' point ls "
       << kStyleSpecial << "\n";
  }
  return os.str();
}

// Two curve lists as one; either may be empty.
std::string Join(const std::string& a, const std::string& b) {
  return a.empty() || b.empty() ? a + b : a + ", \\\n     " + b;
}

// The multiplier of the periodic point nearest to s in (parameter, period):
// where its mark sits on the curve (an LP at a grazing need not be at 1).
double NearestMultiplier(const ContinuationResult& r, const SpecialPoint& s) {
  if (s.kind == SpecialKind::kGrazing) return s.multiplier_before;
  double best = 1, d_best = HUGE_VAL;
  for (const auto& p : r.points) {
    const double d = std::abs(p.p - s.p) + std::abs(p.period - s.period);
    if (p.kind != PointKind::kEquilibrium && d < d_best) best = p.multiplier, d_best = d;
  }
  return best;
}

// multiplier.png: two panels, each with its stability threshold: the
// periodic orbits' nontrivial Floquet multiplier (stable below 1) and steady
// sliding's largest real eigenvalue part (stable below 0).
void MultiplierFigure(std::ostringstream& os, const ContinuationResult& r, double lo, double hi,
                      bool periodic, bool equilibrium, FigureFormat format,
                      const std::string& ext) {
  os << FigureTerminal(format, 1000, 1000) << "set output 'multiplier" << ext << "'.suffix\n"
     << "set multiplot layout 2,1 title " << GnuplotQuoted("stability along the branch") << "\n"
     << "set lmargin 12\n";  // the panels' axes aligned
  auto panel = [&](bool has, const std::string& title, const std::string& ylabel,
                   const std::string& marks, const std::string& curves, const std::string& line) {
    os << "set title " << GnuplotQuoted(title) << "\nset ylabel " << GnuplotQuoted(ylabel) << "\n";
    if (!has) {
      os << "set label 1 'none in this range' at graph 0.5,0.5 center\nset yrange [0:1]\n"
         << "plot NaN notitle\nunset label 1\nset autoscale y\n";
      return;
    }
    os << marks << "plot " << curves << ", \\\n     " << line << "\nunset label\n";
  };
  panel(periodic, "periodic orbits: stable while the multiplier is below 1",
        "nontrivial Floquet multiplier",
        Marks(
            r, lo, hi, [&r](const SpecialPoint& s) { return NearestMultiplier(r, s); },
            [](const SpecialPoint& s) { return s.kind != SpecialKind::kHopf; }),
        Curves(r, kMult, true, false) + Key(r, true, false),
        "1 with lines ls " + std::to_string(kStyleThreshold) + " title 'threshold 1'");
  panel(equilibrium, "steady sliding: stable while the largest Re λ is below 0",
        "largest real part of the eigenvalues, Re λ",
        Marks(
            r, lo, hi, [](const SpecialPoint&) { return 0.0; },
            [](const SpecialPoint& s) { return s.kind == SpecialKind::kHopf; }),
        Curves(r, kMult, false, true) + Key(r, false, true),
        "0 with lines ls " + std::to_string(kStyleThreshold) + " title 'threshold 0'");
  os << "unset multiplot\nunset output\n";
}

// estimates.png: x'_min and the x range of the branch against the seed's
// estimates (3.17) and the averaging amplitude. Extra columns of
// CompareEstimates: 13 r1, 15 a_ps, 17/18 the seed's x bounds.
// Their cells are empty where they do not apply. gnuplot skips a row with an
// empty cell, drawing the line across it; read into arrays by row (pt), the
// cell is NaN there, and the line breaks as it should.
void EstimatesFigure(std::ostringstream& os, bool periodic, std::size_t rows, FigureFormat format,
                     const std::string& ext, const FigureUnits& units) {
  os << FigureTerminal(format, 1000, 1000) << "set output 'estimates" << ext << "'.suffix\n";
  if (!periodic) {
    os << "set label 1 'no periodic orbit in this range' at graph 0.5,0.5 center\n"
       << "set yrange [0:1]\nplot NaN notitle\nunset label 1\nunset output\n";
    return;
  }
  const std::string po = "(strcol(2) ne 'equilibrium')";
  os << "N = " << rows << "\n";
  for (const int col : {13, 15, 17, 18})
    os << "array E" << col << "[N]\ndo for [i = 1:N] { E" << col << "[i] = NaN }\n"
       << "stats 'branch.tsv' using (E" << col << "[int(column('pt'))] = $" << col
       << ", 0) nooutput\n";
  auto e = [](int col) { return "E" + std::to_string(col) + "[int(column('pt'))]"; };
  os << "set multiplot layout 2,1\nset lmargin 12\n"
     << "set title 'smallest slip velocity: computed and estimated'\n"
     << "set ylabel " << GnuplotQuoted("smallest velocity dx/dt" + units.SpeedUnit()) << "\n"
     << "plot 'branch.tsv' using ($1*up):(" << po << " ? $" << kXdMin << "*uv : NaN) with lines ls "
     << kStyleReference << " title 'computed', \\\n"
     << "     '' using ($1*up):(" << e(13) << "*uv) with lines ls " << kStyleEstimate1
     << " title 'seed (3.17): r_1', \\\n"
     << "     '' using ($1*up):(-" << e(15) << "*uv) with lines ls " << kStyleEstimate2
     << " title 'averaging: -a_{ps}'\n"
     << "set title \"displacement range: computed and the seed's bound\"\n"
     << "set ylabel " << GnuplotQuoted("displacement x" + units.LengthUnit()) << "\n"
     << "plot 'branch.tsv' using ($1*up):(" << po << " ? $" << kXMax << "*ul : NaN) with lines ls "
     << kStyleReference << " title 'computed', \\\n"
     << "     '' using ($1*up):(" << po << " ? $" << kXMin << "*ul : NaN) with lines ls "
     << kStyleReference << " notitle, \\\n"
     << "     '' using ($1*up):(" << e(18) << "*ul) with lines ls " << kStyleBound
     << " title \"the seed's bound (x max, x min)\", \\\n"
     << "     '' using ($1*up):(" << e(17) << "*ul) with lines ls " << kStyleBound << " notitle\n"
     << "unset multiplot\nunset output\n";
}
}  // namespace

std::vector<std::string> BifurcationFigures(bool estimates, FigureFormat format) {
  std::vector<std::string> f;
  for (const char* stem : {"bifurcation_x", "bifurcation_xdot", "period", "multiplier"})
    f.push_back(FigureFile(stem, format));
  if (estimates) f.push_back(FigureFile("estimates", format));
  return f;
}

std::string BifurcationScript(const ContinuationResult& r, const std::string& title, bool estimates,
                              FigureFormat format, const FigureUnits& units) {
  const std::string param = r.param.name();
  std::ostringstream os;
  os << "# Bifurcation diagrams written by ss_continue; run `gnuplot bifurcation.gp` in this\n"
     << "# directory. Solid: stable, dashed: unstable; blue stick-slip, vermillion pure slip,\n"
     << "# gray steady sliding. GR grazing-sliding, HB Hopf, LP fold.\n"
     << "if (!exists('suffix')) suffix = ''\n"
     << FigurePreamble(format, 1000, 720) << FigureUnitVariables(units) << "set xlabel "
     << GnuplotQuoted(units.P1Label(r.param)) << "\nset title "
     << GnuplotQuoted(FigureTitle(title, {param})) << "\n"
     << "set offsets 0, 0, graph 0.08, graph 0.08\n";
  bool periodic = false, equilibrium = false;
  double lo = 0, hi = 1;
  for (std::size_t i = 0; i < r.points.size(); ++i) {
    periodic = periodic || r.points[i].kind != PointKind::kEquilibrium;
    equilibrium = equilibrium || r.points[i].kind == PointKind::kEquilibrium;
    lo = i == 0 ? r.points[i].p : std::min(lo, r.points[i].p);
    hi = i == 0 ? r.points[i].p : std::max(hi, r.points[i].p);
  }
  if (!(hi > lo)) lo -= 0.5, hi += 0.5;
  os << "set xrange [up*" << FormatNumber(lo) << ":up*" << FormatNumber(hi) << "]\n";
  const std::string ext = std::string(".") + Name(format);
  // gnuplot refuses a plot with no defined point: an empty frame that says so.
  auto empty = [&](const std::string& why) {
    os << "set label 1 '" << why << "' at graph 0.5,0.5 center\nset yrange [0:1]\n"
       << "plot NaN notitle\nunset label 1\nset autoscale y\n";
  };
  auto all = [](const SpecialPoint&) { return true; };
  auto plot = [&](const std::string& stem, const std::string& ylabel, const std::string& marks,
                  const std::string& curves, bool has_data) {
    os << "set output '" << stem << ext << "'.suffix\nset ylabel " << GnuplotQuoted(ylabel) << "\n";
    if (has_data)
      os << marks << "plot " << curves << "\nunset label\n";
    else
      empty(r.points.empty() ? "no points computed" : "no periodic orbit in this range");
    os << "unset output\n";
  };
  plot("bifurcation_x", "displacement x: min and max" + units.LengthUnit(),
       Marks(
           r, lo, hi, [](const SpecialPoint& s) { return s.extrema.x_max; }, all, "ul"),
       Join(Curves(r, kXMax, true, true), Curves(r, kXMin, true, false)) + Key(r, true, true),
       !r.points.empty());
  plot("bifurcation_xdot", "velocity dx/dt: min and max" + units.SpeedUnit(),
       // On the upper curve, as x_max above: a grazing is where x' = v
       // meets the stick set, the top of the orbit.
       Marks(
           r, lo, hi, [](const SpecialPoint& s) { return s.extrema.xdot_max; }, all, "uv"),
       Join(Curves(r, kXdMax, true, true), Curves(r, kXdMin, true, false)) + Key(r, true, true),
       !r.points.empty());
  auto periodic_point = [](const SpecialPoint& s) {
    return std::isfinite(s.period) && s.period > 0;
  };
  plot("period", "period T" + units.TimeUnit(),
       Marks(
           r, lo, hi, [](const SpecialPoint& s) { return s.period; }, periodic_point, "ut"),
       Curves(r, kPeriod, true, false) + Key(r, true, false), periodic);
  MultiplierFigure(os, r, lo, hi, periodic, equilibrium, format, ext);
  if (estimates) EstimatesFigure(os, periodic, r.points.size(), format, ext, units);
  return os.str();
}

}  // namespace stickslip
