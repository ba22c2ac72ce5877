// bifurcation.gp of a system's run (system_branch_report.hpp): three panels
// against the parameter, each branch, kind and stability its own line style
// (figure_style.hpp: stable solid, unstable dashed), the located points
// marked and labelled on the first.
#include <algorithm>
#include <set>
#include <sstream>
#include <tuple>

#include "io/system_rows.hpp"
#include "stickslip/io/system_branch_report.hpp"

namespace stickslip {

namespace {

// A title line's length in characters: the figure is 1000 px wide, and
// chain10's lines of 104-108 ran past its edges at kTitleWidth.
constexpr std::size_t kSystemTitleWidth = 96;

using io_detail::SystemLine;

int Style(const std::string& kind, bool stable) {
  const int base = kind == "stick-slip"  ? kStyleStickSlip
                   : kind == "pure-slip" ? kStylePureSlip
                                         : kStyleEquilibrium;
  return stable ? base : base + 1;
}

// One panel: column `y` of every (branch, kind, stability) that has rows; the
// key names each (kind, stability) once. A located point joins the segments
// on either side (P marks its row).
void Panel(std::ostream& os, const std::vector<SystemLine>& lines, const std::string& p,
           const std::vector<std::string>& ys, bool key, bool orbits_only) {
  std::set<std::tuple<int, std::string, bool>> drawn;
  for (const SystemLine& l : lines)
    if (!(orbits_only && l.branch == 0)) drawn.insert({l.branch, l.kind, l.stable});
  std::set<std::pair<std::string, bool>> titled;
  bool first = true;
  os << "plot ";
  for (const auto& [b, kind, stable] : drawn)
    for (const std::string& y : ys) {
      const bool title = key && y == ys.front() && titled.insert({kind, stable}).second;
      os << (first ? "" : ", \\\n  ") << "'branch.tsv' using '" << p << "':(sel(" << b << ", '"
         << kind << "', " << stable << ") ? c('" << y
         << "') : 1/0) with "
         // unstable orbit rows marked too: a short piece shows between dashes
         << (stable || b == 0 ? "lines" : "linespoints") << " ls " << Style(kind, stable)
         << (stable || b == 0 ? " " : " pt 6 ps 0.5 ")
         << (title ? "title '" + kind + (stable ? ", stable'" : ", unstable'") : "notitle");
      first = false;
    }
}

}  // namespace

std::vector<std::string> SystemBranchFigures(FigureFormat format) {
  return {FigureFile("bifurcation", format)};
}

std::string SystemBranchScript(const System& s, const SystemRun& run, const std::string& title,
                               FigureFormat format) {
  const std::vector<SystemLine> lines = io_detail::SystemLines(s, run);
  const std::string p = s.ParameterName(run.parameter);
  const std::string x = StateColumn(s, 0);
  int specials = 0;
  bool orbits = false;  // without orbit rows: the first panel alone
  for (const SystemLine& l : lines) {
    specials += l.label != SpecialKind::kNone;
    orbits = orbits || l.branch > 0;
  }
  std::ostringstream os;
  os << "# The bifurcation figure of ss_continue --system: " << s.StateName(0)
     << "'s extremes, the period and the largest |multiplier| against " << p << ".\n"
     << FigurePreamble(format, 1000, orbits ? 1150 : 560) << "set output '"
     << FigureFile("bifurcation", format) << "'\n";
  if (lines.empty())  // nothing computed: an empty frame that says so
    return os.str() + "set title " +
           GnuplotQuoted(EnhancedText(WrapWords(title, kSystemTitleWidth), false)) +
           "\nset xrange [0:1]\nset yrange [0:1]\nset label 1 'no rows' at graph 0.5, graph 0.5 "
           "center\nplot NaN notitle\n";
  os << "c(name) = column(name)\n"
     << "stats 'branch.tsv' using 1 nooutput\nN = STATS_records\narray P[N]\n"
     << "do for [i = 1:N] { P[i] = 0 }\n";
  if (specials > 0) os << "stats 'special_points.tsv' using (P[int(c('pt'))] = 1, 0) nooutput\n";
  os << "sel(b, k, s) = c('branch') == b && strcol('kind') eq k && "
        "(c('stable') == s || P[int(c('pt'))])\n"
     << "set multiplot layout " << (orbits ? 3 : 1) << ", 1 title "
     << GnuplotQuoted(EnhancedText(WrapWords(title, kSystemTitleWidth), false)) << "\n"
     << "set xlabel " << GnuplotQuoted(EnhancedText(p)) << "\nset autoscale xfix\n"
     << "set ylabel " << GnuplotQuoted(EnhancedText(s.StateName(0) + " (min and max)")) << "\n"
     << "set offsets 0, 0, graph 0.12, graph 0.05\n";
  for (std::size_t i = 0; i + 1 < run.gap.size(); i += 2)  // shaded in every panel
    os << "set object " << i / 2 + 1 << " rect from "
       << FormatNumber(std::min(run.gap[i], run.gap[i + 1])) << ", graph 0 to "
       << FormatNumber(std::max(run.gap[i], run.gap[i + 1]))
       << ", graph 1 fc rgb '#e8e8e8' fs solid noborder behind\nset label " << i / 2 + 1
       << " 'not traced: unbounded' at " << FormatNumber(std::max(run.gap[i], run.gap[i + 1]))
       << ", graph 0.93 offset 1, 0 tc rgb '#555555'\n";
  Panel(os, lines, p, {x + "_max", x + "_min"}, true, false);
  // The located points, labelled above and below in turn (gnuplot 5.4
  // crashes on a labels plot without a defined point: the second only with two).
  if (specials > 0)
    os << ", \\\n  'special_points.tsv' using '" << p << "':'" << x << "_max' with points ls "
       << kStyleSpecial << " notitle";
  for (int k = 0; k < std::min(specials, 2); ++k)
    os << ", \\\n  'special_points.tsv' using '" << p << "':(int($0) % 2 == " << k << " ? c('" << x
       << "_max') : 1/0):'lab' with labels offset 0, " << (k ? "-1.2" : "1.2")
       << " boxed font ',10' notitle";
  if (orbits) {
    os << "\nunset label\nset key off\nset bmargin 3.5\nset offsets 0, 0, graph 0.05, graph 0.05\n"
       << "set ylabel 'period'\n";
    Panel(os, lines, p, {"period"}, false, true);
    os << "\nset ylabel 'largest |Floquet multiplier|'\nset yrange [0:*]\n";
    Panel(os, lines, p, {"mult_max"}, false, true);
    os << ", \\\n  1 with lines ls " << kStyleThreshold << " notitle";  // stability's edge
  }
  os << "\nunset multiplot\n";
  return os.str();
}

}  // namespace stickslip
