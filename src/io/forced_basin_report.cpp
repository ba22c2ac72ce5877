// Forced basins' tables and figure (io/forced_basin_report.hpp).
#include "stickslip/io/forced_basin_report.hpp"

#include <cmath>
#include <sstream>

#include "numerics/numbers.hpp"
#include "stickslip/errors.hpp"

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

TsvTable ForcedBasinTable(const ForcedBasins& b) {
  TsvTable t({"x", "xdot", "attractor", "kind", "m", "sticks", "lyapunov"});
  for (const ForcedBasinStart& s : b.starts)
    if (s.attractor >= 0 && !s.message.empty())
      t.AddComment("failed: x = " + FormatNumber(s.x) + ", xdot = " + FormatNumber(s.xdot) + ": " +
                   s.message);
  for (const ForcedBasinStart& s : b.starts) {
    if (s.attractor < 0) continue;
    const Attractor& a = b.attractors[s.attractor];
    const bool measured = a.kind != AttractorKind::kFailed && a.kind != AttractorKind::kUnbounded;
    if (measured && !std::isfinite(s.lyapunov))
      throw InvalidArgument("basin start x = " + FormatNumber(s.x) + " has a non-finite exponent");
    t.AddRow({s.x, s.xdot, s.attractor, Name(a.kind), a.m, a.sticks, measured ? s.lyapunov : 0.0});
  }
  return t;
}

TsvTable AttractorTable(const ForcedBasins& b) {
  TsvTable t({"attractor", "kind", "m", "sticks", "x", "xdot", "lyapunov", "starts", "fraction",
              "label", "sticks_per_period"});
  int total = 0;
  for (const Attractor& a : b.attractors) total += a.starts;
  for (size_t i = 0; i < b.attractors.size(); ++i) {
    const Attractor& a = b.attractors[i];
    t.AddRow({static_cast<int>(i), Name(a.kind), a.m, a.sticks, a.x, a.xdot,
              std::isfinite(a.lyapunov) ? a.lyapunov : 0.0, a.starts,
              total > 0 ? static_cast<double>(a.starts) / total : 0.0, AttractorLabel(a),
              a.sticks_per_period});
  }
  return t;
}

namespace {
// The key's words for attractor a: its label ("~" is gnuplot's overprint:
// written as the sign it means), the section point that tells two periodic
// attractors of one label apart, and its count of starts.
std::string KeyLabel(const Attractor& a) {
  std::string label = AttractorLabel(a);
  const size_t tilde = label.find('~');
  if (tilde != std::string::npos) label.replace(tilde, 1, "≈");
  if (a.kind == AttractorKind::kPeriodic) label += ", x = " + Num(a.x, 3);
  return label + " (" + std::to_string(a.starts) + " starts)";
}
// The section points of every periodic attractor's cycle (all m of them) as
// the data block $cycles; its header line is what `set datafile
// columnheaders` takes. A NaN row keeps the block plottable when it is empty.
std::string CycleBlock(const ForcedBasins& b) {
  std::ostringstream os;
  os << "$cycles << EOD\nattractor\tx\txdot\n";
  int rows = 0;
  for (size_t i = 0; i < b.attractors.size(); ++i)
    for (const auto& q : b.attractors[i].cycle)
      if (b.attractors[i].kind == AttractorKind::kPeriodic)
        os << i << "\t" << FormatNumber(q[0]) << "\t" << FormatNumber(q[1]) << "\n", ++rows;
  if (rows == 0) os << "-1\tNaN\tNaN\n";
  return os.str() + "EOD\n";
}
// Quasi-periodic or slow: a grey that shows on the page and in the key.
constexpr const char* kUndecidedGrey = "#bdbdbd";
}  // namespace

std::string ForcedBasinScript(const ForcedBasins& b, const ForcedBasinOptions& o,
                              const std::string& title, FigureFormat format) {
  const double dx = (o.x_hi - o.x_lo) / std::max(1, o.nx - 1) / 2;
  const double dy = (o.xdot_hi - o.xdot_lo) / std::max(1, o.ny - 1) / 2;
  std::ostringstream os;
  os << "# Basins on the stroboscopic section (forcing phase 0) of ss_basin --force.\n"
     << FigurePreamble(format, 900, 900) << CycleBlock(b) << "set output '"
     << FigureFile("basins_forced", format) << "'\nset title " << GnuplotQuoted(title)
     << "\nset xlabel 'displacement x at forcing phase 0 (dimensionless)'\n"
     << "set ylabel \"velocity x' at forcing phase 0 (dimensionless)\"\nunset grid\n"
     // the key below: a row per attractor and one for the section points
     << "set bmargin " << 5.5 + static_cast<double>(b.attractors.size() + 1) << "\nset xrange ["
     << FormatNumber(o.x_lo - dx) << ":" << FormatNumber(o.x_hi + dx) << "]\nset yrange ["
     << FormatNumber(o.xdot_lo - dy) << ":" << FormatNumber(o.xdot_hi + dy)
     << "]\nset style fill solid 1.0 noborder\nplot ";
  for (size_t i = 0; i < b.attractors.size(); ++i) {
    const Attractor& a = b.attractors[i];
    const char* colour = a.kind == AttractorKind::kChaotic     ? "#000000"
                         : a.kind == AttractorKind::kUndecided ? kUndecidedGrey
                         : a.kind == AttractorKind::kUnbounded ? "#ffffff"
                                                               : SeriesColor(static_cast<int>(i));
    os << (i ? ", \\\n     " : "") << "'basins_forced.tsv' using 'x':(column('attractor') == " << i
       << " ? column('xdot') : 1/0):(" << FormatNumber(1.02 * dx) << "):("  // 2%: no seams
       << FormatNumber(1.02 * dy) << ") with boxxyerror lc rgb '" << colour << "' title "
       << GnuplotQuoted(KeyLabel(a));
  }
  os << (b.attractors.empty() ? "" : ", \\\n     ")
     << "$cycles using 'x':'xdot' with points pt 7 ps 1.4 lc rgb 'white' notitle, \\\n"
        "     $cycles using 'x':'xdot' with points pt 6 ps 1.4 lw 2 lc rgb 'black' title "
        "'the m section points of each periodic attractor'\n";
  return os.str();
}

}  // namespace stickslip
