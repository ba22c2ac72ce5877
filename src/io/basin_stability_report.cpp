#include "stickslip/io/basin_stability_report.hpp"

#include <cstdio>
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
  TsvTable t({c.param.name(), "steady_sliding", "stick_slip", "pure_slip", "undecided", "enclosed"});
  t.AddMeta("model", model_description);
  t.AddMeta("box", "x in [" + FormatNumber(box.x_lo) + ", " + FormatNumber(box.x_hi) +
                       "], xdot in [" + FormatNumber(box.y_lo) + ", " + FormatNumber(box.y_hi) +
                       "]");
  t.AddMeta("status",
            c.status == BasinStatus::kOk
                ? std::string("complete")
                : std::string("partial (") + BasinStatusName(c.status) + "): " + c.message);
  for (size_t i = 0; i < c.p.size(); ++i) {
    const BasinStability& b = c.at[i];
    t.AddRow({c.p[i], b.Of(Fate::kSteadySliding), b.Of(Fate::kStickSlip), b.Of(Fate::kPureSlip),
              b.Of(Fate::kUndecided), b.enclosed.empty() ? 0.0 : b.enclosed.front()});
  }
  return t;
}

std::string BasinStabilityScript(const ParameterAxis& param, const std::string& title,
                                 FigureFormat format, const FigureUnits& units) {
  // The shared style (figure_style.hpp): colour by kind, stable solid (every
  // attractor's basin), a thin dotted gray for the undecided share.
  std::ostringstream os;
  os << "# Basin stability written by ss_basin; run `gnuplot basin_stability.gp` here.\n"
     << "if (!exists('suffix')) suffix = ''\n"
     << FigurePreamble(format, 1000, 720) << FigureUnitVariables(units) << "set output '"
     << FigureFile("basin_stability", format) << "'.suffix\n"
     << "set title " << GnuplotQuoted(FigureTitle(title, {param.name()})) << "\n"
     << "set xlabel " << GnuplotQuoted(units.P1Label(param)) << "\n"
     << "set ylabel 'basin stability (fraction of the box)'\n"
     << "set yrange [-0.02:1.02]\nset autoscale xfix\n"
     << "plot 'basin_stability.tsv' using ($1*up):2 with linespoints ls " << kStyleEquilibrium
     << " pt 7 ps 0.5 title 'steady sliding', \\\n"
     << "     '' using ($1*up):3 with linespoints ls " << kStyleStickSlip
     << " pt 7 ps 0.5 title 'stick-slip', \\\n"
     << "     '' using ($1*up):4 with linespoints ls " << kStylePureSlip
     << " pt 7 ps 0.5 title 'pure slip', \\\n"
     << "     '' using ($1*up):5 with lines ls " << kStyleThreshold << " title 'undecided'\n"
     << "unset output\n";
  return os.str();
}

}  // namespace stickslip
