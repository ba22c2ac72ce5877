// chart.gp (stickslip/io/system_chart_report.hpp): the response grid as
// filled cells (a raster: chaotic and quasi-periodic zones have no exact
// boundary), the traced curves and the codimension-two points on top, each
// named point's label placed off the curves, the key below the frame.
#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>

#include "stickslip/io/response_report.hpp"
#include "stickslip/io/system_chart_report.hpp"
#include "stickslip/systems/belt/parameter_axis.hpp"

namespace stickslip {

namespace {

// The rectangle's widths.
double Width1(const SystemPlane& pl) { return pl.to1 - pl.from1; }
double Width2(const SystemPlane& pl) { return pl.to2 - pl.from2; }

// A parameter's axis words ("forcing frequency Ω") where it is one of the
// belt's or forcing's, else its name in enhanced text (k12 -> k_{12}).
std::string AxisLabel(const System& s, int j) {
  Parameter id = Parameter::kV;
  return FromName(s.ParameterName(j), &id) ? ParameterAxisLabel(ParameterAxis(id))
                                           : EnhancedText(s.ParameterName(j));
}

void CurveLines(std::ostream& os, const SystemChart& c) {
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
      {CurveKind::kHopf, "#e66100", "1", 3.5, "HB of steady sliding", "1"},
      {CurveKind::kGrazing, "#c00000", "1", 3.5, "GR, grazing", "(2,3)"},
      {CurveKind::kFold, "black", "1", 2.5, "LP, fold", "(2,3)"},
      {CurveKind::kPeriodDoubling, "black", "(8,4)", 2.5, "PD, period doubling", "(8,3,2,3)"},
      {CurveKind::kTorus, "#ff00ff", "(10,4,2,4)", 2.5, "NS, Neimark-Sacker", "(2,3)"},
  };
  for (const Style& st : styles)
    for (const bool multiple : {false, true}) {
      bool first = true;
      for (size_t i = 0; i < c.curves.size(); ++i) {
        const SystemCurve& cv = c.curves[i];
        // Period multiples of a clock's (an autonomous orbit's returns are no multiple).
        const bool m2 = cv.section.kind == SectionKind::kTime && cv.section.turns > 1;
        if (cv.kind != st.kind || m2 != multiple) continue;
        const std::string title =
            multiple ? std::string(Name(st.kind)) + " of m >= 2 orbits" : st.title;
        os << ", \\\n     'curves.tsv' using 1:($4 == " << i + 1 << " ? $2 : NaN) with lines lw "
           << (multiple ? 2.0 : st.width) << " lc rgb '" << st.color << "' dt "
           << (multiple ? st.dash_multiple : st.dash)
           << (first ? " title " + GnuplotQuoted(title) : std::string(" notitle"));
        first = false;
      }
    }
}

// The plot area in pixels (about gnuplot's on the 1000 x 860 page with a key
// of 3 rows of 4 or 6 of 3) and a label's size: 8 px per character of the
// 12-pt font, 16 px high.
constexpr int kPlaces = 16;  // where a label may go: 8 directions, 2 distances
constexpr double kPlotW = 870, kPlotH = 576.2, kCharW = 8, kTextH = 16, kLabelGap = 6;

// Distance in pixels from (x, y) to the segment a-b.
double SegmentDistance(double x, double y, double ax, double ay, double bx, double by) {
  const double dx = bx - ax, dy = by - ay, len2 = dx * dx + dy * dy;
  const double t = len2 > 0 ? std::clamp(((x - ax) * dx + (y - ay) * dy) / len2, 0.0, 1.0) : 0.0;
  return std::hypot(x - ax - t * dx, y - ay - t * dy);
}

struct Box {
  double x, y, hw, hh;  // centre and half sizes, pixels
};

// Room in pixels between box b and every curve and taken box.
double Room(const Box& b, const SystemChart& c, const std::vector<Box>& taken, double sx,
            double sy) {
  const SystemPlane& pl = c.plane;
  double room = HUGE_VAL;  // to curves: from the box's centre, less its half diagonal
  for (const SystemCurve& cv : c.curves)
    for (size_t i = 1; i < cv.points.size(); ++i) {
      const SystemCurvePoint &a = cv.points[i - 1], &e = cv.points[i];
      room =
          std::min(room, SegmentDistance(b.x, b.y, (a.p1 - pl.from1) * sx, (a.p2 - pl.from2) * sy,
                                         (e.p1 - pl.from1) * sx, (e.p2 - pl.from2) * sy) -
                             std::hypot(b.hw, b.hh));
    }
  for (const Box& q : taken)  // box to box
    room = std::min(room,
                    std::max(std::abs(b.x - q.x) - b.hw - q.hw, std::abs(b.y - q.y) - b.hh - q.hh));
  return room;
}

// The named codimension-two points' labels, each centred at the one of 16
// places around its point (beside, above, below, diagonal; near and twice as
// far) whose text box keeps the most room from every curve, every
// codimension-two point and the labels placed before it, inside the frame:
// "set label" lines at the centre, in data coordinates.
void Codim2Labels(std::ostream& os, const SystemChart& c) {
  const SystemPlane& pl = c.plane;
  const double sx = kPlotW / Width1(pl), sy = kPlotH / Width2(pl);
  std::vector<Box> taken;  // codim-2 points (a dot) and placed labels
  for (const SystemCodim2& p : c.codim2)
    taken.push_back({(p.p1 - pl.from1) * sx, (p.p2 - pl.from2) * sy, 3, 3});
  for (const SystemCodim2& p : c.codim2) {
    if (p.label == Codim2Label::kSliding) continue;
    const std::string name = Name(p.label);
    const double hw = kCharW * name.size() / 2, hh = kTextH / 2;
    const double x = (p.p1 - pl.from1) * sx, y = (p.p2 - pl.from2) * sy;
    double best = -HUGE_VAL;
    Box pick{x + hw + kLabelGap, y, hw, hh};
    for (int k = 0; k < kPlaces; ++k) {
      const double f = k < 8 ? 1 : 2, ux[] = {1, -1, 0, 0, 1, -1, 1, -1},
                   uy[] = {0, 0, 1, -1, 1, 1, -1, -1};
      const Box b{x + f * ux[k % 8] * (hw + kLabelGap), y + f * uy[k % 8] * (hh + kLabelGap), hw,
                  hh};
      if (b.x - hw < 0 || b.x + hw > kPlotW || b.y - hh < 0 || b.y + hh > kPlotH) continue;
      const double room = Room(b, c, taken, sx, sy);
      if (room > best) best = room, pick = b;
    }
    taken.push_back(pick);
    os << "set label " << GnuplotQuoted(name) << " at " << pl.from1 + pick.x / sx << ","
       << pl.from2 + pick.y / sy << " center front font ',12' noenhanced\n";
  }
}

void Codim2Points(std::ostream& os, const SystemChart& c) {
  const auto sliding = [](const SystemCodim2& p) { return p.label == Codim2Label::kSliding; };
  const std::string sl = Name(Codim2Label::kSliding);
  if (std::any_of(c.codim2.begin(), c.codim2.end(), sliding))
    os << ", \\\n     'codim2.tsv' using 2:(strcol(1) eq '" << sl
       << "' ? $3 : NaN) with points pt 6 ps 1.6 lw 2 lc rgb 'black' title '" << sl
       << ", sliding end'";
  if (!std::all_of(c.codim2.begin(), c.codim2.end(), sliding))
    os << ", \\\n     'codim2.tsv' using 2:(strcol(1) ne '" << sl
       << "' ? $3 : NaN) with points pt 7 ps 1.3 lc rgb 'black' title 'codimension 2'";
}

}  // namespace

std::string SystemChartScript(const System& s, const SystemChart& c, const std::string& title,
                              FigureFormat format, const ResponseGrid* grid) {
  const bool cells = grid != nullptr && grid->n1 > 0;
  const SystemPlane& pl = c.plane;
  std::ostringstream os;
  os.precision(17);
  os << "# A chart written by ss_chart; run `gnuplot chart.gp` in this directory.\n"
     << "# curves.tsv: HB orange, GR red, LP black, PD black dashed, NS magenta, m >= 2 thinner "
        "with\n"
     << "# their own dashes; codim2.tsv: SL open circles, the others black dots with labels"
     << (cells ? "; response.tsv: the cells by the attractor reached.\n" : ".\n")
     << "if (!exists('suffix')) suffix = ''\n"
     << FigureTerminal(format, 1000, 860) << "set output '" << FigureFile("chart", format)
     << "'.suffix\n"
     << "set datafile separator '\\t'\nset datafile columnheaders\nset encoding utf8\n"
     << "set xlabel " << GnuplotQuoted(AxisLabel(s, pl.p1)) << " offset 0,0.5\n"
     << "set ylabel " << GnuplotQuoted(AxisLabel(s, pl.p2)) << "\n"
     << "set xrange [" << pl.from1 << ":" << pl.to1 << "]\n"
     << "set yrange [" << pl.from2 << ":" << pl.to2 << "]\n"
     << "set title " << GnuplotQuoted(title)
     << "\n"
     // Margins by gnuplot, so the key below fits at any --size (a column: fewer
     // key columns, more rows); the label places assume the screen size's plot area.
     << "set rmargin 3\n"
     << "set key outside below center horizontal maxcols 4 width 0 samplen 2 font ',11'\n"
     << "set tics out nomirror front\nset border 3 front\n"
     << (cells ? "" : "set grid lc rgb '#e0e0e0'\n");
  const ResponseClasses rc = cells ? ClassifyResponses(*grid) : ResponseClasses();
  if (cells) ResponsePalette(os, rc);
  // SL ends are many and crowd where curves bunch: a marker with a key entry,
  // not a text label each; the codimension-two points keep their names.
  Codim2Labels(os, c);
  os << "plot ";
  if (cells)
    ResponseRaster(os, *grid, rc, Width1(pl), Width2(pl));
  else
    os << "NaN notitle";
  CurveLines(os, c);
  Codim2Points(os, c);
  os << "\nunset output\n";
  return os.str();
}

}  // namespace stickslip
