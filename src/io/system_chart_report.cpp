// A system's chart as files (stickslip/io/system_chart_report.hpp).
#include "stickslip/io/system_chart_report.hpp"

#include <algorithm>
#include <complex>
#include <sstream>

#include "stickslip/io/response_report.hpp"
#include "stickslip/io/system_branch_report.hpp"

namespace stickslip {

TsvTable SystemCurvesTable(const System& s, const SystemChart& c) {
  const SystemPlane& pl = c.plane;
  const int nt = s.tangent_dimension();
  std::vector<std::string> cols = {s.ParameterName(pl.p1),
                                   s.ParameterName(pl.p2),
                                   "curve",
                                   "id",
                                   "m",
                                   "period",
                                   "sticks",
                                   "crossings"};
  for (int i = 0; i < s.dimension(); ++i) cols.push_back(StateColumn(s, i) + "_0");
  for (int i = 0; i < nt; ++i) cols.push_back(StateColumn(s, i) + "_min");
  for (int i = 0; i < nt; ++i) cols.push_back(StateColumn(s, i) + "_max");
  cols.insert(cols.end(), {"mult_max", "test"});
  TsvTable t(cols);
  for (std::size_t k = 0; k < c.curves.size(); ++k) {
    const SystemCurve& cv = c.curves[k];
    const std::string margin = cv.kind != CurveKind::kGrazing ? ""
                               : cv.gap                       ? " (the gap to the surface)"
                                        : " (an arrival's margin to the static limit)";
    t.AddComment("curve " + std::to_string(k + 1) + " " + CurveLabel(cv.kind) + margin + ": from " +
                 cv.seed + "; ends " + cv.ends.Text());
    const int m = cv.kind == CurveKind::kHopf ? 0 : PeriodMultiple(cv.section);
    for (const SystemCurvePoint& p : cv.points) {
      const OrbitRow& o = p.orbit;
      std::vector<TsvTable::Cell> row = {
          p.p1,     p.p2,     CurveLabel(cv.kind), static_cast<int>(k + 1), m,
          o.period, o.sticks, o.crossings};
      for (int i = 0; i < s.dimension(); ++i)
        row.emplace_back(i < o.start.z.size() ? o.start.z[i] : 0.0);
      const bool hb = cv.kind == CurveKind::kHopf;
      for (const Eigen::VectorXd* v : {&o.lo, &o.hi})
        for (int i = 0; i < nt; ++i) row.emplace_back(hb ? o.start.z[i] : (*v)[i]);
      double mult = 0;
      for (const auto& m : o.multipliers) mult = std::max(mult, std::abs(m));
      row.emplace_back(mult);
      row.emplace_back(p.test);
      t.AddRow(row);
    }
  }
  return t;
}

TsvTable SystemCodim2Table(const System& s, const SystemChart& c) {
  TsvTable t({"label", s.ParameterName(c.plane.p1), s.ParameterName(c.plane.p2), "curve", "on",
              "description", "located"});
  for (const SystemCodim2& p : c.codim2)
    t.AddRow(
        {Name(p.label), p.p1, p.p2, p.curve + 1, CurveLabel(p.on), p.description, Name(p.method)});
  return t;
}

std::string SystemChartScript(const System& s, const SystemChart& c, const std::string& title,
                              FigureFormat format, const ResponseGrid* grid) {
  const bool cells = grid != nullptr && grid->n1 > 0;
  const SystemPlane& pl = c.plane;
  struct Style {
    CurveKind kind;
    const char *color, *dash, *title;
  };
  const Style styles[] = {
      {CurveKind::kHopf, "#c00000", "1", "HB of steady sliding"},
      {CurveKind::kFold, "black", "1", "LP, fold"},
      {CurveKind::kPeriodDoubling, "black", "(8,4)", "PD, period doubling"},
      {CurveKind::kTorus, "#ff00ff", "(10,4,2,4)", "NS, Neimark-Sacker"},
      {CurveKind::kGrazing, "#0060c0", "1", "GR, grazing or crossing-sliding"},
  };
  std::ostringstream os;
  os.precision(17);
  os << "# A system's chart written by ss_chart; run `gnuplot chart.gp` in this directory.\n"
     << "# curves.tsv: HB red, LP black, PD black dashed, NS magenta, GR blue; codim2.tsv: SL "
        "open\n"
     << "# circles, the others black dots with their labels"
     << (cells ? "; response.tsv: the cells by the attractor reached.\n" : ".\n")
     << "if (!exists('suffix')) suffix = ''\n"
     << FigureTerminal(format, 900, 700) << "set output '" << FigureFile("chart", format)
     << "'.suffix\n"
     << "set datafile separator '\\t'\nset datafile columnheaders\nset encoding utf8\n"
     << "set xlabel " << GnuplotQuoted(s.ParameterName(pl.p1)) << " noenhanced\n"
     << "set ylabel " << GnuplotQuoted(s.ParameterName(pl.p2)) << " noenhanced\n"
     << "set xrange [" << pl.from1 << ":" << pl.to1 << "]\n"
     << "set yrange [" << pl.from2 << ":" << pl.to2 << "]\n"
     << "set title \"" << title << "\"\n"
     << "set key outside below horizontal font ',11'\n"
     << "set tics out nomirror front\nset border 3 front\n"
     << (cells ? "" : "set grid lc rgb '#e0e0e0'\n");
  for (const SystemCodim2& p : c.codim2)
    if (p.label != Codim2Label::kSliding)
      os << "set label " << GnuplotQuoted(Name(p.label)) << " at " << p.p1 << "," << p.p2
         << " offset 1,0.6 front font ',11' noenhanced\n";
  const ResponseClasses rc = cells ? ClassifyResponses(*grid) : ResponseClasses();
  if (cells) ResponsePalette(os, rc);
  os << "plot ";
  if (cells)
    ResponseRaster(os, *grid, rc, pl.to1 - pl.from1, pl.to2 - pl.from2);
  else
    os << "NaN notitle";
  for (const Style& st : styles) {
    bool first = true;
    for (std::size_t i = 0; i < c.curves.size(); ++i) {
      if (c.curves[i].kind != st.kind) continue;
      os << ", \\\n     'curves.tsv' using 1:($4 == " << i + 1
         << " ? $2 : NaN) with lines lw 2.5 lc rgb '" << st.color << "' dt " << st.dash
         << (first ? std::string(" title ") + GnuplotQuoted(st.title) : std::string(" notitle"));
      first = false;
    }
  }
  const std::string sl = Name(Codim2Label::kSliding);
  const auto is_sl = [](const SystemCodim2& p) { return p.label == Codim2Label::kSliding; };
  if (std::any_of(c.codim2.begin(), c.codim2.end(), is_sl))
    os << ", \\\n     'codim2.tsv' using 2:(strcol(1) eq '" << sl
       << "' ? $3 : NaN) with points pt 6 ps 1.2 lw 1.5 lc rgb 'black' title '" << sl
       << ", the switching sequence changes'";
  if (!std::all_of(c.codim2.begin(), c.codim2.end(), is_sl))
    os << ", \\\n     'codim2.tsv' using 2:(strcol(1) ne '" << sl
       << "' ? $3 : NaN) with points pt 7 ps 1.2 lc rgb 'black' notitle";
  os << "\n";
  return os.str();
}

}  // namespace stickslip
