// ss_simulate --system (simulate_system.hpp).
#include "cli/simulate_system.hpp"

#include <cmath>
#include <iostream>
#include <memory>
#include <sstream>

#include "cli/about.hpp"
#include "cli/app.hpp"
#include "cli/simulate_forced.hpp"
#include "cli/system_choice.hpp"
#include "stickslip/equilibria/steady_sliding.hpp"
#include "stickslip/flow/simulate.hpp"
#include "stickslip/io/figure_style.hpp"
#include "stickslip/io/system_branch_report.hpp"

namespace stickslip::cli {

namespace {

constexpr double kDisturbance = 0.01;  // the default start: steady sliding, z_0 moved by this

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
  for (int c = 0; c < s.contacts(); ++c)
    if (const auto n = s.NormalForce(c); n && !(n->At(z.data()) > 0))
      throw UsageError(args.Source("state") + " = '" + text + "': contact " + std::to_string(c) +
                       " is open there (normal force " + FormatNumber(n->At(z.data())) + " <= 0)");
  return z;
}

// Two panels: the first contact's coordinate and rate (phase portrait), and
// every displacement (a component some other one is the rate of) against t.
std::string PlotScript(const System& s, const std::string& figure, const std::string& title,
                       FigureFormat format) {
  std::ostringstream os;
  os << FigurePreamble(format, 1400, 650) << "set output " << GnuplotQuoted(figure) << "\n"
     << "set multiplot layout 1,2 title " << GnuplotQuoted(EnhancedText(title)) << "\n"
     << "set xlabel " << GnuplotQuoted(EnhancedText(s.StateName(0))) << "\nset ylabel "
     << GnuplotQuoted(EnhancedText(s.StateName(1))) << "\nset title 'phase portrait'\nunset key\n"
     << "plot 'trajectory.tsv' using '" << StateColumn(s, 0) << "':'" << StateColumn(s, 1)
     << "' with lines ls 1 lw 1.5 notitle\n"
     << "set key\nset xlabel 'time t'\nset ylabel 'displacements'\nset title 'time series'\n"
     << "plot ";
  int k = 0;
  for (int i = 0; i < s.tangent_dimension(); ++i) {
    if (s.DerivativeOf(i) < 0) continue;
    os << (k ? ", \\\n  " : "") << "'trajectory.tsv' using 't':'" << StateColumn(s, i)
       << "' with lines lw 1.5 lc rgb '" << SeriesColor(k) << "' title "
       << GnuplotQuoted(EnhancedText(s.StateName(i)));
    ++k;
  }
  os << "\nunset multiplot\n";
  return os.str();
}

}  // namespace

void AddSimulateSystemOptions(po::options_description& d) {
  d.add_options()("state", Value()->value_name("Z1,Z2,..."),
                  "--system: the start, every state component in order (default: steady "
                  "sliding with the first component moved by 0.01)");
}

int SimulateSystemApp(const Arguments& args, const std::string& prog, const std::string& command) {
  for (const char* o : {"x0", "xdot0", "section", "orbits", "max_m", "max_amplitude"})
    if (args.Given(o))
      throw UsageError(args.Source(o) +
                       " applies to the belt and the forced oscillator; give "
                       "--state with --system " +
                       args.Text("system"));
  const std::unique_ptr<System> s = SystemFromArguments(args);
  const SimulateRange range = SimulateRangeFromArguments(args, 0);
  const FlowOptions options = FlowOptionsFromArguments(args);
  const Eigen::VectorXd z0 = StartState(args, *s);
  const FigureFormat format = FigureFormatOf(args);
  const std::string figure = FigureFile("trajectory", format);
  AppRun app(prog, args, "plots/simulate", {"trajectory.tsv", "trajectory.gp", figure});
  RunControl& run = app.run();
  std::vector<std::string> columns = {"t"};
  for (int i = 0; i < s->dimension(); ++i) columns.push_back(StateColumn(*s, i));
  columns.push_back("mode");
  TsvTable table(columns);
  const std::string model = DescribeSystem(*s, SystemChoiceOf(args), -1);
  for (const auto& [key, value] : ToolMetadata(prog, command)) table.AddMeta(key, value);
  table.AddMeta("system", model);
  table.AddMeta("t_end", FormatNumber(range.t_end));
  table.AddMeta("dt", FormatNumber(range.dt));
  table.AddMeta("rtol", FormatNumber(options.rtol));
  table.AddMeta("atol", FormatNumber(options.atol));
  SimulationOptions o;
  o.flow = options, o.t_end = range.t_end, o.dt = range.dt, o.max_rows = range.max_rows;
  o.cancelled = [&] { return run.Cancelled(); };
  SimulationSink sink;
  sink.row = [&](double t, const double* z, const ModeSet& m) {
    std::vector<TsvTable::Cell> row = {t};
    for (int i = 0; i < s->dimension(); ++i) row.emplace_back(z[i]);
    row.emplace_back(ModeSetName(m, s->contacts()));
    table.AddRow(row);
    run.Progress("t = " + FormatNumber(t), t / range.t_end, t, "time units");
  };
  run.Phase("integrating");
  const Simulation r = Simulate(*s, FlowPoint{0, z0, ModeOf(*s, z0)}, o, sink);
  if (r.status == SimulationStatus::kRowLimit)
    throw UsageError(args.Source("max_rows") + " = " + std::to_string(range.max_rows) +
                     ": the rows at switches took the table past it by t = " +
                     FormatNumber(r.end.t) + "; use a shorter --t_end or a larger --dt");
  run.Phase("writing");
  if (!r.ok()) {  // the rows so far, marked partial; no figure
    const std::string why =
        r.message + (r.status == SimulationStatus::kCancelled ? " (" + run.Reason() + ")" : "");
    table.AddMeta("status", "partial (" + why + ")");
    app.out().Write("trajectory.tsv", table.str());
    app.out().Commit({"trajectory.gp", figure});
    return app.ExitCode(why + "; the trajectory so far is written, marked partial");
  }
  table.AddMeta("status", r.status == SimulationStatus::kContactOpen
                              ? "complete: contact " + std::to_string(r.opened) +
                                    " opens at t = " + FormatNumber(r.end.t) + ", the run ends"
                              : std::string("complete"));
  app.out().Write("trajectory.tsv", table.str());
  app.out().Write("trajectory.gp", PlotScript(*s, figure, model, format));
  if (!app.Finish("trajectory.gp", {figure}, {figure})) return kExitFailed;
  std::cout << prog << ": " << table.rows() << " rows to t = " << FormatNumber(r.end.t) << " ("
            << Name(r.status) << ", " << r.sticks << " sticks); wrote " << app.out().dir()
            << "/trajectory.tsv" << (app.gnuplot().ok() ? " and " + figure : "") << "\n";
  return app.ExitCode("");
}

}  // namespace stickslip::cli
