#include "stickslip/io/basin_stability_report.hpp"

#include <cstdio>
#include <map>
#include <set>
#include <sstream>

#include "numerics/numbers.hpp"

namespace stickslip {

std::vector<std::string> BasinStabilityLines(const BasinStability& b) {
  std::vector<std::string> lines;
  for (const BasinShare& s : b.shares) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.12f", s.fraction);
    lines.push_back("basin stability " + s.Name() + " " + buf);
  }
  return lines;
}

TsvTable BasinStabilityTable(const BasinStabilityCurve& c, const std::string& model_description,
                             const Box& box) {
  TsvTable t(
      {c.param.name(), "steady_sliding", "stick_slip", "pure_slip", "undecided", "enclosed"});
  t.AddMeta("model", model_description);
  t.AddMeta("box", "x in [" + FormatNumber(box.x_lo) + ", " + FormatNumber(box.x_hi) +
                       "], xdot in [" + FormatNumber(box.y_lo) + ", " + FormatNumber(box.y_hi) +
                       "]");
  t.AddMeta("status", c.status == BasinStatus::kOk
                          ? std::string("complete")
                          : std::string("partial (") + Name(c.status) + "): " + c.message);
  for (size_t i = 0; i < c.p.size(); ++i) {
    const BasinStability& b = c.at[i];
    t.AddRow({c.p[i], b.Of(Fate::kSteadySliding), b.Of(Fate::kStickSlip), b.Of(Fate::kPureSlip),
              b.Of(Fate::kUndecided), b.enclosed.empty() ? 0.0 : b.enclosed.front()});
  }
  return t;
}

namespace {
// The marks as dotted vertical lines labelled at the top (marks at one value,
// GR and LP at a non-smooth fold, share a label), and `seg(p)`: how many jumps
// lie below p, so that no line joins two rows across a jump.
std::string MarkLines(const std::vector<BasinStabilityMark>& marks, int* jumps) {
  std::map<double, std::string> at;
  std::set<double> cuts;
  for (const auto& m : marks) {
    std::string& l = at[m.p];
    l += (l.empty() ? "" : ", ") + m.label;
    if (m.jump) cuts.insert(m.p);
  }
  std::ostringstream os;
  int i = 0;
  for (const auto& [p, label] : at) {
    os << "set arrow " << 10 + i << " from up*" << FormatNumber(p) << ", graph 0 to up*"
       << FormatNumber(p) << ", graph 1 nohead lc rgb '#808080' lw 1 dt 2 back\n"
       << "set label " << 10 + i << " '" << label << "' at up*" << FormatNumber(p)
       << ", graph 1 center offset 0, 0.7 front font ',10'\n";
    ++i;
  }
  os << "seg(p) = 0";
  for (double c : cuts) os << " + (p > up*" << FormatNumber(c) << ")";
  os << "\n";
  *jumps = static_cast<int>(cuts.size());
  return os.str();
}
}  // namespace

std::string BasinStabilityScript(const ParameterAxis& param, const std::string& title,
                                 FigureFormat format, const FigureUnits& units,
                                 const std::vector<BasinStabilityMark>& marks) {
  // The shared style (figure_style.hpp): colour by kind, stable solid (every
  // attractor's basin), a thin dotted gray for the undecided share; each
  // curve drawn per piece between jumps (plot for [s = 0:jumps]).
  int jumps = 0;
  const std::string lines = MarkLines(marks, &jumps);
  std::ostringstream os;
  os << "# Basin stability written by ss_basin; run `gnuplot basin_stability.gp` here.\n"
     << "if (!exists('suffix')) suffix = ''\n"
     << FigurePreamble(format, 1000, 720) << FigureUnitVariables(units) << "set output '"
     << FigureFile("basin_stability", format) << "'.suffix\n"
     << "set title " << GnuplotQuoted(FigureTitle(title, {param.name()})) << " offset 0, 1\n"
     << "set xlabel " << GnuplotQuoted(units.P1Label(param)) << "\n"
     << "set ylabel 'basin stability (fraction of the box)'\n"
     << "set yrange [-0.02:1.02]\nset autoscale xfix\n"
     << lines;
  auto curve = [&](int col, const std::string& how, const std::string& name) {
    return "for [s = 0:" + std::to_string(jumps) +
           "] 'basin_stability.tsv' using ($1*up):(seg($1*up) == s ? $" + std::to_string(col) +
           " : NaN) with " + how + " title (s == 0 ? '" + name + "' : '')";
  };
  const std::string pts = " pt 7 ps 0.5";
  os << "plot "
     << curve(2, "linespoints ls " + std::to_string(kStyleEquilibrium) + pts, "steady sliding")
     << ", \\\n     "
     << curve(3, "linespoints ls " + std::to_string(kStyleStickSlip) + pts, "stick-slip")
     << ", \\\n     "
     << curve(4, "linespoints ls " + std::to_string(kStylePureSlip) + pts, "pure slip")
     << ", \\\n     " << curve(5, "lines ls " + std::to_string(kStyleThreshold), "undecided")
     << "\nunset output\n";
  return os.str();
}

}  // namespace stickslip
