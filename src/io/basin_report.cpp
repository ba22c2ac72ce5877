#include "stickslip/io/basin_report.hpp"

#include <sstream>

#include "stickslip/io/figure_style.hpp"

namespace stickslip {

namespace {}  // namespace

TsvTable BasinTable(const BasinResult& r, const std::string& model_description,
                    const std::vector<Disturbance>& disturbances) {
  TsvTable t({"x", "xdot", "fate", "orbit", "t_settle"});
  t.AddComment("model: " + model_description);
  if (r.partial())
    t.AddComment(std::string("status: partial (") + Name(r.status) + "): " + r.message);
  else
    t.AddComment("status: complete");
  std::ostringstream grid;
  grid << r.nx << " x " << r.ny << " starts, x in [" << FormatNumber(r.x_lo) << ", "
       << FormatNumber(r.x_hi) << "], x' in [" << FormatNumber(r.xdot_lo) << ", "
       << FormatNumber(r.xdot_hi) << "]";
  t.AddComment("grid: " + grid.str());
  const PeriodicOrbits& po = r.orbits;
  t.AddComment("steady sliding: x = " + FormatNumber(po.steady.x) + ", " +
               (po.steady.stable() ? "stable" : "unstable"));
  if (po.has_stick_slip)
    t.AddComment("orbit: stick-slip, stable, period " + FormatNumber(po.stick_slip.period) +
                 ", t_stick " + FormatNumber(po.stick_slip.t_stick) + ", x in [" +
                 FormatNumber(po.stick_slip.extrema.x_min) + ", " +
                 FormatNumber(po.stick_slip.extrema.x_max) + "]");
  for (size_t i = 0; i < po.pure_slip.size(); ++i) {
    const Orbit& o = po.pure_slip[i];
    t.AddComment("orbit: pure-slip " + std::to_string(i) + ", " +
                 (o.stable ? "stable" : "unstable") + ", period " + FormatNumber(o.period) +
                 ", multiplier " + FormatNumber(o.multiplier) + ", section amplitude " +
                 FormatNumber(o.start[0] - po.steady.x));
    if (i < disturbances.size() && !o.stable)
      t.AddComment("smallest disturbance: pure-slip " + std::to_string(i) + ": x " +
                   FormatNumber(disturbances[i].x) + ", x' " + FormatNumber(disturbances[i].xdot) +
                   ", energy " + FormatNumber(disturbances[i].energy));
  }
  for (int f = 0; f < 4; ++f)
    t.AddComment(std::string("count: ") + Name(static_cast<Fate>(f)) + " " +
                 std::to_string(r.count[f]));
  for (const BasinStart& s : r.starts) t.AddRow({s.x, s.xdot, Name(s.fate), s.orbit, s.t_settle});
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
                        const std::vector<OrbitCurveRows>& curves, const std::string& title,
                        FigureFormat format, const FigureUnits& units) {
  // In the figure's units: x times L, x' times L / t0 (1 and 1 dimensionless).
  const double ul = units.length, uv = units.length / units.time;
  const double dx = r.nx > 1 ? (r.x_hi - r.x_lo) / (r.nx - 1) : 1;
  const double dy = r.ny > 1 ? (r.xdot_hi - r.xdot_lo) / (r.ny - 1) : 1;
  const Vec2 exit = model.ExitPoint();
  auto fill = [](const char* c) { return std::string("'") + c + "'"; };
  std::ostringstream os;
  os << "# Basins written by ss_basin; run `gnuplot basins.gp` in this directory.\n"
     << "if (!exists('suffix')) suffix = ''\n"
     << FigurePreamble(format, 1000, 900) << "set output '" << FigureFile("basins", format)
     << "'.suffix\n"
     << "set title " << GnuplotQuoted(FigureTitle(title, {})) << "\n"
     << FigureUnitVariables(units) << "set xlabel "
     << GnuplotQuoted("initial displacement x" + units.LengthUnit()) << "\n"
     << "set ylabel " << GnuplotQuoted("initial velocity dx/dt" + units.SpeedUnit()) << "\n"
     << "set xrange [" << FormatNumber(ul * (r.x_lo - dx / 2)) << ":"
     << FormatNumber(ul * (r.x_hi + dx / 2)) << "]\n"
     << "set yrange [" << FormatNumber(uv * (r.xdot_lo - dy / 2)) << ":"
     << FormatNumber(uv * (r.xdot_hi + dy / 2)) << "]\n"
     << "unset grid\n"
     << "set palette defined (-0.5 " << fill(kFillEquilibrium) << ", 0.5 " << fill(kFillEquilibrium)
     << ", 0.5 " << fill(kFillStickSlip) << ", 1.5 " << fill(kFillStickSlip) << ", 1.5 "
     << fill(kFillPureSlip) << ", 2.5 " << fill(kFillPureSlip) << ", 2.5 " << fill(kFillUndecided)
     << ", 3.5 " << fill(kFillUndecided) << ")\n"
     << "set cbrange [-0.5:3.5]\nunset colorbox\n"
     << "fate(s) = s eq 'steady-sliding' ? 0 : s eq 'stick-slip' ? 1 : "
        "s eq 'pure-slip' ? 2 : 3\n"
     << "set arrow from " << FormatNumber(ul * (exit[0] - 2 * model.params().mu_s)) << ","
     << FormatNumber(uv * model.v()) << " to " << FormatNumber(ul * exit[0]) << ","
     << FormatNumber(uv * model.v()) << " nohead lw 4 lc rgb 'black' front\n"
     << "set bmargin 9\n"
     << "plot 'basins.tsv' using ($1*ul):($2*uv):(fate(strcol(3))) with image notitle";
  // Key entries for the fates that occur, in the order of fate().
  const char* fills[] = {kFillEquilibrium, kFillStickSlip, kFillPureSlip, kFillUndecided};
  const char* names[] = {"basin: steady sliding", "basin: stick-slip", "basin: pure slip",
                         "undecided"};
  for (int f = 0; f < 4; ++f)
    if (r.count[f] > 0)
      os << ", \\\n     NaN with boxes fs solid border lc rgb '#808080' lc rgb " << fill(fills[f])
         << " title '" << names[f] << "'";
  os << ", \\\n     NaN with lines lw 4 lc rgb 'black' title 'stick band (dx/dt = v)'";
  for (size_t k = 0; k < curves.size(); ++k) {
    const bool stick = curves[k].kind == "stick-slip";
    const int ls = (stick ? kStyleStickSlip : kStylePureSlip) + (curves[k].stable ? 0 : 1);
    os << ", \\\n     'orbits.tsv' using ($4*ul):($1 == " << k << " ? $5*uv : NaN) with lines ls "
       << ls << " lw 3 title '" << (stick ? "stick-slip" : "pure slip")
       << (curves[k].stable ? " orbit, stable" : " orbit, unstable") << "'";
  }
  os << ", \\\n     '+' using (" << FormatNumber(ul * r.orbits.steady.x)
     << "):(0) every ::0::0 with points "
     << "pt 7 ps 1.5 lc rgb 'black' title 'steady sliding (x̄, 0)'\n"
     << "unset output\n";
  return os.str();
}

}  // namespace stickslip
