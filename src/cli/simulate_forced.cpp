// ss_simulate's range options and forced run (simulate_forced.hpp).
#include "cli/simulate_forced.hpp"

#include <algorithm>
#include <cmath>
#include <iostream>

#include "cli/about.hpp"
#include "cli/app.hpp"
#include "numerics/numbers.hpp"
#include "numerics/tolerances.hpp"
#include "stickslip/flow/simulate.hpp"
#include "stickslip/forced/flow.hpp"
#include "stickslip/io/figure_style.hpp"

namespace stickslip::cli {

namespace {

void Positive(const Arguments& args, const char* name) {
  if (!(args.Number(name, 1) > 0))
    throw UsageError("invalid value '" + args.Text(name) + "' for " + args.Source(name) +
                     ": must be > 0");
}

std::string Quoted(const std::string& s) { return GnuplotQuoted(s); }

// The forcing periods the time series shows: the last few, not the whole run
// (thousands of oscillations drawn in 700 pixels are a block of colour).
constexpr double kShownPeriods = 8;

// Two figures in the common style: trajectory (phase portrait with the stick
// line x' = v, and x, x' against t over the last kShownPeriods forcing
// periods) and section (strobe: x' against x; exit: the exit-phase map, phase
// of exit n+1 against exit n). The first half of the run (t < t_end / 2) is
// drawn as the transient, in gray, apart from the rest.
std::string ForcedScript(SimulationSection sec, const std::string& title, FigureFormat f,
                         double t_end, double period) {
  const std::string ts = FormatNumber(t_end / 2);
  const std::string late = "'after the transient (t ≥ " + Num(t_end / 2, 4) + ")'";
  const std::string early = "'transient (t < " + Num(t_end / 2, 4) + ")'";
  const char* gray = "lc rgb '#b0b0b0'";
  std::string s = FigurePreamble(f, 1400, 650);
  s += "set output " + Quoted(FigureFile("trajectory", f)) + "\n";
  s += "set bmargin 9\n";  // the portrait's key takes three rows under its axis label
  s += "set multiplot layout 1,2 title " + Quoted(FigureTitle(title, {})) + "\n";
  s += "set xlabel 'displacement x'\nset ylabel 'velocity dx/dt'\nset title 'phase portrait'\n";
  s += "plot 'trajectory.tsv' using 2:($1 < " + ts + " ? $3 : NaN) with lines lw 1 " + gray +
       " title " + early + ", \\\n";
  s += "     'trajectory.tsv' using 2:($1 >= " + ts + " ? $3 : NaN) with lines ls 1 lw 1.5 title " +
       late + ", \\\n";
  s += "     'trajectory.tsv' using 2:(strcol(4) eq 'stick' ? $3 : NaN) with lines ls 9 "
       "title 'sticking (dx/dt = v)'\n";
  const double from = std::max(0.0, t_end - kShownPeriods * period);
  s += "set xlabel 'time t'\nset ylabel 'x, dx/dt'\nset title " +
       Quoted("time series: the last " + Num(std::min(kShownPeriods, t_end / period), 3) +
              " forcing periods") +
       "\nset xrange [" + FormatNumber(from) + ":" + FormatNumber(t_end) + "]\n";
  s += "plot 'trajectory.tsv' using 1:2 with lines ls 1 lw 1.5 title 'displacement x', \\\n";
  s += "     'trajectory.tsv' using 1:3 with lines ls 3 lw 1.5 title 'velocity dx/dt'\n";
  s += "unset multiplot\nset autoscale x\nset bmargin 7\n";
  s += FigureTerminal(f, 950, 750);
  s += "set output " + Quoted(FigureFile("section", f)) + "\n";
  if (sec == SimulationSection::kStrobe) {
    s += "set title \"stroboscopic section (cos Ωt = 1)\\n\" . " + Quoted(FigureTitle(title, {})) +
         "\n";
    s += "set xlabel 'displacement x (dimensionless)'\n";
    s += "set ylabel 'velocity dx/dt (dimensionless)'\n";
    s += "set offsets graph 0.04, graph 0.04, graph 0.04, graph 0.04\n";  // no point on the frame
    s += "plot 'section.tsv' using 4:($2 < " + ts + " ? $5 : NaN) with points pt 6 ps 0.6 " + gray +
         " title " + early + ", \\\n";
    s += "     'section.tsv' using 4:($2 >= " + ts +
         " ? $5 : NaN) with points pt 7 ps 0.8 lc rgb '#0072b2' title " + late + "\n";
  } else {
    s += "set title \"exit-phase map (stick exits)\\n\" . " + Quoted(FigureTitle(title, {})) + "\n";
    s += "set xlabel 'forcing phase of stick exit n [rad]'\n";
    s += "set ylabel 'forcing phase of stick exit n+1 [rad]'\n";
    s += "set xrange [0:2*pi]\nset yrange [0:2*pi]\nset size square\nprev = NaN\n";
    s += "plot x with lines lc rgb '#aaaaaa' dt 2 notitle, \\\n";
    s += "     'section.tsv' using (q = prev, prev = $3, q):($2 < " + ts +
         " ? $3 : NaN) with "
         "points pt 6 ps 0.6 " +
         gray + " title " + early + ", \\\n";
    s += "     prev = NaN, 'section.tsv' using (q = prev, prev = $3, q):($2 >= " + ts +
         " ? $3 : NaN) with points pt 7 ps 0.8 lc rgb '#0072b2' title " + late + "\n";
  }
  return s;
}

// Omega t mod 2 pi in [0, 2 pi); within rounding of 2 pi it is 0.
double Phase(const ForcedModel& m, double t) {
  const double wt = m.omega() * t;
  double p = std::fmod(wt, 2 * M_PI);
  if (p < 0) p += 2 * M_PI;
  return 2 * M_PI - p <= Tolerances::kPhaseRounding * (1 + std::abs(wt)) * Tolerances::kPhaseUlps
             ? 0
             : p;
}

}  // namespace

SimulateRange SimulateRangeFromArguments(const Arguments& args, double default_xdot0) {
  SimulateRange r;
  r.x0 = args.Number("x0", r.x0);
  r.xdot0 = args.Number("xdot0", default_xdot0);
  r.t_end = args.Number("t_end", r.t_end);
  r.dt = args.Number("dt", r.dt);
  Positive(args, "t_end");
  Positive(args, "dt");
  r.max_rows = args.Integer("max_rows", SimulateRange::kMaxRows);
  if (r.max_rows < 1 || r.max_rows > SimulateRange::kMaxRows)
    throw UsageError("invalid value '" + args.Text("max_rows") + "' for " +
                     args.Source("max_rows") + ": must be in [1, 1e7]");
  if (r.t_end / r.dt > r.max_rows)
    throw UsageError("t_end / dt = " + FormatNumber(r.t_end / r.dt) + " rows is more than " +
                     args.Source("max_rows") + " = " + std::to_string(r.max_rows) +
                     "; use a larger --dt");
  return r;
}

void AddRangeMeta(TsvTable& table, const SimulateRange& r) {
  table.AddMeta("x0", FormatNumber(r.x0));
  table.AddMeta("xdot0", FormatNumber(r.xdot0));
  table.AddMeta("t_end", FormatNumber(r.t_end));
  table.AddMeta("dt", FormatNumber(r.dt));
}

ForcedInputs ForcedInputsFromArguments(const Arguments& args) {
  ForcedInputs in;
  ForcedParams& p = in.p;
  for (const char* phys : {"mass", "damping", "stiffness", "belt_speed"})
    if (args.Given(phys))
      throw UsageError(args.Source(phys) + ": the forced oscillator takes dimensionless inputs");
  p.base = UncheckedModelFromArguments(args);
  p.force = args.Number("force", 0);
  p.omega = args.Number("omega", 1);
  CheckForcedModel(args, p);
  FlowOptions& flow = in.shown;
  flow = FlowOptionsFromArguments(args);
  if (flow.integrator != Integrator::kTaylor)
    throw UsageError(args.Source(args.Given("method") ? "method" : "integrator") +
                     ": the forced oscillator is integrated by Taylor series only");
  // The forced flow's own defaults (rtol = atol = 1e-12, max_steps per row) unless given.
  if (!args.Given("rtol")) flow.rtol = in.flow.rtol;
  if (!args.Given("atol")) flow.atol = in.flow.atol;
  if (!args.Given("max_steps")) flow.max_steps = in.flow.max_steps;
  in.flow.rtol = flow.rtol, in.flow.atol = flow.atol, in.flow.max_steps = flow.max_steps;
  return in;
}

void AddSimulateForcedOptions(po::options_description& d) {
  d.add_options()("section", Value()->value_name("strobe|exit"),
                  "forced: the Poincare section in section.tsv: strobe (every forcing period, "
                  "cos(Omega t) = 1; default) or exit (every stick exit)")(
      "orbits", po::bool_switch(),
      "forced: instead of a trajectory, every periodic orbit of period multiple m <= max_m at "
      "these parameters (stable or not; FindOrbits), in orbits.tsv, one row per "
      "stroboscopic point")("max_m", Value()->value_name("M"),
                            "with --orbits: the largest period multiple, 1..12 (default 4)");
}

// The forced run's settings, all checked before anything runs or is written.
struct SimulateSetup {
  ForcedParams p;
  SimulationOptions o;
  FlowOptions flow;  // as the metadata shows it
  SimulateRange range;
};

SimulateSetup ConfigureForced(const Arguments& args) {
  SimulateSetup st;
  const ForcedInputs in = ForcedInputsFromArguments(args);
  st.p = in.p, st.flow = in.shown, st.o.flow = in.flow;
  const std::string sec = args.Text("section", "strobe");
  if (sec != "strobe" && sec != "exit")
    throw UsageError("invalid value '" + sec + "' for " + args.Source("section") +
                     ": must be strobe or exit");
  st.o.section = sec == "strobe" ? SimulationSection::kStrobe : SimulationSection::kExit;
  st.range = SimulateRangeFromArguments(args, st.p.base.v);
  st.o.t_end = st.range.t_end, st.o.dt = st.range.dt, st.o.max_rows = st.range.max_rows;
  st.o.period = ForcedModel(st.p).period();
  st.o.extrema = {0, 1};
  return st;
}

int SimulateForcedApp(const Arguments& args, const std::string& prog, const std::string& command) {
  SimulateSetup st = ConfigureForced(args);
  const ForcedParams& p = st.p;
  SimulationOptions& o = st.o;
  const SimulateRange& range = st.range;
  const ForcedModel model(p);
  if (o.section == SimulationSection::kStrobe && o.t_end / model.period() > range.max_rows)
    throw UsageError("t_end / (2 pi / omega) = " + FormatNumber(o.t_end / model.period()) +
                     " section points is more than " + args.Source("max_rows") + " = " +
                     std::to_string(range.max_rows));
  const FigureFormat format = FigureFormatOf(args);
  const std::string fig_t = FigureFile("trajectory", format), fig_s = FigureFile("section", format);
  AppRun app(prog, args, "plots/simulate",
             {"trajectory.tsv", "section.tsv", "trajectory.gp", fig_t, fig_s});
  RunControl& run = app.run();
  run.Phase("integrating");
  o.cancelled = [&] {
    run.Heartbeat("");
    return run.Cancelled();
  };
  TsvTable traj({"t", "x", "xdot", "mode", "phase"});
  TsvTable section({"n", "t", "phase", "x", "xdot", "mode"});
  double t_last = 0;
  SimulationSink sink;
  sink.row = [&](double t, const double* z, const ModeSet& m) {
    traj.AddRow({t, z[0], z[1], Name(m[0]), Phase(model, t)});
    t_last = t;
  };
  sink.section = [&](long n, double t, const double* z, const ModeSet& m) {
    section.AddRow({static_cast<double>(n), t, Phase(model, t), z[0], z[1], Name(m[0])});
  };
  const Simulation r = Simulate(model, ForcedStart(model, 0, range.x0, range.xdot0), o, sink);
  if (r.status == SimulationStatus::kRowLimit)  // bad input found late: nothing written
    throw UsageError(args.Source("t_end") + " " + args.Text("t_end", "100") + " with " +
                     args.Source("dt") + " " + args.Text("dt", "0.01") + ": " + r.message +
                     "; use a shorter --t_end or a larger --dt");
  run.Phase("writing");
  const std::string title =
      DescribeModel(p.base) + " force=" + FormatNumber(p.force) + " omega=" + FormatNumber(p.omega);
  Metadata meta = RunMetadata(prog, command, p.base, st.flow);
  meta.insert(meta.end(), {{"model", "forced oscillator, " + title},
                           {"force", FormatNumber(p.force)},
                           {"omega", FormatNumber(p.omega)},
                           {"section", Name(o.section)}});
  const std::string why =
      r.ok()
          ? ""
          : r.message + (r.status == SimulationStatus::kCancelled ? " (" + run.Reason() + ")" : "");
  meta.emplace_back("status", r.ok() ? "complete" : "partial (" + why + ")");
  for (TsvTable* t : {&traj, &section}) {
    t->PrependMeta(meta);
    AddRangeMeta(*t, range);
  }
  app.out().Write("trajectory.tsv", traj.str());
  app.out().Write("section.tsv", section.str());
  if (!r.ok()) {
    app.out().Commit({"trajectory.gp", fig_t, fig_s});
    return app.ExitCode(why + "; the trajectory so far is written to " + app.out().dir() +
                        ", marked partial");
  }
  app.out().Write("trajectory.gp", ForcedScript(o.section, title, format, t_last, model.period()));
  if (!app.Finish("trajectory.gp", {fig_t, fig_s}, {fig_t, fig_s})) return kExitFailed;
  std::cout << prog << ": forced oscillator, " << title << "\n"
            << r.rows << " rows to t = " << FormatNumber(t_last) << ", " << r.section_points
            << " section points (" << Name(o.section) << "), " << r.sticks << " sticks, "
            << r.crossings << " crossings; x in [" << FormatNumber(r.lo[0]) << ", "
            << FormatNumber(r.hi[0]) << "]\n"
            << "wrote " << app.out().dir() << "/trajectory.tsv, section.tsv, trajectory.gp"
            << (app.gnuplot().ok() ? ", " + fig_t + " and " + fig_s : "") << "\n";
  return app.ExitCode("");
}

}  // namespace stickslip::cli
