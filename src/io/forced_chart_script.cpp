// forced_chart.gp (stickslip/io/forced_chart_report.hpp): the response grid
// as filled cells (a raster: chaotic and quasi-periodic zones have no exact
// boundary), the traced curves and the codimension-two points on top, the
// key below the frame.
#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>

#include "stickslip/io/forced_chart_report.hpp"

namespace stickslip {

namespace {

void CurveLines(std::ostream& os, const ForcedChartResult& r) {
  struct Style {
    CurveKind kind;
    const char* color;
    const char* dash;
    double width;
    const char* title;
    const char* dash_multiple;  // the same kind's curves of m >= 2 orbits
  };
  // Every kind and multiple its own line: colour by kind, dash by kind and m.
  const Style styles[] = {
      {CurveKind::kGrazing, "#c00000", "1", 3.5, "GR, non-stop motion ends", "(2,3)"},
      {CurveKind::kFold, "black", "1", 2.5, "LP, fold", "(2,3)"},
      {CurveKind::kPeriodDoubling, "black", "(8,4)", 2.5, "PD, period doubling", "(8,3,2,3)"},
      {CurveKind::kTorus, "#ff00ff", "(10,4,2,4)", 2.5, "NS, Neimark-Sacker", "(2,3)"},
  };
  // Curves of m >= 2 orbits (seeded from doubled branches too): thinner, their own dashes.
  for (const Style& st : styles)
    for (const bool multiple : {false, true}) {
      bool first = true;
      const std::vector<SystemCurve>& curves = r.chart.curves;
      for (size_t i = 0; i < curves.size(); ++i) {
        if (curves[i].kind != st.kind || (curves[i].section.turns > 1) != multiple) continue;
        const std::string title =
            multiple ? std::string(Name(st.kind)) + " of m ≥ 2 orbits" : st.title;
        os << ", \\\n     'curves.tsv' using 1:($4 == " << i + 1 << " ? $2 : NaN) with lines lw "
           << (multiple ? 2.0 : st.width) << " lc rgb '" << st.color << "' dt "
           << (multiple ? st.dash_multiple : st.dash)
           << (first ? " title " + GnuplotQuoted(title) : std::string(" notitle"));
        first = false;
      }
    }
}

// The plot area in pixels (ForcedChartScript's margins on a 1000 x 860 page)
// and a label's size: 8 px per character of the 12-pt font, 16 px high.
constexpr int kPlaces = 16;  // where a label may go: 8 directions, 2 distances
constexpr double kPlotW = 870, kPlotH = 576.2, kCharW = 8, kTextH = 16, kLabelGap = 6;

// Distance in pixels from (x, y) to the segment a-b.
double SegmentDistance(double x, double y, double ax, double ay, double bx, double by) {
  const double dx = bx - ax, dy = by - ay, len2 = dx * dx + dy * dy;
  const double t = len2 > 0 ? std::clamp(((x - ax) * dx + (y - ay) * dy) / len2, 0.0, 1.0) : 0.0;
  return std::hypot(x - ax - t * dx, y - ay - t * dy);
}

// The named codimension-two points' labels, each centred at the one of 16
// places around its point (beside, above, below, diagonal; near and twice as
// far) whose text box keeps the most room from every curve, every
// codimension-two point and the labels placed before it, inside the frame:
// "set label" lines at the centre, in data coordinates.
void Codim2Labels(std::ostream& os, const ForcedChartResult& r, const Plane& pl) {
  const double sx = kPlotW / pl.width1(), sy = kPlotH / pl.width2();
  auto px = [&](double p1, double p2) {
    return std::array<double, 2>{(p1 - pl.from1) * sx, (p2 - pl.from2) * sy};
  };
  struct Box {
    double x, y, hw, hh;  // centre and half sizes, pixels
  };
  std::vector<Box> taken;  // codim-2 points (a dot) and placed labels
  for (const SystemCodim2& p : r.chart.codim2) {
    const auto q = px(p.p1, p.p2);
    taken.push_back({q[0], q[1], 3, 3});
  }
  for (const SystemCodim2& p : r.chart.codim2) {
    if (p.label == Codim2Label::kSliding) continue;
    const std::string name = Name(p.label);
    const double hw = kCharW * name.size() / 2, hh = kTextH / 2;
    const auto at = px(p.p1, p.p2);
    double best = -HUGE_VAL;
    Box pick{at[0] + hw + kLabelGap, at[1], hw, hh};
    for (int k = 0; k < kPlaces; ++k) {
      const double f = k < 8 ? 1 : 2, ux[] = {1, -1, 0, 0, 1, -1, 1, -1},
                   uy[] = {0, 0, 1, -1, 1, 1, -1, -1};
      const Box b{at[0] + f * ux[k % 8] * (hw + kLabelGap),
                  at[1] + f * uy[k % 8] * (hh + kLabelGap), hw, hh};
      if (b.x - hw < 0 || b.x + hw > kPlotW || b.y - hh < 0 || b.y + hh > kPlotH) continue;
      double room = HUGE_VAL;  // to curves: from the box's centre, less its half diagonal
      for (const SystemCurve& c : r.chart.curves)
        for (size_t i = 1; i < c.points.size(); ++i) {
          const auto a = px(c.points[i - 1].p1, c.points[i - 1].p2);
          const auto e = px(c.points[i].p1, c.points[i].p2);
          room = std::min(room,
                          SegmentDistance(b.x, b.y, a[0], a[1], e[0], e[1]) - std::hypot(hw, hh));
        }
      for (const Box& q : taken)  // box to box
        room = std::min(room,
                        std::max(std::abs(b.x - q.x) - hw - q.hw, std::abs(b.y - q.y) - hh - q.hh));
      if (room > best) best = room, pick = b;
    }
    taken.push_back(pick);
    os << "set label " << GnuplotQuoted(name) << " at " << pl.from1 + pick.x / sx << ","
       << pl.from2 + pick.y / sy << " center front font ',12' noenhanced\n";
  }
}

}  // namespace

std::string ForcedChartScript(const ForcedChartResult& r, const Plane& pl, const std::string& title,
                              FigureFormat format) {
  const ResponseGrid& g = r.grid;
  const ResponseClasses c = ClassifyResponses(g);
  std::ostringstream os;
  os.precision(17);
  os << "# Forced chart written by ss_chart; run `gnuplot forced_chart.gp` in this directory.\n"
     << "# Cells (response.tsv): the attractor reached there; curves (curves.tsv): GR red,\n"
     << "# LP black, PD black dashed, NS magenta, m >= 2 thinner with their own dashes; "
        "codim2.tsv: SL open circles, the others black dots with labels.\n"
     << "if (!exists('suffix')) suffix = ''\n"
     << FigureTerminal(format, 1000, 860) << "set output '" << FigureFile("forced_chart", format)
     << "'.suffix\n"
     << "set datafile separator '\\t'\nset datafile columnheaders\nset encoding utf8\n"
     << "set xlabel " << GnuplotQuoted(ParameterAxisLabel(pl.p1)) << "\n"
     << "set ylabel " << GnuplotQuoted(ParameterAxisLabel(pl.p2)) << "\n"
     << "set xrange [" << pl.from1 << ":" << pl.to1 << "]\n"
     << "set yrange [" << pl.from2 << ":" << pl.to2 << "]\n"
     << "set title \"" << title << "\"\n"
     << "set lmargin at screen 0.1\nset rmargin at screen 0.97\n"
     << "set tmargin at screen 0.93\nset bmargin at screen 0.26\n"
     << "set key at screen 0.53, screen 0.01 center bottom horizontal maxcols 4 width 1 "
        "samplen 3 font ',11'\n"
     << "set tics out nomirror front\nset border 3 front\n";
  ResponsePalette(os, c);
  // SL ends are many and crowd where curves bunch: a marker with a key entry,
  // not a text label each; the codimension-two points keep their names.
  Codim2Labels(os, r, pl);
  os << "plot ";
  ResponseRaster(os, g, c, pl.width1(), pl.width2());
  CurveLines(os, r);
  const auto sliding = [](const SystemCodim2& p) { return p.label == Codim2Label::kSliding; };
  const std::string sl = Name(Codim2Label::kSliding);
  const std::vector<SystemCodim2>& codim2 = r.chart.codim2;
  if (std::any_of(codim2.begin(), codim2.end(), sliding))
    os << ", \\\n     'codim2.tsv' using 2:(strcol(1) eq '" << sl
       << "' ? $3 : NaN) with points pt 6 ps 1.2 lw 1.5 lc rgb 'black' title '" << sl
       << ", curve ends: sliding'";
  if (!std::all_of(codim2.begin(), codim2.end(), sliding))
    os << ", \\\n     'codim2.tsv' using 2:(strcol(1) ne '" << sl
       << "' ? $3 : NaN) with points pt 7 ps 1.3 lc rgb 'black' title "
          "'codimension 2'";
  os << "\nunset output\n";
  return os.str();
}

}  // namespace stickslip
