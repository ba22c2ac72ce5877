// ss_chart: the stability chart of a study in two parameters: HB, GR and LP
// curves followed by pseudo-arclength continuation, their codimension-two
// points (GH, GR-LP) and the regions between them; TSV files and chart.png.
#include <cstdio>
#include <iostream>
#include <string>
#include <vector>

#include "chart/chart_region_faces.hpp"
#include "cli/about.hpp"
#include "cli/app.hpp"
#include "cli/chart_forced.hpp"
#include "cli/chart_system.hpp"
#include "cli/physical.hpp"
#include "cli/restart.hpp"
#include "cli/study.hpp"
#include "cli/system_choice.hpp"
#include "stickslip/chart/chart.hpp"
#include "stickslip/io/chart_report.hpp"
#include "stickslip/io/report.hpp"

namespace ss = stickslip;
namespace cli = stickslip::cli;
namespace po = boost::program_options;

namespace {

constexpr const char* kProg = "ss_chart";
constexpr const char* kNotes =
    "Outputs in --out (each written whole or not at all): curves.tsv (one row per curve\n"
    "point: HB Hopf with its first Lyapunov coefficient l1, GR grazing with the pure-slip\n"
    "multiplier and its type, LP fold of pure-slip orbits), codim2.tsv (GH generalized\n"
    "Hopf, GR-LP where the grazing type changes), regions.tsv (the regions as polygons\n"
    "between the curves, each classified at one interior point), chart.gp and chart.png\n"
    "(.pdf, .svg with --format).\n"
    "The files are written as one set (docs/reliability.md); with --no_plots the older\n"
    "regions.tsv, chart.gp and chart.png are removed.\n"
    "Solver defaults of this app (the Solver group above states them): --max_steps 20000,\n"
    "and a first return is given up after time 50; a longer run is an orbit running away.\n"
    "Study files: model and solver keys at top level, this app's keys in [chart].\n"
    "An interrupted or failed run writes the curves so far, marked partial.\n"
    "Forced oscillator: --force A, --omega W, or an axis omega or force selects it; the\n"
    "axes are two of its parameters, the law's, force and omega (defaults omega [0.5, 2] x\n"
    "force [0.05, 1]; --force 0.3 where force is no axis), its flow's rtol and atol 1e-12\n"
    "and --grid 40. A system of several\n"
    "masses or contacts (--system chain or mode_coupling): --param and --param2 name two of\n"
    "its parameters, and --from, --to, --from2 and --to2 are required. Both are charts of\n"
    "one kind (docs/systems.md, \"Charts\"): HB curves of steady sliding (no forcing) and LP,\n"
    "PD, NS and GR curves of periodic orbits (GR, forced: where non-stop motion ends) are\n"
    "traced from the special points of one-parameter runs on --seed_lines lines per axis;\n"
    "--grid N shades N x N cells by the attractor reached there (period m and sticks,\n"
    "quasi-periodic, chaotic by the largest Lyapunov exponent, rest, contact lost; each row\n"
    "swept along --param from the blocks carried by the belt; forced: on the stroboscopic\n"
    "map, else on the maxima of the first component). Outputs: curves.tsv, codim2.tsv (SL,\n"
    "LPPD, R1, R2, CP, GG), response.tsv (with a grid), chart.gp and chart.png. A curve cut\n"
    "short, a failed seed run or a failed cell makes it partial (exit 1). --max_amplitude X\n"
    "ends seed branches and grid cells past |x| = X (forced: default 50; --system: 1000).\n"
    "Their solver defaults are the library's (--max_steps 200000, no time limit on a\n"
    "return). --no_plots writes the tables only (with a grid, response.tsv too).\n";
constexpr const char* kExample = "\nExample: ss_chart --study studies/seed_chart.ini --out chart";

po::options_description AppOptions() {
  po::options_description d("Chart (study section [chart])");
  d.add_options()("param", cli::Value()->value_name("NAME"),
                  "first axis, any model parameter (default v)")(
      "from", cli::Value()->value_name("A"), "first axis from (default 0.05)")(
      "to", cli::Value()->value_name("B"), "first axis to, > from (default 0.6)")(
      "param2", cli::Value()->value_name("NAME"), "second axis, != param (default beta)")(
      "from2", cli::Value()->value_name("C"), "second axis from (default 0)")(
      "to2", cli::Value()->value_name("D"), "second axis to, > from2 (default 0.25)")(
      "max_step", cli::Value()->value_name("F"),
      "largest continuation step, fraction of the rectangle (default 0.01)")(
      "grid", cli::Value()->value_name("N"),
      "also classify an N x N grid of cell centres, a check of the region polygons: the "
      "summary counts the cells whose region differs from the polygon drawn there "
      "(default 0: none); forced and --system: the response grid, N x N cells, each the "
      "attractor reached there (forced: default 40; --system: default 0, none)")(
      "seed_lines", cli::Value()->value_name("N"),
      "forced and --system: lines per axis whose one-parameter runs seed the curves, in [0, 20] "
      "(default 3)")(
      "max_m", cli::Value()->value_name("M"),
      "forced: curves of orbits of period m <= M: each PD with 2m <= M starts the doubled "
      "branch, whose points seed curves too, in [1, 8] (default 2); --system: doubled "
      "branches while 2^doublings <= M");
  cli::AddRunOptions(d, "chart",
                     "only the tables: curves.tsv and codim2.tsv (response.tsv with a grid); no "
                     "regions, no gnuplot");
  cli::AddRestartOptions(d);  // the model from a GR or HB point; its curve is followed first
  return d;
}

// What was computed, per curve, and the codim-2 points, on stdout.
void PrintSummary(const ss::ChartResult& r, const ss::Plane& pl, const std::string& model,
                  const std::string& dir, const std::string& figure, bool plots_ok) {
  const std::string p1 = pl.p1.name(), p2 = pl.p2.name();
  std::printf("%s: %s x %s; %s\n%d curves, %d points in %.1f ms", kProg, p1.c_str(), p2.c_str(),
              model.c_str(), static_cast<int>(r.curves.size()), r.points(), r.seconds * 1e3);
  if (!figure.empty())
    std::printf(" (%zu region polygons in %.1f ms)", r.faces.size(), r.face_seconds * 1e3);
  std::printf("\n");
  if (r.regions.n1 > 0)
    std::printf(
        "grid check: %d of %d x %d cell centres differ from the polygon drawn there (%.1f ms)\n",
        ss::GridDisagreements(r.faces, r.regions), r.regions.n1, r.regions.n2,
        r.region_seconds * 1e3);
  for (size_t i = 0; i < r.curves.size(); ++i) {
    const ss::Curve& c = r.curves[i];
    std::printf("  curve %zu %s: %zu points, %d evaluations, %.1f ms, ends %s\n", i + 1,
                ss::CurveLabel(c.kind), c.points.size(), c.evaluations, c.seconds * 1e3,
                c.ends.Text().c_str());
  }
  for (const ss::Codim2Point& p : r.codim2)
    std::printf("  %-5s %s = %.12f  %s = %.12f  %s\n", ss::Name(p.label), p1.c_str(), p.p1,
                p2.c_str(), p.p2, p.description.c_str());
  const std::string drawn =
      figure.empty() ? "" : ", regions.tsv, chart.gp" + (plots_ok ? ", " + figure : "");
  std::printf("wrote %s/curves.tsv, codim2.tsv%s\n", dir.c_str(), drawn.c_str());
}

// An axis by name (UsageError naming the option if it is no parameter).
ss::ParameterAxis Axis(const cli::Arguments& args, const char* key, const std::string& fallback) {
  const std::string name = args.Text(key, fallback);
  const std::string e = ss::UnknownAxisError(name, key);
  if (!e.empty()) throw cli::UsageError(args.Source(key) + ": " + e);
  return ss::ParameterAxis(name);
}

// The options, validated (UsageError naming the option otherwise).
ss::ChartOptions Configure(const cli::Arguments& args, ss::Params* base) {
  for (const char* key : {"seed_lines", "max_m"})  // the forced chart's only
    if (args.Given(key))
      throw cli::UsageError(args.Source(key) +
                            " applies to the forced chart and --system only (--force, "
                            "an axis omega or force, or --system)");
  ss::ChartOptions opts;
  ss::Plane& pl = opts.plane;
  const auto restart = cli::RestartFromArguments(args);
  if (restart && restart->forced)  // its axis (omega, force) is no belt parameter
    throw cli::UsageError(args.Source("restart") + " " + args.Text("restart") +
                          " is a forced run (point " + restart->label + ", " + restart->type +
                          "): a chart restarts from a belt run's GR or HB point");
  pl.p1 = Axis(args, "param", restart ? restart->ParamName() : "v");
  pl.p2 = Axis(args, "param2", "beta");
  pl.from1 = args.Number("from", 0.05);
  pl.to1 = args.Number("to", 0.6);
  pl.from2 = args.Number("from2", 0.0);
  pl.to2 = args.Number("to2", 0.25);
  // The base model is validated at the rectangle's corner; its own values of
  // the two axes are never used.
  *base = cli::ModelFromArguments(args, "", 0, restart ? restart->params : ss::Params());
  ss::FlowOptions flow = opts.orbit.flow;  // a restart's solver, with the chart's step cap
  if (restart) flow = restart->flow, flow.max_steps = opts.orbit.flow.max_steps;
  opts.orbit.flow = cli::FlowOptionsFromArguments(args, flow);
  if (restart) opts.seeds.push_back(cli::ChartSeed(args, *restart, pl, *base));
  opts.max_step = args.Number("max_step", opts.max_step);
  const long grid = args.Integer("grid", 0);
  if (grid != 0 && (grid < 2 || grid > 1000))
    throw cli::UsageError("invalid value '" + args.Text("grid") + "' for " + args.Source("grid") +
                          ": must be 0 (none) or in [2, 1000]");
  // The regions are polygons between the curves; the grid only checks them.
  opts.region_faces = !args.Flag("no_plots");
  if (opts.region_faces) opts.region_n1 = opts.region_n2 = static_cast<int>(grid);
  // A plane error names the option it is about, with where it came from.
  const ss::PlaneError pe = pl.Check(*base);
  if (!pe.message.empty()) {
    const std::string key = ss::PlaneInputKey(pe.input);
    const std::string who = pe.input == ss::PlaneInput::kRectangle
                                ? args.Source("to") + ", " + args.Source("to2")
                                : args.Source(key.empty() ? "param" : key);
    throw cli::UsageError(who + ": " + pe.message);
  }
  const std::string err = opts.ValidationError(*base);
  if (!err.empty()) throw cli::UsageError(err);
  return opts;
}

// "law=cubic k1=... v=[0.05, 0.6] beta=[0, 0.25]": the law's parameters but
// the two axes, then the axes' ranges.
std::string DescribeChart(const ss::Params& base, const ss::Plane& pl) {
  std::string model = std::string("law=") + ss::Name(base.law);
  for (const ss::ParameterAxis& a : ss::ParameterAxes(base.law))
    if (a != pl.p1 && a != pl.p2) model += " " + a.name() + "=" + ss::FormatNumber(a.Get(base));
  return model + " " + pl.p1.name() + "=[" + ss::FormatNumber(pl.from1) + ", " +
         ss::FormatNumber(pl.to1) + "] " + pl.p2.name() + "=[" + ss::FormatNumber(pl.from2) + ", " +
         ss::FormatNumber(pl.to2) + "]";
}

int Main(int argc, char** argv) {
  po::options_description mine = AppOptions();
  mine.add(cli::ForcingOptions());
  const po::options_description desc = cli::AppDescription(mine, ss::ChartOptions().orbit.flow);
  const cli::Arguments args = cli::ParseArguments(argc, argv, desc, "chart");
  if (cli::HelpOrVersion(std::cout, args, kProg, "ss_chart [--study FILE] [options]", desc,
                         std::string(kNotes) + cli::kExitCodeHelp + kExample))
    return 0;
  if (cli::SystemRequested(args)) {
    return cli::RunChart(args, kProg,
                         cli::SystemChartJob(args, kProg, cli::CommandLine(argc, argv)));
  }
  cli::RefuseSystem(args, kProg);
  if (cli::ForcedChartRequested(args)) {
    return cli::RunChart(args, kProg,
                         cli::ForcedChartJob(args, kProg, cli::CommandLine(argc, argv)));
  }
  ss::Params base;
  ss::ChartOptions opts = Configure(args, &base);
  const ss::Plane& pl = opts.plane;
  const ss::FigureFormat format = cli::FigureFormatOf(args);
  const std::string figure = ss::FigureFile("chart", format);
  cli::AppRun app(kProg, args, "chart",
                  {"curves.tsv", "codim2.tsv", "regions.tsv", "chart.gp", figure});
  cli::RunControl& run = app.run();
  run.Phase("following curves");
  opts.cancelled = [&run] {  // polled between points
    run.Heartbeat("");
    return run.Cancelled();
  };
  const ss::ChartResult r = ss::Chart(base, opts);

  const std::string model = DescribeChart(base, pl);
  // Every file starts with the tool, the command, the model and the integrator.
  cli::Metadata meta = cli::RunMetadata(kProg, cli::CommandLine(argc, argv), base, opts.orbit.flow);
  for (auto& [key, value] : meta)  // the axes' base values are never used
    if (key == pl.p1.name() || key == pl.p2.name()) value = "axis";
  meta.push_back({"range", pl.p1.name() + " = [" + ss::FormatNumber(pl.from1) + ", " +
                               ss::FormatNumber(pl.to1) + "], " + pl.p2.name() + " = [" +
                               ss::FormatNumber(pl.from2) + ", " + ss::FormatNumber(pl.to2) + "]"});
  auto text = [&](ss::TsvTable t) {
    t.PrependMeta(meta);
    return t.str();
  };
  run.Phase("writing");
  app.out().Write("curves.tsv", text(ss::CurvesTable(r, pl, model)));
  app.out().Write("codim2.tsv", text(ss::Codim2Table(r, pl, model)));
  if (app.plots()) {
    app.out().Write("regions.tsv", text(ss::RegionsTable(r, pl, model)));
    app.out().Write("chart.gp", ss::ChartScript(r, pl, ss::ChartTitle(base, pl), format,
                                                cli::FigureUnitsOf(cli::ScalesFromArguments(args),
                                                                   pl.p1, pl.p2)));
  }
  // Without plots, the older regions and figure do not belong to these curves.
  const std::vector<std::string> stale = app.plots()
                                             ? std::vector<std::string>{}
                                             : std::vector<std::string>{"regions.tsv", "chart.gp"};
  if (!app.Finish("chart.gp", {figure}, {figure}, stale)) return cli::kExitFailed;
  PrintSummary(r, pl, model, app.out().dir(), app.plots() ? figure : std::string(),
               app.gnuplot().ok());
  if (r.unphysical_points > 0)
    cli::PrintError(kProg, std::to_string(r.unphysical_points) +
                               " curve points have orbits visiting slip speeds where mu <= 0 "
                               "(not physical there; flagged in curves.tsv)");
  std::string partial;
  if (r.status != ss::ChartStatus::kOk)
    partial = std::string("partial chart written (") + ss::Name(r.status) + "): " + r.message +
              (r.status == ss::ChartStatus::kCancelled ? " (" + run.Reason() + ")" : "");
  return app.ExitCode(partial);
}

}  // namespace

int main(int argc, char** argv) {
  return cli::RunApp(kProg, [&] { return Main(argc, argv); });
}
