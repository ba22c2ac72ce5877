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

TsvTable BasinStabilityTable(const BasinStabilityCurve& c, const std::string& param,
                             const std::string& model_description, const Box& box) {
  TsvTable t({param, "steady_sliding", "stick_slip", "pure_slip", "undecided", "enclosed"});
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

std::string BasinStabilityScript(const std::string& param, const std::string& title) {
  std::ostringstream os;
  os << "# Basin stability written by ss_basin; run `gnuplot basin_stability.gp` here.\n"
     << "if (!exists('suffix')) suffix = ''\n"
     << "set terminal pngcairo size 900,600 enhanced font ',12'\n"
     << "set output 'basin_stability.png'.suffix\n"
     << "set datafile separator '\\t'\n"
     << "set datafile columnheaders\n"
     << "set title '" << title << "' noenhanced\n"
     << "set xlabel '" << param << "' noenhanced\n"
     << "set ylabel 'basin stability (fraction of the box)'\n"
     << "set yrange [-0.02:1.02]\nset key outside right top\nset grid\n"
     << "plot 'basin_stability.tsv' using 1:2 with linespoints lw 2 pt 7 ps 0.6 "
        "lc rgb '#3182bd' title 'steady sliding', \\\n"
     << "     '' using 1:3 with linespoints lw 2 pt 7 ps 0.6 lc rgb '#e6550d' "
        "title 'stick-slip', \\\n"
     << "     '' using 1:4 with linespoints lw 2 pt 7 ps 0.6 lc rgb '#31a354' "
        "title 'pure slip', \\\n"
     << "     '' using 1:5 with lines lw 1 dt 2 lc rgb 'gray40' title 'undecided'\n"
     << "unset output\n";
  return os.str();
}

}  // namespace stickslip
