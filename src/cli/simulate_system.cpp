// ss_simulate for the forced oscillator and --system (simulate_system.hpp).
#include "cli/simulate_system.hpp"

#include <cmath>
#include <iostream>
#include <memory>

#include "cli/about.hpp"
#include "cli/app.hpp"
#include "cli/simulate_forced.hpp"
#include "cli/system_choice.hpp"
#include "stickslip/equilibria/steady_sliding.hpp"
#include "stickslip/flow/simulate.hpp"
#include "stickslip/io/figure_style.hpp"
#include "stickslip/io/system_branch_report.hpp"
#include "stickslip/io/trajectory_report.hpp"
#include "stickslip/orbits/shooting.hpp"

namespace stickslip::cli {

namespace {

constexpr double kDisturbance = 0.01;  // the default start: steady sliding, z_0 moved by this

// The run: its system, start and settings, all checked before anything runs.
struct Scene {
  std::unique_ptr<System> system;
  Eigen::VectorXd z0;
  SimulationOptions o;
  SimulateRange range;
  Metadata meta;      // the model and solver lines of both tables
  std::string title;  // as drawn
  std::string model;  // stdout's description
};

// --state: n comma-separated numbers; else steady sliding moved by kDisturbance.
Eigen::VectorXd StartState(const Arguments& args, const System& s) {
  if (!args.Given("state")) return NearSteadySliding(s, kDisturbance);
  const std::string text = args.Text("state");
  const std::vector<std::string> items = CommaItems(text);  // an empty one is refused below
  if (static_cast<int>(items.size()) != s.dimension())
    throw UsageError(args.Source("state") + " = '" + text + "': " + std::to_string(items.size()) +
                     " items, expected " + std::to_string(s.dimension()) +
                     " comma-separated numbers (" + StateColumn(s, 0) + ", ...)");
  Eigen::VectorXd z(s.dimension());
  for (int i = 0; i < s.dimension(); ++i)
    z[i] = ParseNumber(items[i], args.Source("state") + " component " + std::to_string(i + 1));
  // A clock's phase modulo 2 pi: unreduced, 1e20 + Omega t would not move.
  constexpr double kMaxPhase = 1e9;  // beyond it a double keeps under 7 digits of the phase
  for (int i = s.tangent_dimension(); i < s.dimension(); ++i) {
    if (!(std::abs(z[i]) <= kMaxPhase))
      throw UsageError(args.Source("state") + " component " + std::to_string(i + 1) + " (" +
                       s.StateName(i) + ") = " + items[i] +
                       ": a phase beyond 1e9 has too few digits left; give it in [0, 2 pi)");
    z[i] = ClockPhase(z[i]);
  }
  for (int c = 0; c < s.contacts(); ++c)
    if (const auto n = s.NormalForce(c); n && !(n->At(z.data()) > 0))
      throw UsageError(args.Source("state") + " = '" + text + "': contact " + std::to_string(c) +
                       " is open there (normal force " + FormatNumber(n->At(z.data())) + " <= 0)");
  return z;
}

// --section strobe|exit|none (default: strobe with a clock, else none).
SimulationSection SectionOf(const Arguments& args, const System& s) {
  const std::string text = args.Text("section", s.clocks() ? "strobe" : "none");
  SimulationSection sec = SimulationSection::kNone;
  if (!FromName(text, &sec))
    throw UsageError("invalid value '" + text + "' for " + args.Source("section") +
                     ": must be strobe, exit or none");
  if (sec == SimulationSection::kStrobe && !s.clocks())
    throw UsageError(args.Source("section") + " strobe needs a forcing (a clock); " +
                     SystemLabel(args) + " is autonomous: give exit or none");
  return sec;
}

Scene ForcedScene(const Arguments& args, const std::string& prog, const std::string& command) {
  const ForcedInputs in = ForcedInputsFromArguments(args);
  Scene sc;
  sc.system = std::make_unique<ForcedBelt>(in.p);
  sc.range = SimulateRangeFromArguments(args, in.p.base.v);
  sc.z0 = Eigen::Vector3d(sc.range.x0, sc.range.xdot0, 0);
  sc.o.flow = in.flow;
  const std::string params = DescribeModel(in.p.base) + " force=" + FormatNumber(in.p.force) +
                             " omega=" + FormatNumber(in.p.omega);
  sc.model = "forced oscillator, " + params;
  sc.title = FigureTitle(params, {});
  sc.meta = RunMetadata(prog, command, in.p.base, in.shown);
  sc.meta.insert(sc.meta.end(), {{"model", sc.model},
                                 {"force", FormatNumber(in.p.force)},
                                 {"omega", FormatNumber(in.p.omega)}});
  return sc;
}

Scene ChosenScene(const Arguments& args, const std::string& prog, const std::string& command) {
  const std::string name = SystemLabel(args);
  for (const char* o : {"x0", "xdot0"})
    if (args.Given(o))
      throw UsageError(args.Source(o) + " applies to the belt and the forced oscillator; give " +
                       "--state with " + name);
  for (const char* o : {"orbits", "max_m", "max_amplitude"})
    if (args.Given(o))
      throw UsageError(args.Source(o) + " applies to the forced oscillator only, not to " + name);
  Scene sc;
  sc.system = SystemFromArguments(args);
  sc.range = SimulateRangeFromArguments(args, 0);
  sc.o.flow = FlowOptionsFromArguments(args);
  sc.z0 = StartState(args, *sc.system);
  sc.model = DescribeSystem(*sc.system, SystemChoiceOf(args), -1);
  sc.title = SystemFigureTitle(sc.model);
  sc.meta = ToolMetadata(prog, command);
  sc.meta.insert(sc.meta.end(), {{"system", sc.model},
                                 {"rtol", FormatNumber(sc.o.flow.rtol)},
                                 {"atol", FormatNumber(sc.o.flow.atol)}});
  return sc;
}

Scene SceneOf(const Arguments& args, const std::string& prog, const std::string& command) {
  Scene sc =
      SystemRequested(args) ? ChosenScene(args, prog, command) : ForcedScene(args, prog, command);
  sc.o.section = SectionOf(args, *sc.system);
  // The clock's period 2 pi / omega, as the one shooting's section takes it (0: none).
  sc.o.period = sc.system->clocks() ? PoincareSection::Stroboscopic(*sc.system, sc.z0, 1).time : 0;
  if (sc.system->clocks() && !(sc.o.period > 0 && std::isfinite(sc.o.period)))
    throw UsageError("the clock " + sc.system->StateName(sc.system->tangent_dimension()) +
                     " turns at rate " + FormatNumber(2 * M_PI / sc.o.period) +
                     ": it must be > 0 (check the parameters set by --set or the model file)");
  sc.o.t_end = sc.range.t_end, sc.o.dt = sc.range.dt, sc.o.max_rows = sc.range.max_rows;
  sc.o.extrema = {0};
  if (sc.o.section == SimulationSection::kStrobe &&
      sc.range.t_end / sc.o.period > sc.range.max_rows)
    throw UsageError("t_end / (2 pi / omega) = " + FormatNumber(sc.range.t_end / sc.o.period) +
                     " section points is more than " + args.Source("max_rows") + " = " +
                     std::to_string(sc.range.max_rows));
  sc.meta.emplace_back("section", Name(sc.o.section));
  return sc;
}

// The figures the run draws.
std::vector<std::string> Figures(const Scene& sc, FigureFormat format) {
  std::vector<std::string> f = {FigureFile("trajectory", format)};
  if (sc.o.section != SimulationSection::kNone) f.push_back(FigureFile("section", format));
  return f;
}

void PrintSummary(const std::string& prog, const Scene& sc, const Simulation& r, long rows) {
  const System& s = *sc.system;
  std::cout << prog << ": " << sc.model << "\n"
            << rows << " rows to t = " << FormatNumber(r.end.t) << " (" << Name(r.status) << ")";
  if (sc.o.section != SimulationSection::kNone)
    std::cout << ", " << r.section_points << " section points (" << Name(sc.o.section) << ")";
  std::cout << ", " << r.sticks << " sticks, " << r.crossings << " crossings; " << s.StateName(0)
            << " in [" << FormatNumber(r.lo[0]) << ", " << FormatNumber(r.hi[0]) << "]\n";
}

}  // namespace

void AddSimulateSystemOptions(po::options_description& d) {
  d.add_options()("state", Value()->value_name("Z1,Z2,..."),
                  "--system or --model: the start, every state component in order (default: "
                  "steady sliding, or the origin where there is none, with the first "
                  "component moved by 0.01)");
}

int SimulateSystemApp(const Arguments& args, const std::string& prog, const std::string& command) {
  Scene sc = SceneOf(args, prog, command);
  const System& s = *sc.system;
  const FigureFormat format = FigureFormatOf(args);
  const bool sectioned = sc.o.section != SimulationSection::kNone;
  const std::vector<std::string> figures = Figures(sc, format);
  std::vector<std::string> files = {"trajectory.tsv", "trajectory.gp"};
  if (sectioned) files.push_back("section.tsv");
  files.insert(files.end(), figures.begin(), figures.end());
  AppRun app(prog, args, "plots/simulate", files);
  RunControl& run = app.run();
  TsvTable traj(TrajectoryColumns(s)), section(SectionColumns(s));
  sc.o.cancelled = [&] { return run.Cancelled(); };
  SimulationSink sink;
  sink.row = [&](double t, const double* z, const ModeSet& m) {
    traj.AddRow(TrajectoryRow(s, -1, t, z, m));
    run.Progress("t = " + FormatNumber(t), t / sc.range.t_end, t, "time units");
  };
  sink.section = [&](long n, double t, const double* z, const ModeSet& m) {
    section.AddRow(TrajectoryRow(s, n, t, z, m));
  };
  run.Phase("integrating");
  const Simulation r = Simulate(s, FlowPoint{0, sc.z0, ModeOf(s, sc.z0)}, sc.o, sink);
  if (r.status == SimulationStatus::kRowLimit)  // bad input found late: nothing written
    throw UsageError(args.Source("t_end") + " " + args.Text("t_end", "100") + " with " +
                     args.Source("dt") + " " + args.Text("dt", "0.01") + ": " + r.message +
                     "; use a shorter --t_end or a larger --dt");
  run.Phase("writing");
  const bool partial = !r.ok();
  const std::string why =
      r.message + (r.status == SimulationStatus::kCancelled ? " (" + run.Reason() + ")" : "");
  Metadata meta = sc.meta;
  meta.emplace_back("status", partial ? "partial (" + why + ")"
                              : r.status == SimulationStatus::kContactOpen
                                  ? "complete: contact " + std::to_string(r.opened) +
                                        " opens at t = " + FormatNumber(r.end.t) + ", the run ends"
                                  : std::string("complete"));
  std::string start;
  for (int i = 0; i < s.dimension(); ++i) start += (i ? "," : "") + FormatNumber(sc.z0[i]);
  for (TsvTable* t : {&traj, &section}) {
    t->PrependMeta(meta);
    if (SystemRequested(args)) {  // the start as --state takes it
      t->AddMeta("state", start);
      t->AddMeta("t_end", FormatNumber(sc.range.t_end));
      t->AddMeta("dt", FormatNumber(sc.range.dt));
    } else {
      AddRangeMeta(*t, sc.range);
    }
  }
  app.out().Write("trajectory.tsv", traj.str());
  if (sectioned) app.out().Write("section.tsv", section.str());
  if (partial) {  // the rows so far, marked partial; no figure
    std::vector<std::string> gone = {"trajectory.gp"};
    gone.insert(gone.end(), figures.begin(), figures.end());
    app.out().Commit(gone);
    return app.ExitCode(why + "; the trajectory so far is written to " + app.out().dir() +
                        ", marked partial");
  }
  TrajectoryFigure fig;
  fig.title = sc.title, fig.format = format, fig.section = sc.o.section;
  fig.t_end = r.end.t, fig.period = s.clocks() ? sc.o.period : 0;
  app.out().Write("trajectory.gp", TrajectoryScript(s, fig));
  if (!app.Finish("trajectory.gp", figures, figures)) return kExitFailed;
  PrintSummary(prog, sc, r, traj.rows());
  std::cout << "wrote " << app.out().dir() << "/trajectory.tsv"
            << (sectioned ? ", section.tsv" : "") << ", trajectory.gp"
            << (app.gnuplot().ok() ? " and the figures" : "") << "\n";
  return app.ExitCode("");
}

}  // namespace stickslip::cli
