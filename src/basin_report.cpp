#include "stickslip/basin_report.hpp"

#include <sstream>

namespace stickslip {

namespace {
std::string Num(double x) { return FormatNumber(x); }
}  // namespace

TsvTable BasinTable(const BasinResult& r, const std::string& model_description,
                    const std::vector<Disturbance>& disturbances) {
  TsvTable t({"x", "xdot", "fate", "orbit", "t_settle"});
  t.AddComment("model: " + model_description);
  if (r.partial())
    t.AddComment(std::string("status: partial (") + BasinStatusName(r.status) + "): " + r.message);
  else
    t.AddComment("status: complete");
  std::ostringstream grid;
  grid << r.nx << " x " << r.ny << " starts, x in [" << Num(r.x_lo) << ", " << Num(r.x_hi)
       << "], x' in [" << Num(r.xdot_lo) << ", " << Num(r.xdot_hi) << "]";
  t.AddComment("grid: " + grid.str());
  const PeriodicOrbits& po = r.orbits;
  t.AddComment("steady sliding: x = " + Num(po.steady.x) + ", " +
               (po.steady.stable() ? "stable" : "unstable"));
  if (po.has_stick_slip)
    t.AddComment("orbit: stick-slip, stable, period " + Num(po.stick_slip.period) + ", t_stick " +
                 Num(po.stick_slip.t_stick) + ", x in [" + Num(po.stick_slip.x_min) + ", " +
                 Num(po.stick_slip.x_max) + "]");
  for (size_t i = 0; i < po.pure_slip.size(); ++i) {
    const Orbit& o = po.pure_slip[i];
    t.AddComment("orbit: pure-slip " + std::to_string(i) + ", " +
                 (o.stable ? "stable" : "unstable") + ", period " + Num(o.period) +
                 ", multiplier " + Num(o.multiplier) + ", section amplitude " +
                 Num(o.start[0] - po.steady.x));
    if (i < disturbances.size() && !o.stable)
      t.AddComment("smallest disturbance: pure-slip " + std::to_string(i) + ": x " +
                   Num(disturbances[i].x) + ", x' " + Num(disturbances[i].xdot) + ", energy " +
                   Num(disturbances[i].energy));
  }
  for (int f = 0; f < 4; ++f)
    t.AddComment(std::string("count: ") + FateName(static_cast<Fate>(f)) + " " +
                 std::to_string(r.count[f]));
  for (const BasinStart& s : r.starts)
    t.AddRow({s.x, s.xdot, FateName(s.fate), s.orbit, s.t_settle});
  return t;
}

TsvTable OrbitTable(const std::vector<OrbitCurveRows>& curves, const BasinStability* stability) {
  std::vector<std::string> cols = {"orbit", "kind", "stable", "x", "xdot"};
  if (stability) cols.push_back("basin_stability");
  TsvTable t(cols);
  if (stability)
    for (const std::string& line : BasinStabilityLines(*stability)) t.AddComment(line);
  int pure_slip = 0;
  for (size_t i = 0; i < curves.size(); ++i) {
    // The share of the attractor this curve is (stick-slip, or pure-slip k).
    double share = 0;
    const bool ps = curves[i].kind != "stick-slip";
    if (stability)
      for (const BasinShare& b : stability->shares)
        if (ps ? b.fate == Fate::kPureSlip && b.orbit == pure_slip : b.fate == Fate::kStickSlip)
          share = b.fraction;
    pure_slip += ps;
    for (const Vec2& z : curves[i].points) {
      std::vector<TsvTable::Cell> row = {static_cast<int>(i), curves[i].kind,
                                         curves[i].stable ? 1 : 0, z[0], z[1]};
      if (stability) row.emplace_back(share);
      t.AddRow(row);
    }
  }
  return t;
}

std::string BasinScript(const BasinResult& r, const Model& model,
                        const std::vector<OrbitCurveRows>& curves, const std::string& title) {
  const double dx = r.nx > 1 ? (r.x_hi - r.x_lo) / (r.nx - 1) : 1;
  const double dy = r.ny > 1 ? (r.xdot_hi - r.xdot_lo) / (r.ny - 1) : 1;
  const Vec2 exit = model.ExitPoint();
  std::ostringstream os;
  os << "# Basins written by ss_basin; run `gnuplot basins.gp` in this directory.\n"
     << "if (!exists('suffix')) suffix = ''\n"
     << "set terminal pngcairo size 1000,800 enhanced font ',12'\n"
     << "set output 'basins.png'.suffix\n"
     << "set datafile separator '\\t'\n"
     << "set datafile columnheaders\n"
     << "set title '" << title << "' noenhanced\n"
     << "set xlabel 'x'\nset ylabel \"x'\"\n"
     << "set xrange [" << Num(r.x_lo - dx / 2) << ":" << Num(r.x_hi + dx / 2) << "]\n"
     << "set yrange [" << Num(r.xdot_lo - dy / 2) << ":" << Num(r.xdot_hi + dy / 2) << "]\n"
     << "set key outside right top\n"
     << "set palette defined (-0.5 '#9ecae1', 0.5 '#9ecae1', 0.5 '#fdae6b', 1.5 '#fdae6b', "
        "1.5 '#a1d99b', 2.5 '#a1d99b', 2.5 '#d9d9d9', 3.5 '#d9d9d9')\n"
     << "set cbrange [-0.5:3.5]\nunset colorbox\n"
     << "fate(s) = s eq 'steady-sliding' ? 0 : s eq 'stick-slip' ? 1 : "
        "s eq 'pure-slip' ? 2 : 3\n"
     << "set arrow from " << Num(exit[0] - 2 * model.params().mu_s) << "," << Num(model.v())
     << " to " << Num(exit[0]) << "," << Num(model.v()) << " nohead lw 4 lc rgb 'black' front\n"
     << "plot 'basins.tsv' using 1:2:(fate(strcol(3))) with image notitle, \\\n"
     << "     NaN with boxes fs solid lc rgb '#9ecae1' title 'steady sliding', \\\n"
     << "     NaN with boxes fs solid lc rgb '#fdae6b' title 'stick-slip', \\\n"
     << "     NaN with boxes fs solid lc rgb '#a1d99b' title 'pure slip', \\\n"
     << "     NaN with boxes fs solid lc rgb '#d9d9d9' title 'undecided', \\\n"
     << "     NaN with lines lw 4 lc rgb 'black' title 'stick band'";
  for (size_t k = 0; k < curves.size(); ++k)
    os << ", \\\n     'orbits.tsv' using 4:($1 == " << k << " ? $5 : NaN) with lines lw 3 dt "
       << (curves[k].stable ? 1 : 2) << " lc rgb '" << (curves[k].stable ? "black" : "red")
       << "' title '" << curves[k].kind << (curves[k].stable ? " (stable)" : " (unstable)") << "'";
  os << ", \\\n     '+' using (" << Num(r.orbits.steady.x) << "):(0) every ::0::0 with points "
     << "pt 7 ps 1.5 lc rgb 'black' title 'steady sliding (xbar, 0)'\n"
     << "unset output\n";
  return os.str();
}

}  // namespace stickslip
