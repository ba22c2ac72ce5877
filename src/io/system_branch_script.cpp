// bifurcation.gp of a system's run (system_branch_report.hpp): three panels
// against the parameter, each kind and stability its own line style
// (figure_style.hpp: stable solid, unstable dashed), the located points
// marked and labelled on the first; for the forced oscillator where it
// applies, Den Hartog's closed-form amplitude on the first too.
#include <algorithm>
#include <set>
#include <sstream>

#include "stickslip/io/system_branch_report.hpp"
#include "stickslip/systems/forced/forced.hpp"

namespace stickslip {

namespace {

// A title line's length in characters: the figure is 1000 px wide, and
// chain10's lines of 104-108 ran past its edges at kTitleWidth.
constexpr std::size_t kSystemTitleWidth = 96;

// What the script needs of a row: its branch, kind (K's code), stability and
// whether it is a located point (a light pass over the run, no copy of the rows).
struct Line {
  int branch = 0, kind = 0;
  bool stable = false, special = false;
};

std::vector<Line> Lines(const SystemRun& run) {
  std::vector<Line> out;
  out.reserve(run.steady.rows.size());
  for (const SteadyRow& r : run.steady.rows)
    out.push_back({0, 0, r.state.stable(), r.label != SpecialKind::kNone});
  for (std::size_t b = 0; b < run.pieces.size(); ++b)
    for (const OrbitRow& r : run.pieces[b].rows)
      out.push_back({b < run.numbers.size() ? run.numbers[b] : static_cast<int>(b) + 1,
                     r.sticks > 0 ? 1 : 2, r.stable, r.label != SpecialKind::kNone});
  return out;
}

int Style(const std::string& kind, bool stable) {
  const int base = kind == "stick-slip"  ? kStyleStickSlip
                   : kind == "pure-slip" ? kStylePureSlip
                                         : kStyleEquilibrium;
  return stable ? base : base + 1;
}

// The kinds by their code in the script's array K.
constexpr const char* kKinds[] = {"equilibrium", "stick-slip", "pure-slip"};

// One panel: the columns `ys` (their blocks of the array Y) of every (kind,
// stability) that has rows, one curve each over all branches; the key names
// each once. A segment between two rows of a branch takes the style of the
// row that is not a located point (where the stability or the kind changes),
// else the later row's, so that every segment is drawn once (sel, below).
void Panel(std::ostream& os, const std::vector<Line>& lines, const std::vector<int>& ys, bool key,
           bool orbits_only) {
  std::set<std::pair<int, bool>> drawn;
  for (const Line& l : lines)
    if (!(orbits_only && l.branch == 0)) drawn.insert({l.kind, l.stable});
  bool first = true;
  os << "plot ";
  for (const auto& [k, stable] : drawn)
    for (const int y : ys) {
      const bool title = key && y == ys.front();
      const bool marks = !stable && k > 0;  // a short unstable piece shows between dashes
      os << (first ? "" : ", \\\n  ") << "D using (X[row($1)]):(sel($1, " << k << ", " << stable
         << ", " << y << ")) with " << (marks ? "linespoints" : "lines") << " ls "
         << Style(kKinds[k], stable) << (marks ? " pt 6 ps 0.5 " : " ")
         << (title ? "title '" + std::string(kKinds[k]) + (stable ? ", stable'" : ", unstable'")
                   : "notitle");
      first = false;
    }
}

// The rows into arrays (X, branch B, kind K, stable S; Y the columns drawn,
// block y of N each), so that a segment takes one style: a style's line runs
// through the entries 2i - 1 (row i) and 2i (row i again if the segment to
// row i + 1 is that style's, else a break) of the dummy array D.
void Arrays(std::ostream& os, const std::string& p, const std::string& x, bool orbits) {
  const std::vector<std::string> ys =
      orbits ? std::vector<std::string>{x + "_max", x + "_min", "period", "mult_max"}
             : std::vector<std::string>{x + "_max", x + "_min"};
  os << "array X[N]; array B[N]; array K[N]; array S[N]; array D[2*N]; array Y[" << ys.size()
     << "*N]\ndo for [i = 1:" << ys.size() << "*N] { Y[i] = NaN }\n"
     << "stats 'branch.tsv' using (i = int($0) + 1, X[i] = c('" << p
     << "'), B[i] = c('branch'), K[i] = (strcol('kind') eq 'stick-slip' ? 1 : strcol('kind') eq "
        "'pure-slip' ? 2 : 0), S[i] = c('stable'), 0) nooutput\n";
  for (std::size_t y = 0; y < ys.size(); ++y)
    os << "stats 'branch.tsv' using (Y[" << y << " * N + int($0) + 1] = c('" << ys[y]
       << "'), 0) nooutput\n";
  os << "owner(i) = P[i + 1] && !P[i] ? i : i + 1\n"
     << "seg(i, k, s) = i >= 1 && i < N && B[i] == B[i + 1] ? (K[owner(i)] == k && "
        "S[owner(i)] == s) : 0\n"
     << "row(j) = int((j + 1) / 2)\n"
     << "sel(j, k, s, y) = int(j) % 2 ? (seg(row(j) - 1, k, s) || seg(row(j), k, s) ? "
        "Y[y * N + row(j)] : NaN) : (seg(row(j), k, s) ? Y[y * N + row(j)] : NaN)\n";
}

// Den Hartog's (1931) closed form for a forced system's non-stop motion:
// Coulomb friction with mu_s = mu_k, no damping, no belt (v = 0), continued
// in Omega; else "".
std::string DenHartogCurve(const System& s, const std::string& p, const std::set<int>& branches) {
  const auto* f = dynamic_cast<const ForcedBelt*>(&s);
  if (!f || p != "omega") return "";
  const Params& b = f->params().base;
  if (!(b.law == LawKind::kCoulomb && b.mu_s == b.mu_k && b.v == 0 && b.beta == 0)) return "";
  // X = sqrt(V^2 - (mu U)^2), V = A / (1 - W^2), U = sin(pi / W) / (W (1 + cos(pi / W))),
  // real where the motion has no stop: drawn on the computed pure-slip rows only.
  std::ostringstream os;
  os << "mu = " << FormatNumber(b.mu_k) << "; A = " << FormatNumber(f->force()) << "\n"
     << "V(w) = A / (1 - w*w); U(w) = sin(pi/w) / (w * (1 + cos(pi/w)))\n"
     << "D(w) = V(w)**2 - (mu * U(w))**2\n"
     << "DH(w) = D(w) > 0 ? sqrt(D(w)) : 1/0\n";
  bool first = true;  // one curve per branch: none across a gap
  for (const int k : branches) {
    os << (first ? "" : ", \\\n  ") << "'branch.tsv' using '" << p << "':(c('branch') == " << k
       << " && strcol('kind') eq 'pure-slip' ? DH(c('" << p << "')) : 1/0) with lines lw 1 "
       << "dt (4, 6) lc rgb 'black' "
       << (first ? "title 'Den Hartog (1931) closed form'" : "notitle");
    first = false;
  }
  return os.str();
}

// The figure's title: the run's description wrapped; the forced
// oscillator's as the belt's figures write theirs (FigureTitle: its law, then
// its coefficients and forcing but the continued one, in symbols).
std::string Heading(const System& s, const std::string& title, const std::string& p) {
  const auto* f = dynamic_cast<const ForcedBelt*>(&s);
  if (!f) return EnhancedText(WrapWords(title, kSystemTitleWidth), false);
  const LawKind law = f->params().base.law;
  std::string d = "law=" + std::string(Name(law));
  std::vector<std::string> names = ParameterNames(law);
  names.insert(names.end(), {"force", "omega"});
  for (const std::string& n : names)
    d += " " + n + "=" + FormatNumber(s.ParameterValue(s.ParameterIndex(n)));
  return FigureTitle(d, {p});
}

}  // namespace

std::vector<std::string> SystemBranchFigures(FigureFormat format) {
  return {FigureFile("bifurcation", format)};
}

std::string SystemBranchScript(const System& s, const SystemRun& run, const std::string& title,
                               FigureFormat format) {
  const std::vector<Line> lines = Lines(run);
  const std::string p = s.ParameterName(run.parameter);
  const std::string x = StateColumn(s, 0);
  int specials = 0;
  bool orbits = false;  // without orbit rows: the first panel alone
  for (const Line& l : lines) {
    specials += l.special;
    orbits = orbits || l.branch > 0;
  }
  std::ostringstream os;
  os << "# The bifurcation figure of ss_continue --system: " << s.StateName(0)
     << "'s extremes, the period and the largest |multiplier| against " << p << ".\n"
     << FigurePreamble(format, 1000, orbits ? 1150 : 560) << "set output '"
     << FigureFile("bifurcation", format) << "'\n";
  if (lines.empty())  // nothing computed: an empty frame that says so
    return os.str() + "set title " + GnuplotQuoted(Heading(s, title, p)) +
           "\nset xrange [0:1]\nset yrange [0:1]\nset label 1 'no rows' at graph 0.5, graph 0.5 "
           "center\nplot NaN notitle\n";
  os << "c(name) = column(name)\n"
     << "stats 'branch.tsv' using 1 nooutput\nN = STATS_records\narray P[N]\n"
     << "do for [i = 1:N] { P[i] = 0 }\n";
  if (specials > 0) os << "stats 'special_points.tsv' using (P[int(c('pt'))] = 1, 0) nooutput\n";
  Arrays(os, p, x, orbits);
  os << "set multiplot layout " << (orbits ? 3 : 1) << ", 1 title "
     << GnuplotQuoted(Heading(s, title, p)) << "\n"
     << "set xlabel " << GnuplotQuoted(EnhancedText(p)) << "\nset autoscale xfix\n"
     << "set ylabel " << GnuplotQuoted(EnhancedText(s.StateName(0) + " (min and max)")) << "\n"
     << "set offsets 0, 0, graph 0.12, graph 0.05\n";
  for (std::size_t i = 0; i + 1 < run.gap.size(); i += 2)  // shaded in every panel
    os << "set object " << i / 2 + 1 << " rect from "
       << FormatNumber(std::min(run.gap[i], run.gap[i + 1])) << ", graph 0 to "
       << FormatNumber(std::max(run.gap[i], run.gap[i + 1]))
       << ", graph 1 fc rgb '#e8e8e8' fs solid noborder behind\nset label " << i / 2 + 1
       << " 'not traced: unbounded' at " << FormatNumber(std::max(run.gap[i], run.gap[i + 1]))
       << ", graph 0.93 offset 1, 0 tc rgb '#555555'\n";
  std::set<int> branches;
  for (const Line& l : lines)
    if (l.branch > 0) branches.insert(l.branch);
  const std::string dh = DenHartogCurve(s, p, branches);  // its functions, then its plot terms
  const std::size_t split = dh.rfind("DH(w) =");
  const std::size_t terms = split == std::string::npos ? 0 : dh.find('\n', split) + 1;
  os << dh.substr(0, terms);
  Panel(os, lines, {0, 1}, true, false);
  if (!dh.empty()) os << ", \\\n  " << dh.substr(terms);
  // The located points, labelled above and below in turn (gnuplot 5.4
  // crashes on a labels plot without a defined point: the second only with two).
  if (specials > 0)
    os << ", \\\n  'special_points.tsv' using '" << p << "':'" << x << "_max' with points ls "
       << kStyleSpecial << " notitle";
  for (int k = 0; k < std::min(specials, 2); ++k)
    os << ", \\\n  'special_points.tsv' using '" << p << "':(int($0) % 2 == " << k << " ? c('" << x
       << "_max') : 1/0):'lab' with labels offset 0, " << (k ? "-1.2" : "1.2")
       << " boxed font ',10' notitle";
  if (orbits) {
    os << "\nunset label\nset key off\nset bmargin 3.5\nset offsets 0, 0, graph 0.05, graph 0.05\n"
       << "set ylabel 'period'\n";
    Panel(os, lines, {2}, false, true);
    os << "\nset ylabel 'largest |Floquet multiplier|'\nset yrange [0:*]\n";
    Panel(os, lines, {3}, false, true);
    os << ", \\\n  1 with lines ls " << kStyleThreshold << " notitle";  // stability's edge
  }
  os << "\nunset multiplot\n";
  return os.str();
}

}  // namespace stickslip
