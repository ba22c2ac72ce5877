// ss_simulate --force A --omega W --orbits (simulate_forced.hpp): every
// periodic orbit of period multiple m <= --max_m at one parameter point, by
// FindOrbits (orbits/orbit_search.hpp), in orbits.tsv: one row per
// stroboscopic point, the orbit's data repeated; orbits.gp draws the points.
#include <iostream>
#include <string>
#include <vector>

#include "cli/about.hpp"
#include "cli/app.hpp"
#include "cli/simulate_forced.hpp"
#include "stickslip/io/figure_style.hpp"
#include "stickslip/orbits/forced_orbit.hpp"
#include "stickslip/orbits/orbit_search.hpp"

namespace stickslip::cli {

namespace {

constexpr int kMaxScanMultiple = 12;  // the scan's work grows like max_m^2

// The script plots only the series that have points (gnuplot fails on a
// series that is NaN throughout): stable and unstable stroboscopic points,
// or an empty frame that says none was found.
std::string OrbitsScript(const std::string& title, FigureFormat f, int stable, int unstable) {
  std::string s = FigurePreamble(f, 950, 750);
  s += "set output " + GnuplotQuoted(FigureFile("orbits", f)) + "\n";
  s += "set title \"periodic orbits, stroboscopic points (cos Ωt = 1)\\n\" . " +
       GnuplotQuoted(FigureTitle(title, {})) + "\n";
  s += "set xlabel 'displacement x (dimensionless)'\nset ylabel 'velocity dx/dt (dimensionless)'\n";
  s += "set offsets graph 0.05, graph 0.05, graph 0.05, graph 0.05\n";
  if (stable + unstable == 0)
    return s +
           "set xrange [-1:1]\nset yrange [-1:1]\n"
           "set label 'no periodic orbit found' at graph 0.5, graph 0.5 center\n"
           "plot NaN notitle\n";
  std::vector<std::string> series;
  if (stable > 0)
    series.push_back(
        "'orbits.tsv' using (column('stable') == 1 ? $7 : NaN):8:(sprintf('m=%d', "
        "column('m'))) with labels point pt 7 ps 1.2 lc rgb '#1f77b4' offset 1,1 title 'stable'");
  if (unstable > 0)
    series.push_back(
        "'orbits.tsv' using (column('stable') == 0 ? $7 : NaN):8 with points pt 6 ps 1.2 "
        "lc rgb '#d62728' title 'unstable'");
  s += "plot " + series[0];
  if (series.size() > 1) s += ", \\\n     " + series[1];
  return s + "\n";
}

}  // namespace

int ForcedOrbitsApp(const Arguments& args, const std::string& prog, const std::string& command) {
  const ForcedInputs in = ForcedInputsFromArguments(args);
  const ForcedBelt model(in.p);
  OrbitSearchOptions so;
  so.orbit = ShootingOptions(in.flow);
  so.half_width = model.SearchBox();
  so.max_m = static_cast<int>(args.Integer("max_m", so.max_m));
  if (so.max_m < 1 || so.max_m > kMaxScanMultiple)
    throw UsageError("invalid value '" + args.Text("max_m") + "' for " + args.Source("max_m") +
                     ": must be an integer in [1, " + std::to_string(kMaxScanMultiple) + "]");
  const FigureFormat format = FigureFormatOf(args);
  const std::string figure = FigureFile("orbits", format);
  AppRun app(prog, args, "plots/orbits", {"orbits.tsv", "orbits.gp", figure});
  app.run().Phase("scanning");
  so.cancelled = [&] {
    app.run().Heartbeat("");
    return app.run().Cancelled();
  };
  const FoundOrbits r = FindOrbits(model, so);
  app.run().Phase("writing");
  const std::string title = DescribeModel(in.p.base) + " force=" + FormatNumber(in.p.force) +
                            " omega=" + FormatNumber(in.p.omega);
  Metadata meta = RunMetadata(prog, command, in.p.base, in.shown);
  std::string partial;
  if (r.status == OrbitScanStatus::kCancelled)
    partial = "scan cancelled (" + app.run().Reason() + ")";
  else if (!r.ok())
    partial = "scan failed: " + r.message;
  meta.insert(meta.end(), {{"model", "forced oscillator, " + title},
                           {"force", FormatNumber(in.p.force)},
                           {"omega", FormatNumber(in.p.omega)},
                           {"max_m", std::to_string(so.max_m)},
                           {"shots", std::to_string(r.shots) + " Newton solves, " +
                                         std::to_string(r.converged) + " converged"},
                           {"status", r.ok() ? "complete" : "partial (" + partial + ")"}});
  TsvTable t({"orbit", "m", "sticks", "crossings", "kind", "point", "x", "xdot", "x_min", "x_max",
              "xdot_min", "xdot_max", "mult1_re", "mult1_im", "mult2_re", "mult2_im", "mult_max",
              "stable", "found_by"});
  t.PrependMeta(meta);
  int index = 0;
  for (const FoundOrbit& so_ : r.orbits) {
    const PeriodicOrbit& o = so_.orbit;
    const Extrema e = OrbitExtrema(o);
    ++index;
    for (size_t k = 0; k < so_.points.size(); ++k)
      t.AddRow({index, so_.m, o.sticks, o.crossings, o.sticks > 0 ? "stick-slip" : "pure-slip",
                static_cast<int>(k + 1), so_.points[k][0], so_.points[k][1], e.x_min, e.x_max,
                e.xdot_min, e.xdot_max, o.multipliers[0].real(), o.multipliers[0].imag(),
                o.multipliers[1].real(), o.multipliers[1].imag(), std::abs(o.multipliers[0]),
                o.stable ? 1 : 0, so_.from_exit_map ? "exit-map" : "strobe"});
  }
  app.out().Write("orbits.tsv", t.str());
  int stable = 0, unstable = 0;  // stroboscopic points of each
  for (const FoundOrbit& f : r.orbits)
    (f.orbit.stable ? stable : unstable) += static_cast<int>(f.points.size());
  app.out().Write("orbits.gp", OrbitsScript(title, format, stable, unstable));
  if (!app.Finish("orbits.gp", {figure}, {figure})) return kExitFailed;
  std::cout << prog << ": forced oscillator, " << title << "; " << r.orbits.size()
            << " periodic orbits with m <= " << so.max_m << "\n";
  for (const FoundOrbit& so_ : r.orbits)
    std::cout << "  m = " << so_.m << ", " << so_.orbit.sticks << " sticks, x_max "
              << FormatNumber(OrbitExtrema(so_.orbit).x_max) << ", |multiplier| "
              << FormatNumber(std::abs(so_.orbit.multipliers[0])) << ", "
              << (so_.orbit.stable ? "stable" : "unstable") << "\n";
  if (r.shots > 0 && r.converged == 0)  // none found is not none there (a slow settling)
    std::cerr << prog << ": note: none of the " << r.shots
              << " Newton solves converged; an orbit may still exist (a simulation at these "
                 "parameters shows where the motion settles)\n";
  std::cout << "wrote " << app.out().dir() << "/orbits.tsv, orbits.gp"
            << (app.gnuplot().ok() ? " and " + figure : "") << "\n";
  return app.ExitCode(partial);
}

}  // namespace stickslip::cli
