// The forced branch's resonance figure script (resonance_report.hpp).
#include "stickslip/io/resonance_report.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace stickslip {

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
     << "'), Y[i] = c('x_max'), B[i] = c('branch'), K[i] = (strcol('kind') eq 'pure-slip'), "
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
  // The belt figures' styles (figure_style.hpp): stick-slip blue, pure-slip
  // (non-stop) vermillion; stable solid, unstable dashed.
  const char* kinds[] = {"pure-slip", "stick-slip"};  // the tables' kind
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
       << " && strcol('kind') eq 'pure-slip' ? DH(c('" << ax << "')) : 1/0) with lines lw 1 "
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
