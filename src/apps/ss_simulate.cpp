// ss_simulate: one trajectory of the belt model (or, with --force, --system
// or --model, of the forced oscillator or another system, their columns named
// from the system: cli/simulate_system.hpp), written into --out DIR as
// trajectory.tsv (metadata lines, then the header: the belt's t, x, xdot,
// mode) and drawn as trajectory.png unless --no_plots.
#include <cmath>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include "cli/about.hpp"
#include "cli/app.hpp"
#include "cli/output.hpp"
#include "cli/physical.hpp"
#include "cli/run_control.hpp"
#include "cli/simulate_forced.hpp"
#include "cli/simulate_system.hpp"
#include "cli/study.hpp"
#include "cli/system_choice.hpp"
#include "stickslip/flow/simulate.hpp"
#include "stickslip/io/figure_style.hpp"
#include "stickslip/io/report.hpp"
#include "stickslip/systems/belt/model.hpp"

namespace ss = stickslip;
namespace cli = stickslip::cli;
namespace po = boost::program_options;

namespace {

constexpr const char* kProg = "ss_simulate";
constexpr const char* kNotes =
    "Output, in --out DIR: trajectory.tsv starts with '# key: value' lines (tool, command,\n"
    "model, run and solver settings, status), then the header line 't<TAB>x<TAB>xdot<TAB>mode'\n"
    "(mode: slip-below, stick, slip-above), then one row every --dt and one at every switch.\n"
    "Stick rows have xdot == v exactly. trajectory.gp draws trajectory.png (phase portrait\n"
    "and time series). With --force A > 0 (the forced oscillator, dimensionless inputs) or\n"
    "--system, the columns are t, every state component (the forced oscillator's x, xdot,\n"
    "theta = Omega t mod 2 pi) and mode, and section.tsv (n, then the same columns) holds\n"
    "the Poincare section (--section strobe: every forcing period, at cos(Omega t) = 1;\n"
    "exit: every stick exit), drawn as section.png (strobe: x' against x; exit: the\n"
    "return map of the stick exits' forcing phase, or of the first component).\n"
    "Study files: key = value lines ('#' comments); keys outside sections are model\n"
    "and solver options, [simulate] holds this app's keys; the command line wins.\n"
    "The files are written as one set (docs/reliability.md); a run cut short writes the\n"
    "trajectory so far, marked '# status: partial (...)', without figures.\n";

po::options_description AppOptions() {
  po::options_description d("Simulation (study section [simulate])");
  d.add_options()("x0", cli::Value()->value_name("X"), "initial displacement (default 0)")(
      "xdot0", cli::Value()->value_name("X"),
      "initial velocity (default 0.25: on the stick set at the seed's v, fig. 5; forced: v)")(
      "t_end", cli::Value()->value_name("T"), "end time, > 0 (default 100)")(
      "dt", cli::Value()->value_name("DT"),
      "output interval, > 0 (default 0.01); switches are written too")(
      "max_rows", cli::Value()->value_name("N"),
      "rows held and written at most, rows at switches (and section points) included, in "
      "[1, 1e7] (default 1e7); a run that needs more exits 2 and writes nothing");
  cli::AddSimulateForcedOptions(d);
  cli::AddSimulateSystemOptions(d);
  cli::AddRunOptions(d, "plots/simulate",
                     "write the TSV files and the script, but do not run gnuplot");
  return d;
}

std::string GnuplotString(const std::string& s) {
  std::string out = "'";
  for (char c : s) out += c == '\'' ? std::string("''") : std::string(1, c);
  return out + "'";
}

// A two-panel figure in the common style (figure_style.hpp): the phase
// portrait with the stick set, and x, x' against t; in SI units (columns
// t_s, x_m, xdot_m_s) when the run has physical inputs.
std::string PlotScript(const std::string& data, const std::string& figure, const ss::Model& model,
                       const std::optional<cli::Scales>& si, ss::FigureFormat format) {
  const double L = si ? si->L : 1, t0 = si ? si->t0 : 1;
  const double v = model.v() * L / t0;
  const double mu_s = model.params().mu_s * L;
  const double shift = 2.0 * model.beta() * model.v() * L;
  const std::string q = GnuplotString(data);
  const int ct = si ? 5 : 1, cx = si ? 6 : 2, cv = si ? 7 : 3;
  const std::string stick = "(strcol(4) eq 'stick' ? $" + std::to_string(cv) + " : NaN)";
  const std::string ux = si ? " [m]" : " (dimensionless)", uv = si ? " [m/s]" : " (dimensionless)",
                    ut = si ? " [s]" : " (dimensionless)";
  const std::string c = ":", n = std::to_string(cx), nv = std::to_string(cv);
  std::string s = ss::FigurePreamble(format, 1400, 650);
  s += "set output " + GnuplotString(figure) + "\n";
  // The stick set: x' = v, |x + 2 beta v| <= mu_s. Its header line is the
  // one `set datafile columnheaders` takes (else it takes the first end).
  s += "$omega << EOD\nx\txdot\n" + ss::FormatNumber(-mu_s - shift) + "\t" + ss::FormatNumber(v) +
       "\n" + ss::FormatNumber(mu_s - shift) + "\t" + ss::FormatNumber(v) + "\nEOD\n";
  s += "set multiplot layout 1,2 title " +
       ss::GnuplotQuoted(ss::FigureTitle(cli::DescribeModel(model.params()), {})) + "\n";
  s += "set xlabel " + ss::GnuplotQuoted("displacement x" + ux) + "\n";
  s += "set ylabel " + ss::GnuplotQuoted("velocity dx/dt" + uv) + "\nset title 'phase portrait'\n";
  s += "plot $omega using 1:2 with lines lw 8 lc rgb '#f4a6a6' title 'stick set: dx/dt = v', \\\n";
  s += "     " + q + " using " + n + c + nv + " with lines ls 1 lw 1.5 title 'trajectory', \\\n";
  s += "     " + q + " using " + n + c + stick + " with lines ls 9 title 'sticking'\n";
  s += "set xlabel " + ss::GnuplotQuoted("time t" + ut) + "\n";
  s += "set ylabel " + ss::GnuplotQuoted("x" + ux + ", dx/dt" + uv) + "\nset title 'time series'\n";
  s += "plot " + q + " using " + std::to_string(ct) + c + n + " with lines ls 1 lw 1.5 title " +
       ss::GnuplotQuoted("displacement x") + ", \\\n";
  s += "     " + q + " using " + std::to_string(ct) + c + nv + " with lines ls 3 lw 1.5 title " +
       ss::GnuplotQuoted("velocity dx/dt") + "\n";
  s += "unset multiplot\n";
  return s;
}

// The belt run's settings, all checked before anything runs or is written.
struct Settings {
  ss::Params params;
  ss::FlowOptions options;
  cli::SimulateRange range;
};

Settings Configure(const cli::Arguments& args) {
  Settings s;
  s.params = cli::ModelFromArguments(args);
  s.options = cli::FlowOptionsFromArguments(args);
  s.range = cli::SimulateRangeFromArguments(args, 0.25);
  return s;
}

// Why a run gives no data: the simulation's status, and where.
std::string Failure(const ss::Simulation& r, const cli::RunControl& run) {
  std::string where;
  if (r.status == ss::SimulationStatus::kFailed && r.flow != ss::FlowStatus::kIntegratorFailed &&
      r.message.find("non-finite") == std::string::npos)  // these messages say where
    where = " (at t = " + ss::FormatNumber(r.end.t) + " in " + ss::Name(r.end.mode[0]) +
            ", x = " + ss::FormatNumber(r.end.z[0]) + ", x' = " + ss::FormatNumber(r.end.z[1]) +
            ")";
  return r.message + where +
         (r.status == ss::SimulationStatus::kCancelled ? " (" + run.Reason() + ")" : "");
}

int SimulateBelt(const cli::Arguments& args, const std::string& command) {
  const Settings s = Configure(args);
  // With physical inputs, physical copies of t, x and x' follow (seed section 3 scaling).
  const std::optional<cli::Scales> scales = cli::ScalesFromArguments(args);
  const ss::FigureFormat format = cli::FigureFormatOf(args);
  const std::string figure = ss::FigureFile("trajectory", format);
  cli::AppRun app(kProg, args, "plots/simulate", {"trajectory.tsv", "trajectory.gp", figure});
  cli::RunControl& run = app.run();
  const ss::Model model(s.params);
  ss::SimulationOptions o;
  o.flow = s.options, o.t_end = s.range.t_end, o.dt = s.range.dt, o.max_rows = s.range.max_rows;
  o.cancelled = [&] {
    run.Heartbeat("");
    return run.Cancelled();
  };
  run.Phase("integrating");
  std::vector<std::string> columns = {"t", "x", "xdot", "mode"};
  if (scales) columns.insert(columns.end(), {"t_s", "x_m", "xdot_m_s"});
  ss::TsvTable table(columns);
  for (const auto& [key, value] : cli::RunMetadata(kProg, command, s.params, s.options))
    table.AddMeta(key, value);
  table.AddMeta("model", cli::DescribeModel(s.params));
  cli::AddRangeMeta(table, s.range);
  if (scales) {
    table.AddMeta("L", ss::FormatNumber(scales->L) + " m (M g / K)");
    table.AddMeta("t0", ss::FormatNumber(scales->t0) + " s (sqrt(M / K))");
  }
  ss::SimulationSink sink;
  double t_last = 0;  // the last row's t
  sink.row = [&](double t, const double* z, const ss::ModeSet& m) {
    t_last = t;
    if (scales)
      table.AddRow({t, z[0], z[1], ss::Name(m[0]), t * scales->t0, z[0] * scales->L,
                    z[1] * scales->L / scales->t0});
    else
      table.AddRow({t, z[0], z[1], ss::Name(m[0])});
    run.Progress("t = " + ss::FormatNumber(t), t / s.range.t_end, t, "time units");
  };
  const ss::Vec2 start(s.range.x0, s.range.xdot0);
  ss::Simulation r;
  try {
    r = ss::Simulate(model, ss::FlowPoint{0, start, ss::ModeSet(model.ModeAt(start))}, o, sink);
  } catch (const ss::InvalidArgument& e) {  // valid input: a numerical failure
    throw ss::Error(std::string("numerical failure: ") + e.what());
  }
  if (r.status == ss::SimulationStatus::kRowLimit)  // bad input found late: nothing written
    throw cli::UsageError(args.Source("t_end") + " " + args.Text("t_end", "100") + " with " +
                          args.Source("dt") + " " + args.Text("dt", "0.01") + ": more than " +
                          args.Source("max_rows") + " = " + std::to_string(s.range.max_rows) +
                          " rows (rows at switches included) by t = " + ss::FormatNumber(t_last) +
                          "; use a shorter --t_end or a larger --dt");
  run.Phase("writing");
  if (!r.ok()) {
    // As every app: the rows so far (all finite), marked partial with where
    // the run stopped; no figure, and an older one is removed (not this run's).
    const std::string why = Failure(r, run);
    table.AddMeta("status", "partial (" + why + ")");
    app.out().Write("trajectory.tsv", table.str());
    app.out().Commit({"trajectory.gp", figure});
    return app.ExitCode(why + "; the trajectory so far is written to " + app.out().dir() +
                        "/trajectory.tsv, marked partial");
  }
  table.AddMeta("status", "complete");
  app.out().Write("trajectory.tsv", table.str());
  app.out().Write("trajectory.gp", PlotScript("trajectory.tsv", figure, model, scales, format));
  if (!app.Finish("trajectory.gp", {figure}, {figure})) return cli::kExitFailed;
  std::cout << kProg << ": " << table.rows() << " rows to t = " << ss::FormatNumber(r.end.t)
            << "; wrote " << app.out().dir() << "/trajectory.tsv"
            << (app.gnuplot().ok() ? " and " + figure : "") << "\n";
  return app.ExitCode("");
}

int Main(int argc, char** argv) {
  po::options_description desc = cli::AppDescription(AppOptions());
  desc.add(cli::ForcingOptions());
  const cli::Arguments args = cli::ParseArguments(argc, argv, desc, "simulate");
  if (cli::HelpOrVersion(std::cout, args, kProg,
                         "ss_simulate [--study FILE] [model options] [--force A --omega W "
                         "[--section strobe|exit | --orbits [--max_m M]]] [--x0 X] [--xdot0 Y] "
                         "[--t_end T] [--dt DT] "
                         "[--out DIR] [--no_plots] [--max_time S]",
                         desc,
                         std::string(kNotes) + cli::kExitCodeHelp +
                             "\nExample: ss_simulate --study studies/seed.ini --xdot0 "
                             "0.125 --out plots/traj"))
    return 0;
  const std::string command = cli::CommandLine(argc, argv);
  if (cli::SystemRequested(args))  // chain, mode_coupling (docs/systems.md)
    return cli::SimulateSystemApp(args, kProg, command);
  cli::RefuseSystem(args, kProg, {"state"});
  const bool forced = cli::ForcedRequested(args);
  if (forced && args.Flag("orbits")) {
    // A study's [simulate] section is for its trajectory: only the command line's is refused.
    if (args.OnCommandLine("section"))
      throw cli::UsageError(args.Source("section") +
                            " applies to a trajectory, not to --orbits (a list of orbits)");
    return cli::ForcedOrbitsApp(args, kProg, command);
  }
  if (forced && args.OnCommandLine("max_amplitude"))
    throw cli::UsageError(args.Source("max_amplitude") +
                          " bounds a branch or a chart; a trajectory has --max_rows");
  for (const char* name : {"orbits", "max_m"})
    if (args.Given(name) && (!forced || std::string(name) == "max_m"))
      throw cli::UsageError(args.Source(name) + (forced ? " needs --orbits"
                                                        : " needs the forced oscillator: give "
                                                          "--force A > 0"));
  if (forced) return cli::SimulateSystemApp(args, kProg, command);
  if (args.Given("section"))
    throw cli::UsageError(args.Source("section") +
                          " needs the forced oscillator (--force A > 0) or --system");
  return SimulateBelt(args, command);
}

}  // namespace

int main(int argc, char** argv) {
  return cli::RunApp(kProg, [&] { return Main(argc, argv); });
}
