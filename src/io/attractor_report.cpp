// Basins' tables and figure on a section (io/attractor_report.hpp).
#include "stickslip/io/attractor_report.hpp"

#include <cmath>
#include <sstream>

#include "numerics/numbers.hpp"
#include "stickslip/errors.hpp"
#include "stickslip/io/system_branch_report.hpp"

namespace stickslip {

std::string AttractorLabel(const Attractor& a) {
  const std::string s = std::to_string(a.sticks) + (a.sticks == 1 ? " stick" : " sticks");
  switch (a.kind) {
    case AttractorKind::kPeriodic:
      return "period " + std::to_string(a.m) + ", " + s;
    case AttractorKind::kChaotic:  // the measured mean (issue 35: 0.66, not ~1)
      return "chaotic, " + Num(a.sticks_per_period, 2) + " sticks/period";
    default:
      return Name(a.kind);
  }
}

TsvTable AttractorStartTable(const System& sys, const AttractorBasins& b, const StartSlice& g) {
  const std::string u = StateColumn(sys, g.components[0]), w = StateColumn(sys, g.components[1]);
  TsvTable t({u, w, "attractor", "kind", "m", "sticks", "lyapunov"});
  for (const AttractorStart& s : b.starts)  // failed, or undecided for want of a return
    if (s.attractor >= 0 && !s.message.empty())
      t.AddComment(std::string(Name(b.attractors[s.attractor].kind)) + ": " + u + " = " +
                   FormatNumber(s.at[0]) + ", " + w + " = " + FormatNumber(s.at[1]) + ": " +
                   s.message);
  for (const AttractorStart& s : b.starts) {
    if (s.attractor < 0) continue;
    const Attractor& a = b.attractors[s.attractor];
    const bool measured = HasExponent(a.kind);
    if (measured && !std::isfinite(s.lyapunov))
      throw InvalidArgument("basin start " + u + " = " + FormatNumber(s.at[0]) +
                            " has a non-finite exponent");
    t.AddRow(
        {s.at[0], s.at[1], s.attractor, Name(a.kind), a.m, a.sticks, measured ? s.lyapunov : 0.0});
  }
  return t;
}

TsvTable AttractorTable(const System& sys, const AttractorBasins& b) {
  const int nt = sys.tangent_dimension();
  std::vector<std::string> cols = {"attractor", "kind", "m", "sticks"};
  for (int i = 0; i < nt; ++i) cols.push_back(StateColumn(sys, i));
  cols.insert(cols.end(), {"lyapunov", "starts", "fraction", "label", "sticks_per_period"});
  TsvTable t(cols);
  int total = 0;
  for (const Attractor& a : b.attractors) total += a.starts;
  for (size_t i = 0; i < b.attractors.size(); ++i) {
    const Attractor& a = b.attractors[i];
    std::vector<TsvTable::Cell> row = {static_cast<int>(i), Name(a.kind), a.m, a.sticks};
    for (int c = 0; c < nt; ++c) row.push_back(a.z[c]);
    row.insert(row.end(), {std::isfinite(a.lyapunov) ? a.lyapunov : 0.0, a.starts,
                           total > 0 ? static_cast<double>(a.starts) / total : 0.0,
                           AttractorLabel(a), a.sticks_per_period});
    t.AddRow(row);
  }
  return t;
}

namespace {
// The key's words for attractor a: its label ("~" is gnuplot's overprint:
// written as the sign it means), the section point that tells two periodic
// attractors of one label apart, and its count of starts.
std::string KeyLabel(const Attractor& a, const std::string& x) {
  std::string label = AttractorLabel(a);
  const size_t tilde = label.find('~');
  if (tilde != std::string::npos) label.replace(tilde, 1, "≈");
  if (a.kind == AttractorKind::kPeriodic) label += ", " + x + " = " + Num(a.z[0], 3);
  return label + " (" + std::to_string(a.starts) + " starts)";
}
// The section points of every periodic attractor's cycle (all m of them) as
// the data block $cycles; its header line is what `set datafile
// columnheaders` takes. A NaN row keeps the block plottable when it is empty.
std::string CycleBlock(const AttractorBasins& b, const std::string& u, const std::string& w,
                       const StartSlice& g) {
  std::ostringstream os;
  os << "$cycles << EOD\nattractor\t" << u << "\t" << w << "\n";
  int rows = 0;
  for (size_t i = 0; i < b.attractors.size(); ++i)
    for (const auto& q : b.attractors[i].cycle)
      if (b.attractors[i].kind == AttractorKind::kPeriodic)
        os << i << "\t" << FormatNumber(q[g.components[0]]) << "\t"
           << FormatNumber(q[g.components[1]]) << "\n",
            ++rows;
  if (rows == 0) os << "-1\tNaN\tNaN\n";
  return os.str() + "EOD\n";
}
// Quasi-periodic or slow: a grey that shows on the page and in the key.
constexpr const char* kUndecidedGrey = "#bdbdbd";
}  // namespace

std::string AttractorScript(const System& sys, const AttractorBasins& b, const StartSlice& g,
                            const AttractorFigure& f, const std::string& title,
                            FigureFormat format) {
  const std::string u = StateColumn(sys, g.components[0]), w = StateColumn(sys, g.components[1]);
  const double dx = (g.hi[0] - g.lo[0]) / std::max(1, g.n[0] - 1) / 2;
  const double dy = (g.hi[1] - g.lo[1]) / std::max(1, g.n[1] - 1) / 2;
  std::ostringstream os;
  os << "# " << f.comment << "\n"
     << FigurePreamble(format, 900, 900) << CycleBlock(b, u, w, g) << "set output '"
     << FigureFile(f.stem, format) << "'\nset title " << GnuplotQuoted(title) << "\nset xlabel "
     << GnuplotQuoted(f.xlabel) << "\nset ylabel " << GnuplotQuoted(f.ylabel)
     << "\nunset grid\n"
     // the key below: a row per attractor and one for the section points
     << "set bmargin " << 5.5 + static_cast<double>(b.attractors.size() + 1) << "\nset xrange ["
     << FormatNumber(g.lo[0] - dx) << ":" << FormatNumber(g.hi[0] + dx) << "]\nset yrange ["
     << FormatNumber(g.lo[1] - dy) << ":" << FormatNumber(g.hi[1] + dy)
     << "]\nset style fill solid 1.0 noborder\nplot ";
  for (size_t i = 0; i < b.attractors.size(); ++i) {
    const Attractor& a = b.attractors[i];
    const char* colour = a.kind == AttractorKind::kChaotic       ? "#000000"
                         : a.kind == AttractorKind::kUndecided   ? kUndecidedGrey
                         : a.kind == AttractorKind::kUnbounded   ? "#ffffff"
                         : a.kind == AttractorKind::kContactLost ? kFillContactLost
                         : a.kind == AttractorKind::kSettling    ? kFillSettling
                                                                 : SeriesColor(static_cast<int>(i));
    os << (i ? ", \\\n     " : "") << "'" << f.stem << ".tsv' using '" << u
       << "':(column('attractor') == " << i << " ? column('" << w << "') : 1/0):("
       << FormatNumber(1.02 * dx) << "):("  // 2%: no seams
       << FormatNumber(1.02 * dy) << ") with boxxyerror lc rgb '" << colour << "' title "
       << GnuplotQuoted(KeyLabel(a, StateColumn(sys, 0)));
  }
  os << (b.attractors.empty() ? "" : ", \\\n     ") << "$cycles using '" << u << "':'" << w
     << "' with points pt 7 ps 1.4 lc rgb 'white' notitle, \\\n     $cycles using '" << u << "':'"
     << w
     << "' with points pt 6 ps 1.4 lw 2 lc rgb 'black' title "
        "'the m section points of each periodic attractor'\n";
  return os.str();
}

}  // namespace stickslip
