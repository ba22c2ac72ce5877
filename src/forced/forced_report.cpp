// The forced branch as TSV tables and the resonance figure's script.
#include <cmath>
#include <map>
#include <sstream>

#include "stickslip/errors.hpp"
#include "stickslip/forced/report.hpp"

namespace stickslip {

namespace {

std::vector<std::string> Columns(ForcedAxis axis) {
  return {
      "branch",   ForcedAxisName(axis), "m",        "sticks",   "crossings", "kind",  "x_min",
      "x_max",    "xdot_min",           "xdot_max", "period",   "x0",        "xdot0", "mult1_re",
      "mult1_im", "mult2_re",           "mult2_im", "mult_max", "stable",    "pt"};
}

std::vector<TsvTable::Cell> Cells(const ForcedBranchRow& r, int piece, const ForcedParams& p,
                                  ForcedAxis axis) {
  ForcedParams at = p;
  SetAxis(at, axis, r.p);
  const double period = r.m * 2 * M_PI / at.omega;
  const double mult_max = std::max(std::abs(r.multipliers[0]), std::abs(r.multipliers[1]));
  const double numbers[] = {r.p,
                            r.extrema.x_min,
                            r.extrema.x_max,
                            r.extrema.xdot_min,
                            r.extrema.xdot_max,
                            period,
                            r.x0,
                            r.xdot0,
                            r.multipliers[0].real(),
                            r.multipliers[0].imag(),
                            r.multipliers[1].real(),
                            r.multipliers[1].imag(),
                            mult_max};
  for (double x : numbers)
    if (!std::isfinite(x))
      throw InvalidArgument("forced branch row at " + std::string(ForcedAxisName(axis)) + " = " +
                            FormatNumber(r.p) + " has a non-finite value");
  return {piece,           r.p,         r.m,
          r.sticks,        r.crossings, r.sticks > 0 ? "stick-slip" : "non-stop",
          numbers[1],      numbers[2],  numbers[3],
          numbers[4],      period,      r.x0,
          r.xdot0,         numbers[8],  numbers[9],
          numbers[10],     numbers[11], mult_max,
          r.stable ? 1 : 0};
}

// Every row with its point number (pt, 1-based over the pieces) and, for the
// special ones, the label with its index per type (GR1, CR1, PD1, ...).
template <class F>
void ForEachRow(const std::vector<ForcedPiece>& pieces, F f) {
  int pt = 0;
  std::map<ForcedLabel, int> count;
  for (const ForcedPiece& piece : pieces)
    for (const ForcedBranchRow& r : piece.branch.rows) {
      ++pt;
      const std::string lab =
          r.label == ForcedLabel::kNone
              ? ""
              : std::string(ForcedLabelName(r.label)) + std::to_string(++count[r.label]);
      f(piece, r, pt, lab);
    }
}

}  // namespace

TsvTable ForcedBranchTable(const std::vector<ForcedPiece>& pieces, ForcedAxis axis,
                           const ForcedParams& p) {
  auto cols = Columns(axis);
  TsvTable t(cols);
  ForEachRow(pieces,
             [&](const ForcedPiece& piece, const ForcedBranchRow& r, int pt, const std::string&) {
               auto cells = Cells(r, piece.index, p, axis);
               cells.push_back(pt);
               t.AddRow(cells);
             });
  return t;
}

TsvTable ForcedSpecialTable(const std::vector<ForcedPiece>& pieces, ForcedAxis axis,
                            const ForcedParams& p) {
  auto cols = Columns(axis);
  cols.insert(cols.begin(), "label");
  cols.insert(cols.end(), {"lab", "description"});
  TsvTable t(cols);
  ForEachRow(pieces, [&](const ForcedPiece& piece, const ForcedBranchRow& r, int pt,
                         const std::string& lab) {
    if (lab.empty()) return;
    auto cells = Cells(r, piece.index, p, axis);
    cells.insert(cells.begin(), ForcedLabelName(r.label));
    cells.insert(cells.end(), {pt, lab, r.description});
    t.AddRow(cells);
  });
  return t;
}

bool DenHartogApplies(const ForcedParams& p, ForcedAxis axis) {
  return axis == ForcedAxis::kOmega && p.base.law == LawKind::kCoulomb &&
         p.base.mu_s == p.base.mu_k && p.base.v == 0 && p.base.beta == 0;
}

// Den Hartog (1931): X = sqrt(V^2 - (mu U)^2), V = A / (1 - W^2),
// U = sin(pi / W) / (W (1 + cos(pi / W))), real where the motion has no stop.
std::string ResonanceScript(const ForcedParams& p, ForcedAxis axis, int pieces,
                            const std::string& title, const std::vector<double>& gap, int specials,
                            FigureFormat format) {
  const std::string ax = ForcedAxisName(axis);
  std::ostringstream os;
  os << "# The resonance figure of ss_continue (forced oscillator): x_max against " << ax << ".\n"
     << FigurePreamble(format, 1000, 720) << "set output '" << FigureFile("resonance", format)
     << "'\nset title " << GnuplotQuoted(FigureTitle(title, {ax})) << "\nset xlabel "
     << GnuplotQuoted(ParameterAxisLabel(axis) +
                      (axis == ForcedAxis::kOmega ? " (over the natural one)" : ""))
     << "\nset ylabel 'largest displacement x_{max} (dimensionless)'\nset yrange [0:*]\n"
     << "set autoscale xfix\n"
     << "c(name) = column(name)\n"
     << "in(b, k, s) = c('branch') == b && strcol('kind') eq k && c('stable') == s\n"
     << "# a style's rows, and the row after each of its runs (no gap at a change)\n"
     << "sel(b, k, s) = (cur = in(b, k, s), out = (cur || (prev && c('branch') == b)) ? "
        "c('x_max') : 1/0, prev = cur, out)\n";
  if (gap.size() == 2)
    os << "set object 1 rect from " << FormatNumber(std::min(gap[0], gap[1])) << ", graph 0 to "
       << FormatNumber(std::max(gap[0], gap[1])) << ", graph 1 fc rgb '#e8e8e8' fs solid "
       << "noborder behind\nset label 1 'not traced: |x| unbounded' at "
       << FormatNumber(std::max(gap[0], gap[1])) << ", graph 0.93 offset 1, 0 tc rgb '#555555'\n";
  const bool dh = DenHartogApplies(p, axis);
  if (dh)  // a fifth key entry: a third row below the plot
    os << "set bmargin 8.5\nmu = " << FormatNumber(p.base.mu_k) << "; A = " << FormatNumber(p.force)
       << "\n"
       << "V(w) = A / (1 - w*w); U(w) = sin(pi/w) / (w * (1 + cos(pi/w)))\n"
       << "D(w) = V(w)**2 - (mu * U(w))**2\n"
       << "DH(w) = D(w) > 0 ? sqrt(D(w)) : 1/0\n";
  os << "plot \\\n";
  // The belt figures' styles (figure_style.hpp): stick-slip blue, non-stop
  // (pure slip) vermillion; stable solid, unstable dashed.
  const char* kinds[] = {"non-stop", "stick-slip"};
  const int styles[] = {kStylePureSlip, kStyleStickSlip};
  bool first = true;
  for (int b = 1; b <= pieces; ++b)
    for (int k = 0; k < 2; ++k)
      for (int s = 1; s >= 0; --s) {
        os << (first ? "  " : ", \\\n  ") << "prev = 0, 'branch.tsv' using '" << ax << "':(sel("
           << b << ", '" << kinds[k] << "', " << s << ")) with lines ls " << styles[k] + 1 - s
           << " ";
        if (b == 1)
          os << "title '" << kinds[k] << (s ? ", stable" : ", unstable") << "'";
        else
          os << "notitle";
        first = false;
      }
  for (int b = 1; b <= pieces && dh; ++b)  // on the computed non-stop rows only
    os << ", \\\n  'branch.tsv' using '" << ax << "':(c('branch') == " << b
       << " && strcol('kind') eq 'non-stop' ? DH(c('" << ax << "')) : 1/0) with lines lw 1 "
       << "lc rgb 'black' " << (b == 1 ? "title 'Den Hartog (1931) closed form'" : "notitle");
  // LP, PD, NS and the sliding points, located (special_points.tsv), labelled
  // LP1, PD1, ... above and below in turn, so that neighbours do not overlap.
  if (specials > 0)
    os << ", \\\n  'special_points.tsv' using '" << ax << "':'x_max' with points ls "
       << kStyleSpecial << " notitle, \\\n  'special_points.tsv' using '" << ax
       << "':(int($0) % 2 == 0 ? c('x_max') : 1/0):'lab' with labels offset 0, 1.2 boxed "
       << "font ',10' notitle";
  // (gnuplot 5.4 crashes on a labels plot without one defined point: only with a second point)
  if (specials > 1)
    os << ", \\\n  'special_points.tsv' using '" << ax
       << "':(int($0) % 2 == 1 ? c('x_max') : 1/0):'lab' with labels offset 0, -1.2 boxed "
       << "font ',10' notitle";
  os << "\n";
  return os.str();
}

}  // namespace stickslip
