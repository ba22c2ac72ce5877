// The orbit diagram's tables and figure (stickslip/io/orbit_diagram_report.hpp).
#include "stickslip/io/orbit_diagram_report.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "numerics/tolerances.hpp"
#include "stickslip/errors.hpp"
#include "stickslip/io/report.hpp"
#include "stickslip/io/system_branch_report.hpp"

namespace stickslip {
namespace {

bool Done(const DiagramColumn& c) { return c.computed && c.settled(); }

void AddFailures(const OrbitDiagram& d, const std::string& param, TsvTable& t) {
  for (const DiagramColumn& c : d.columns)
    if (c.computed && !Done(c))
      t.AddComment(std::string(c.run.status == LyapunovStatus::kContactOpen ? "contact lost: "
                                                                            : "failed: ") +
                   Name(c.direction) + " " + param + " = " + FormatNumber(c.value) + ": " +
                   Name(c.run.status) + ", " + c.run.message);
}

void CheckFinite(double x, const DiagramColumn& c, const std::string& param) {
  if (!std::isfinite(x))
    throw InvalidArgument("orbit diagram at " + param + " = " + FormatNumber(c.value) +
                          " has a non-finite value");
}

}  // namespace

TsvTable OrbitDiagramTable(const System& s, const OrbitDiagram& d, const DiagramLabels& l) {
  const int nt = s.tangent_dimension(), k = s.contacts();
  std::vector<std::string> cols = {"direction", l.param, "period"};
  for (int i = 0; i < nt; ++i) cols.push_back(StateColumn(s, i));
  for (int i = 0; i < k; ++i) cols.push_back(k == 1 ? "stuck" : "stuck" + std::to_string(i + 1));
  cols.insert(cols.end(), {"sticks", "exits", "exit_phase", "lyapunov", "lyapunov_err"});
  TsvTable t(cols);
  AddFailures(d, l.param, t);
  std::vector<TsvTable::Cell> row;
  for (const DiagramColumn& c : d.columns) {
    if (!Done(c)) continue;
    CheckFinite(c.run.lyapunov + c.run.lyapunov_err, c, l.param);
    int n = 0;
    for (const SectionPoint& q : c.run.points) {
      CheckFinite(q.z.sum(), c, l.param);
      row = {Name(c.direction), c.value, ++n};
      for (int i = 0; i < nt; ++i) row.emplace_back(q.z[i]);
      for (int i = 0; i < k; ++i) row.emplace_back(q.mode[i] == Mode::kStick ? 1 : 0);
      row.insert(row.end(), {q.sticks, q.exits, static_cast<double>(q.first_exit_phase),
                             c.run.lyapunov, c.run.lyapunov_err});
      t.AddRow(row);
    }
  }
  return t;
}

TsvTable ExponentTable(const System& s, const OrbitDiagram& d, const DiagramLabels& l) {
  const std::string x = StateColumn(s, 0);
  TsvTable t({"direction", l.param, "lyapunov", "lyapunov_err", "sticks_per_period", "collapses",
              x + "_min", x + "_max"});
  AddFailures(d, l.param, t);
  for (const DiagramColumn& c : d.columns) {
    if (!Done(c) || c.run.points.empty()) continue;
    double sticks = 0, lo = c.run.points[0].z[0], hi = lo;
    for (const SectionPoint& q : c.run.points) {
      sticks += q.sticks;
      lo = std::min(lo, q.z[0]), hi = std::max(hi, q.z[0]);
    }
    t.AddRow({Name(c.direction), c.value, c.run.lyapunov, c.run.lyapunov_err,
              sticks / c.run.points.size(), c.run.collapses, lo, hi});
  }
  return t;
}

std::string OrbitDiagramScript(const System& s, FigureFormat format, const DiagramLabels& l,
                               const std::string& title, bool up, bool down) {
  const std::string& ax = l.param;
  const std::string& label = l.param_label;
  const std::string x = StateColumn(s, 0);
  std::ostringstream os;
  os << "# The orbit diagram of ss_orbit_diagram: section points (" << l.section << ") and\n"
     << "# the largest Lyapunov exponent against " << ax << ".\n"
     << FigurePreamble(format, 1100, 900) << "set output '" << FigureFile("orbit_diagram", format)
     << "'\nset multiplot\nset autoscale xfix\nset lmargin 12\nset rmargin 4\nunset key\n"
     << "sel(d, col) = strcol('direction') eq d ? column(col) : 1/0\n"
     << "set size 1, 0.62\nset origin 0, 0.38\nset tmargin 3\nset bmargin 0.5\n"
     << "set title " << GnuplotQuoted(title) << "\nset format x ''\n"
     << "set ylabel "
     << GnuplotQuoted((s.clocks() ? "displacement " : "") + s.StateName(0) + " at " + l.section)
     << "\n"
     << "plot ";
  const char* dirs[] = {"up", "down"};
  const bool on[] = {up, down};
  bool first = true;
  for (int i = 1; i >= 0; --i) {  // up drawn over down: where they differ, hysteresis
    if (!on[i]) continue;
    os << (first ? "" : ", \\\n     ") << "'orbit_diagram.tsv' using (sel('" << dirs[i] << "', '"
       << ax << "')):'" << x << "' with points pt 7 ps " << (i == 0 ? "0.12" : "0.25")
       << " lc rgb '" << SeriesColor(i) << "' title 'sweep " << dirs[i] << "'";
    first = false;
  }
  os << "\nunset title\nset size 1, 0.38\nset origin 0, 0\nset tmargin 0.5\nset bmargin 7\n"
     << "set format x '% g'\nset xlabel " << GnuplotQuoted(label) << "\n"
     << "set ylabel 'largest Lyapunov exponent λ_1'\n"
     << "set key outside below center horizontal\nplot 0 with lines ls 7 notitle";
  for (int i = 1; i >= 0; --i) {
    if (!on[i]) continue;
    os << ", \\\n     'lyapunov.tsv' using (sel('" << dirs[i] << "', '" << ax
       << "')):'lyapunov' with points pt 7 ps 0.35 lc rgb '" << SeriesColor(i) << "' title 'sweep "
       << dirs[i] << "'";
  }
  // Chaos marked as the basins classify it (docs/theory.md): lambda_1 > max(3 err, floor).
  const std::string floor = FormatNumber(Tolerances().ChaoticExponentFloor());
  os << ", \\\n     'lyapunov.tsv' using '" << ax
     << "':(column('lyapunov') > 3 * column('lyapunov_err') && column('lyapunov') > " << floor
     << " ? column('lyapunov') : 1/0) with points pt 6 ps 1.2 lw 1.5 lc rgb 'black' title "
        "'chaotic: λ_1 > max(3σ, "
     << floor << ")'";
  os << "\nunset multiplot\n";
  return os.str();
}

}  // namespace stickslip
