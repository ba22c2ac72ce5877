// chart.gp: the chart figure (chart_report.hpp). Regions are filled polygons
// between the exact curves; the curves, codim-2 points and labels on top; the
// key below the frame.
#include <algorithm>
#include <cmath>
#include <sstream>

#include "stickslip/io/chart_report.hpp"

namespace stickslip {

namespace {
struct Symbol {
  const char* name;
  const char* symbol;  // gnuplot enhanced text
};
constexpr Symbol kSymbols[] = {
    {"v", "v"},      {"beta", "β"},  {"mu_s", "μ_s"}, {"mu_m", "μ_m"}, {"v_m", "v_m"},
    {"mu_k", "μ_k"}, {"v_s", "v_s"}, {"delta", "δ"},  {"k5", "k_5"},
};

const Symbol* Find(const std::string& name) {
  for (const Symbol& s : kSymbols)
    if (name == s.name) return &s;
  return nullptr;
}

std::string SymbolOf(const std::string& name) {
  const Symbol* s = Find(name);
  return s ? s->symbol : name;
}

// Region fills in Region's order: the kinds' fills of figure_style.hpp (as the
// basins), bistable purple.
const char* const kFill[] = {kFillEquilibrium, kFillStickSlip, kFillPureSlip, "#d9b3ef"};

// Polygons, largest first: a face inside a hole is painted over the face
// around. Vertices in the figure's units (u1, u2 per parameter).
void Polygons(std::ostream& os, const ChartResult& r, double u1, double u2) {
  int id = 1;
  for (const RegionFace& rf : r.faces) {
    const auto& ring = rf.face.outer;
    os << "set object " << id++ << " polygon from " << u1 * ring[0][0] << "," << u2 * ring[0][1];
    for (size_t i = 1; i <= ring.size(); ++i)
      os << " \\\n  to " << u1 * ring[i % ring.size()][0] << "," << u2 * ring[i % ring.size()][1];
    os << " \\\n  fc rgb '" << kFill[static_cast<int>(rf.region)]
       << "' fs solid 1.0 noborder behind\n";
  }
}

// Codim-2 labels: one per point (equal labels within kSameLabel of the
// rectangle are one point); a label whose default place (up right) is within
// kClashX by kClashY of an earlier point's goes down right, then up left, then
// down left.
constexpr double kSameLabel = 0.01, kClashX = 0.06, kClashY = 0.04;
void Codim2Labels(std::ostream& os, const ChartResult& r, const Plane& pl) {
  struct Placed {
    double x, y;
  };
  std::vector<Placed> placed;
  std::vector<const Codim2Point*> shown;
  for (const Codim2Point& p : r.codim2) {
    bool dup = false;
    for (const Codim2Point* q : shown)
      dup = dup || (q->label == p.label && std::abs(q->p1 - p.p1) < kSameLabel * pl.width1() &&
                    std::abs(q->p2 - p.p2) < kSameLabel * pl.width2());
    if (dup) continue;
    shown.push_back(&p);
    const double dx[] = {1, 1, -1, -1}, dy[] = {1, -1, 1, -1};
    int k = 0;
    for (; k < 3; ++k) {
      const double x = p.p1 + dx[k] * 0.03 * pl.width1(), y = p.p2 + dy[k] * 0.03 * pl.width2();
      bool clash = false;
      for (const Placed& q : placed)
        clash = clash || (std::abs(q.x - x) < kClashX * pl.width1() &&
                          std::abs(q.y - y) < kClashY * pl.width2());
      if (!clash) break;
    }
    placed.push_back({p.p1 + dx[k] * 0.03 * pl.width1(), p.p2 + dy[k] * 0.03 * pl.width2()});
    os << "set label '" << Name(p.label) << "' at up*" << p.p1 << ",up2*" << p.p2 << " offset "
       << (dx[k] > 0 ? "0.8" : "-0.8") << "," << (dy[k] > 0 ? "0.9" : "-0.9") << " "
       << (dx[k] > 0 ? "left" : "right") << " front font ',13' noenhanced\n";
  }
}

// The key entries of the curves present, then the curves from curves.tsv.
void Curves(std::ostream& os, const ChartResult& r) {
  struct Style {
    CurveKind kind;
    CurvePointType type;
    const char* color;
    const char* dash;
    const char* title;
  };
  const Style styles[] = {
      {CurveKind::kHopf, CurvePointType::kSupercritical, "black", "1", "HB, supercritical"},
      {CurveKind::kHopf, CurvePointType::kSubcritical, "black", "(7,5)", "HB, subcritical"},
      {CurveKind::kGrazing, CurvePointType::kPersistence, "#c00000", "1", "GR, persistence"},
      {CurveKind::kGrazing, CurvePointType::kNonsmoothFold, "#c00000", "(7,5)",
       "GR, nonsmooth fold"},
      {CurveKind::kFold, CurvePointType::kFold, "#009e73", "1",
       "LP, pure-slip fold"},  // green: not on blue
  };
  for (const Style& st : styles) {
    bool present = false;
    for (const Curve& c : r.curves)
      for (const CurvePoint& p : c.points)
        present = present || (c.kind == st.kind && p.type == st.type);
    if (!present) continue;
    for (size_t i = 0; i < r.curves.size(); ++i) {
      if (r.curves[i].kind != st.kind) continue;
      os << ", \\\n     'curves.tsv' using ($1*up):(($4 == " << i + 1 << " && strcol(9) eq '"
         << Name(st.type) << "') ? $2*up2 : NaN) with lines lw 2.5 lc rgb '" << st.color << "' dt "
         << st.dash;
      os << (present ? std::string(" title '") + st.title + "'" : std::string(" notitle"));
      present = false;  // one key entry per style
    }
  }
}

// The inset: where two or more codimension-two points crowd into a corner
// (their box, padded, under 30 % of each range), a zoom of that box in
// the corner of the frame farthest from it, with the box outlined on the chart.
// The plot area on the page (the margins of ChartScript), and the inset's size
// as a fraction of it.
constexpr double kL = 0.11, kR = 0.96, kB = 0.21, kT = 0.93, kInsetW = 0.38, kInsetH = 0.45,
                 kInsetPad = 0.03, kInsetTics = 0.05;  // room for its y tic labels
constexpr double kCrowded = 0.3;  // the padded box's largest side, of the chart's range
struct Zoom {
  double lo1 = 0, hi1 = 0, lo2 = 0, hi2 = 0;
};
bool CrowdedCorner(const ChartResult& r, const Plane& pl, Zoom* z) {
  if (r.codim2.size() < 2) return false;
  z->lo1 = z->hi1 = r.codim2[0].p1, z->lo2 = z->hi2 = r.codim2[0].p2;
  for (const Codim2Point& p : r.codim2) {
    z->lo1 = std::min(z->lo1, p.p1), z->hi1 = std::max(z->hi1, p.p1);
    z->lo2 = std::min(z->lo2, p.p2), z->hi2 = std::max(z->hi2, p.p2);
  }
  const double pad1 = std::max(0.35 * (z->hi1 - z->lo1), 0.03 * pl.width1());
  const double pad2 = std::max(0.35 * (z->hi2 - z->lo2), 0.03 * pl.width2());
  z->lo1 = std::max(pl.from1, z->lo1 - pad1), z->hi1 = std::min(pl.to1, z->hi1 + pad1);
  z->lo2 = std::max(pl.from2, z->lo2 - pad2), z->hi2 = std::min(pl.to2, z->hi2 + pad2);
  return z->hi1 - z->lo1 < kCrowded * pl.width1() && z->hi2 - z->lo2 < kCrowded * pl.width2();
}
void Inset(std::ostream& os, const ChartResult& r, const Plane& pl, const Zoom& z, double u1,
           double u2) {
  // the corner of the frame farthest from the zoomed box's centre
  const bool right = (z.lo1 + z.hi1) / 2 - pl.from1 < pl.width1() / 2;
  const bool top = (z.lo2 + z.hi2) / 2 - pl.from2 < pl.width2() / 2;
  const double w = kInsetW * (kR - kL), h = kInsetH * (kT - kB);
  const double x0 = right ? kR - kInsetPad - w : kL + kInsetPad + kInsetTics;
  const double y0 = top ? kT - kInsetPad - h : kB + kInsetPad;
  os << "# the inset: the crowded corner, zoomed\n"
     << "set lmargin at screen " << x0 << "\nset rmargin at screen " << x0 + w
     << "\nset bmargin at screen " << y0 << "\nset tmargin at screen " << y0 + h << "\n"
     << "unset object 90\nset xrange [" << u1 * z.lo1 << ":" << u1 * z.hi1 << "]\nset yrange ["
     << u2 * z.lo2 << ":" << u2 * z.hi2 << "]\n"
     << "unset key\nunset title\nunset xlabel\nunset ylabel\nset border 15 front lw 1.5\n"
     << "set xtics in mirror font ',9'\nset ytics in mirror font ',9'\nplot NaN notitle";
  Curves(os, r);
  os << ", \\\n     'codim2.tsv' using ($2*up):($3*up2) with points pt 7 ps 1.4 lc rgb 'black' "
        "notitle\n";
}
}  // namespace

std::string ChartTitle(const Params& base, const Plane& plane) {
  const char* law[] = {"cubic", "Coulomb", "Stribeck", "Leine"};  // LawKind's order
  const int k = static_cast<int>(base.law);
  std::string t =
      std::string("Stability chart, ") + (k >= 0 && k < 4 ? law[k] : Name(base.law)) + " law";
  const char* sep = ": ";
  for (const auto& name : ParameterNames(base.law)) {
    if (name == plane.p1.name() || name == plane.p2.name()) continue;
    if (name == "k5" && base.k5 == 0) continue;
    t += sep + SymbolOf(name) + " = " + FormatNumber(GetParameter(base, name));
    sep = ", ";
  }
  return t;
}

std::string ChartScript(const ChartResult& r, const Plane& plane, const std::string& title,
                        FigureFormat format, const FigureUnits& units) {
  const double u1 = units.p1.factor, u2 = units.p2.factor;
  std::ostringstream os;
  os.precision(17);
  os << "# Stability chart written by ss_chart; run `gnuplot chart.gp` in this directory.\n"
     << "# Regions: the polygons of regions.tsv. Curves (curves.tsv): HB black, GR red,\n"
     << "# solid supercritical / persistence, dashed subcritical / nonsmooth fold; LP green.\n"
     << "if (!exists('suffix')) suffix = ''\n"
     << FigureTerminal(format, 1000, 820) << "set output '" << FigureFile("chart", format)
     << "'.suffix\n"
     << "set datafile separator '\\t'\n"
     << "set datafile columnheaders\n"
     << "set encoding utf8\n"
     << FigureUnitVariables(units) << "set xlabel " << GnuplotQuoted(units.P1Label(plane.p1))
     << "\nset ylabel " << GnuplotQuoted(units.P2Label(plane.p2)) << "\n"
     << "set xrange [" << u1 * plane.from1 << ":" << u1 * plane.to1 << "]\n"
     << "set yrange [" << u2 * plane.from2 << ":" << u2 * plane.to2 << "]\n"
     << "set title \"" << title << "\"\n"
     << "set lmargin at screen " << kL << "\nset rmargin at screen " << kR << "\n"
     << "set tmargin at screen " << kT << "\nset bmargin at screen " << kB << "\n"
     << "set key at screen 0.53, screen 0.015 center bottom horizontal maxcols 3 width 1 "
        "samplen 3\n"
     << "set tics out nomirror\nset border 3 front\n";
  Polygons(os, r, u1, u2);
  Codim2Labels(os, r, plane);
  Zoom zoom;
  const bool inset = CrowdedCorner(r, plane, &zoom);
  if (inset)
    os << "set multiplot\nset object 90 rect from " << u1 * zoom.lo1 << "," << u2 * zoom.lo2
       << " to " << u1 * zoom.hi1 << "," << u2 * zoom.hi2
       << " fs empty border lc rgb 'black' lw 1 front\n";
  os << "plot ";
  const char* sep = "";
  for (int k = 0; k < 4; ++k) {
    bool present = false;
    for (const RegionFace& f : r.faces) present = present || static_cast<int>(f.region) == k;
    if (!present) continue;
    os << sep << "NaN with boxes fs solid 1.0 lc rgb '" << kFill[k] << "' title '"
       << Name(static_cast<Region>(k)) << "'";
    sep = ", \\\n     ";
  }
  if (*sep == 0) os << "NaN notitle";
  Curves(os, r);
  os << ", \\\n     'codim2.tsv' using ($2*up):($3*up2) with points pt 7 ps 1.4 lc rgb 'black' "
        "notitle\n";
  if (inset) {
    Inset(os, r, plane, zoom, u1, u2);
    os << "unset multiplot\n";
  }
  os << "unset output\n";
  return os.str();
}

}  // namespace stickslip
