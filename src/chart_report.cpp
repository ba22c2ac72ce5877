#include "stickslip/chart_report.hpp"

#include <sstream>

#include "stickslip/figure_style.hpp"

namespace stickslip {

namespace {
void Header(TsvTable& t, const ChartResult& r, const std::string& model) {
  t.AddComment("model: " + model);
  if (r.status == ChartStatus::kPartial)
    t.AddComment("status: partial: " + r.message);
  else if (r.status != ChartStatus::kOk)
    t.AddComment(std::string("status: partial (") + ChartStatusName(r.status) + "): " + r.message);
  else
    t.AddComment("status: complete");
}
}  // namespace

TsvTable CurvesTable(const ChartResult& r, const Plane& plane, const std::string& model) {
  TsvTable t({plane.p1, plane.p2, "curve", "id", "period", "amplitude", "multiplier", "l1", "type",
              "unphysical"});
  Header(t, r, model);
  for (size_t i = 0; i < r.curves.size(); ++i)
    t.AddComment("curve " + std::to_string(i + 1) + " " + CurveLabel(r.curves[i].kind) + ": " +
                 std::to_string(r.curves[i].points.size()) + " points, ends " + r.curves[i].ends);
  if (r.unphysical_points > 0)
    t.AddComment("unphysical: " + std::to_string(r.unphysical_points) +
                 " points whose orbit visits slip speeds where mu <= 0");
  for (size_t i = 0; i < r.curves.size(); ++i) {
    const Curve& c = r.curves[i];
    for (const CurvePoint& p : c.points) {
      const bool hb = c.kind == CurveKind::kHopf;
      t.AddRow({p.p1, p.p2, CurveLabel(c.kind), static_cast<int>(i + 1), p.period, p.amplitude,
                p.multiplier, hb ? TsvTable::Cell(p.l1) : TsvTable::Cell("-"), p.type,
                p.unphysical ? 1 : 0});
    }
  }
  return t;
}

TsvTable Codim2Table(const ChartResult& r, const Plane& plane, const std::string& model) {
  TsvTable t({"label", plane.p1, plane.p2, "description"});
  Header(t, r, model);
  for (const Codim2Point& p : r.codim2) t.AddRow({p.label, p.p1, p.p2, p.description});
  return t;
}

TsvTable RegionsTable(const ChartResult& r, const Plane& plane, const std::string& model) {
  TsvTable t({plane.p1, plane.p2, "region", "name"});
  Header(t, r, model);
  const RegionGrid& g = r.regions;
  for (int i = 0; i < g.n1; ++i)
    for (int j = 0; j < g.n2; ++j)
      t.AddRow({g.x1[i], g.x2[j], static_cast<int>(g.at(i, j)), RegionName(g.at(i, j))});
  return t;
}

std::string ChartScript(const ChartResult& r, const Plane& plane, const std::string& title,
                        FigureFormat format) {
  std::ostringstream os;
  os << "# Stability chart written by ss_chart; run `gnuplot chart.gp` in this directory.\n"
     << "# Shading: regions.tsv. Curves: HB black (solid supercritical, dashed subcritical),\n"
     << "# GR red (solid persistence, dashed nonsmooth fold), LP blue. Points: codim2.tsv.\n"
     << "if (!exists('suffix')) suffix = ''\n"
     << FigureTerminal(format, 1100, 800)
     << "set output '" << FigureFile("chart", format) << "'.suffix\n"
     << "set datafile separator '\\t'\n"
     << "set datafile columnheaders\n"
     << "set xlabel '" << plane.p1 << "' noenhanced\nset ylabel '" << plane.p2 << "' noenhanced\n"
     << "set xrange [" << plane.from1 << ":" << plane.to1 << "]\n"
     << "set yrange [" << plane.from2 << ":" << plane.to2 << "]\n"
     << "set title '" << title << "' noenhanced\n"
     << "set key outside right top\n"
     << "set palette defined (0 '#f2f2f2', 1 '#f2f2f2', 1 '#f4a6a6', 2 '#f4a6a6', "
     << "2 '#a6c8f4', 3 '#a6c8f4', 3 '#d9b3ef', 4 '#d9b3ef')\n"
     << "set cbrange [-0.5:3.5]\nunset colorbox\n"
     << "plot ";
  const char* names[] = {"steady sliding only", "stick-slip", "pure-slip oscillation", "bistable"};
  const char* colors[] = {"#f2f2f2", "#f4a6a6", "#a6c8f4", "#d9b3ef"};
  if (r.regions.n1 > 0) os << "'regions.tsv' using 1:2:3 with image notitle, \\\n     ";
  for (int k = 0; k < 4; ++k)
    os << "NaN with boxes fs solid 1.0 lc rgb '" << colors[k] << "' title '" << names[k]
       << "', \\\n     ";
  bool titled[3] = {false, false, false};
  for (size_t i = 0; i < r.curves.size(); ++i) {
    const CurveKind kind = r.curves[i].kind;
    const int k = static_cast<int>(kind);
    const char* color = kind == CurveKind::kHopf      ? "black"
                        : kind == CurveKind::kGrazing ? "red"
                                                      : "blue";
    const char* solid = kind == CurveKind::kHopf      ? "supercritical"
                        : kind == CurveKind::kGrazing ? "persistence"
                                                      : "fold";
    const char* what[] = {"HB (dashed: subcritical)", "GR (dashed: nonsmooth fold)",
                          "LP (pure-slip fold)"};
    for (int dashed : {0, 1}) {
      if (kind == CurveKind::kFold && dashed) continue;
      os << "'curves.tsv' using 1:(($4 == " << i + 1 << " && (strcol(9) eq '" << solid
         << "') == " << (dashed ? 0 : 1) << ") ? $2 : NaN) with lines lw 2.5 lc rgb '" << color
         << "' dt " << (dashed ? 2 : 1) << " "
         << (titled[k] || dashed ? std::string("notitle") : "title '" + std::string(what[k]) + "'")
         << ", \\\n     ";
      titled[k] = titled[k] || !dashed;
    }
  }
  os << "'codim2.tsv' using 2:3 with points pt 7 ps 1.5 lc rgb 'black' notitle, \\\n"
     << "     'codim2.tsv' using 2:3:1 with labels offset 1.5,0.8 font ',12' notitle\n"
     << "unset output\n";
  return os.str();
}

}  // namespace stickslip
