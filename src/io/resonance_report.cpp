// The forced branch as TSV tables and the resonance figure's script.
#include "stickslip/io/resonance_report.hpp"

#include <cmath>
#include <map>
#include <sstream>

#include "stickslip/errors.hpp"

namespace stickslip {

namespace {

std::vector<std::string> Columns(ParameterAxis axis) {
  return {"branch",   axis.name(), "m",        "sticks",   "crossings", "kind",  "x_min",
          "x_max",    "xdot_min",  "xdot_max", "period",   "x0",        "xdot0", "mult1_re",
          "mult1_im", "mult2_re",  "mult2_im", "mult_max", "stable",    "pt"};
}

std::vector<TsvTable::Cell> Cells(const OrbitRow& r, int piece, const OrbitBranch& branch,
                                  const ForcedParams& p, ParameterAxis axis) {
  ForcedParams at = p;
  axis.Set(at, r.p);
  const int m = PeriodMultiple(branch);
  const double period = m * 2 * M_PI / at.omega;
  const double mult_max = std::max(std::abs(r.multipliers[0]), std::abs(r.multipliers[1]));
  const Extrema e = RowExtrema(r);
  const double numbers[] = {r.p,
                            e.x_min,
                            e.x_max,
                            e.xdot_min,
                            e.xdot_max,
                            period,
                            r.start.z[0],
                            r.start.z[1],
                            r.multipliers[0].real(),
                            r.multipliers[0].imag(),
                            r.multipliers[1].real(),
                            r.multipliers[1].imag(),
                            mult_max};
  for (double x : numbers)
    if (!std::isfinite(x))
      throw InvalidArgument("forced branch row at " + std::string(axis.name()) + " = " +
                            FormatNumber(r.p) + " has a non-finite value");
  return {piece,           r.p,         m,
          r.sticks,        r.crossings, r.sticks > 0 ? "stick-slip" : "non-stop",
          numbers[1],      numbers[2],  numbers[3],
          numbers[4],      period,      numbers[6],
          numbers[7],      numbers[8],  numbers[9],
          numbers[10],     numbers[11], mult_max,
          r.stable ? 1 : 0};
}

// Every row with its piece (1-based), its point number (pt, 1-based over the
// pieces) and, for the special ones, the label with its index per type (GR1,
// CR1, PD1, ...).
template <class F>
void ForEachRow(const std::vector<OrbitBranch>& pieces, F f) {
  int pt = 0;
  std::map<SpecialKind, int> count;
  for (size_t i = 0; i < pieces.size(); ++i)
    for (const OrbitRow& r : pieces[i].rows) {
      ++pt;
      const std::string lab = r.label == SpecialKind::kNone
                                  ? ""
                                  : std::string(Name(r.label)) + std::to_string(++count[r.label]);
      f(static_cast<int>(i) + 1, pieces[i], r, pt, lab);
    }
}

}  // namespace

TsvTable ForcedBranchTable(const std::vector<OrbitBranch>& pieces, ParameterAxis axis,
                           const ForcedParams& p) {
  auto cols = Columns(axis);
  TsvTable t(cols);
  ForEachRow(pieces,
             [&](int piece, const OrbitBranch& b, const OrbitRow& r, int pt, const std::string&) {
               auto cells = Cells(r, piece, b, p, axis);
               cells.push_back(pt);
               t.AddRow(cells);
             });
  return t;
}

TsvTable ForcedSpecialTable(const std::vector<OrbitBranch>& pieces, ParameterAxis axis,
                            const ForcedParams& p) {
  auto cols = Columns(axis);
  cols.insert(cols.begin(), "label");
  cols.insert(cols.end(), {"lab", "description"});
  TsvTable t(cols);
  ForEachRow(pieces, [&](int piece, const OrbitBranch& b, const OrbitRow& r, int pt,
                         const std::string& lab) {
    if (lab.empty()) return;
    auto cells = Cells(r, piece, b, p, axis);
    cells.insert(cells.begin(), Name(r.label));
    cells.insert(cells.end(), {pt, lab, r.description});
    t.AddRow(cells);
  });
  return t;
}

bool DenHartogApplies(const ForcedParams& p, ParameterAxis axis) {
  return axis == Parameter::kOmega && p.base.law == LawKind::kCoulomb &&
         p.base.mu_s == p.base.mu_k && p.base.v == 0 && p.base.beta == 0;
}

// Den Hartog (1931): X = sqrt(V^2 - (mu U)^2), V = A / (1 - W^2),
// U = sin(pi / W) / (W (1 + cos(pi / W))), real where the motion has no stop.
std::string ResonanceScript(const ForcedParams& p, ParameterAxis axis, int pieces,
                            const std::string& title, const std::vector<double>& gap, int specials,
                            FigureFormat format) {
  const std::string ax = axis.name();
  std::ostringstream os;
  os << "# The resonance figure of ss_continue (forced oscillator): x_max against " << ax << ".\n"
     << FigurePreamble(format, 1000, 720) << "set output '" << FigureFile("resonance", format)
     << "'\nset title " << GnuplotQuoted(FigureTitle(title, {ax})) << "\nset xlabel "
     << GnuplotQuoted(ParameterAxisLabel(axis) +
                      (axis == Parameter::kOmega ? " (over the natural one)" : ""))
     << "\nset ylabel 'largest displacement x_{max} (dimensionless)'\nset yrange [0:*]\n"
     << "set offsets 0, 0, graph 0.1, 0  # room above the top point for its label\n"
     << "set autoscale xfix\n"
     << "c(name) = column(name)\n"
     // The rows into arrays (X, Y, branch B, non-stop K, stable S, located P),
     // so that each segment between rows i and i+1 takes one style: that of
     // the row that is not a located point (a special point is where the
     // stability changes), else the later row's. A style's line is drawn
     // through array entries 2i - 1 (row i) and 2i (row i again if the
     // segment to row i + 1 is that style's, else a break).
     << "stats 'branch.tsv' using 1 nooutput\nN = STATS_records\n"
     << "array X[N]; array Y[N]; array B[N]; array K[N]; array S[N]; array P[N]; array D[2*N]\n"
     << "array R[4] = [0, 0, 0, 0]  # rows per style: a key entry only for a drawn style\n"
     << "stats 'branch.tsv' using (i = int($0) + 1, X[i] = c('" << ax
     << "'), Y[i] = c('x_max'), B[i] = c('branch'), K[i] = (strcol('kind') eq 'non-stop'), "
        "S[i] = c('stable'), P[i] = 0, R[1 + 2 * K[i] + S[i]] = R[1 + 2 * K[i] + S[i]] + 1, 0) "
        "nooutput\n";
  if (specials > 0) os << "stats 'special_points.tsv' using (P[int(c('pt'))] = 1, 0) nooutput\n";
  os << "owner(i) = P[i + 1] && !P[i] ? i : i + 1\n"
     << "seg(i, k, s) = i >= 1 && i < N && B[i] == B[i + 1] ? (K[owner(i)] == k && "
        "S[owner(i)] == s) : 0\n"
     << "row(j) = int((j + 1) / 2)\n"
     << "sel(j, k, s) = int(j) % 2 ? (seg(row(j) - 1, k, s) || seg(row(j), k, s) ? Y[row(j)] : "
        "NaN) "
        ": (seg(row(j), k, s) ? Y[row(j)] : NaN)\n";
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
  for (int k = 0; k < 2; ++k)
    for (int s = 1; s >= 0; --s) {
      os << (first ? "  " : ", \\\n  ") << "D using (X[row($1)]):(sel($1, " << 1 - k << ", " << s
         << ")) with lines ls " << styles[k] + 1 - s << " title (R[" << 1 + 2 * (1 - k) + s
         << "] > 0 ? '" << kinds[k] << (s ? ", stable" : ", unstable") << "' : '')";
      first = false;
    }
  for (int b = 1; b <= pieces && dh; ++b)  // on the computed non-stop rows only
    os << ", \\\n  'branch.tsv' using '" << ax << "':(c('branch') == " << b
       << " && strcol('kind') eq 'non-stop' ? DH(c('" << ax << "')) : 1/0) with lines lw 1 "
       << "dt (4, 6) lc rgb 'black' "
       << (b == 1 ? "title 'Den Hartog (1931) closed form'" : "notitle");
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
