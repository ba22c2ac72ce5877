// ss_continue: the bifurcation diagram of a study in one parameter: branches
// of stick-slip and pure-slip orbits and of steady sliding, their special
// points (GR, HB, LP), TSV files and gnuplot figures in --out.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include "cli/about.hpp"
#include "cli/app.hpp"
#include "cli/clock_start.hpp"
#include "cli/estimates_text.hpp"
#include "cli/physical.hpp"
#include "cli/restart.hpp"
#include "cli/run_continuation.hpp"
#include "cli/run_control.hpp"
#include "cli/run_log.hpp"
#include "cli/run_system.hpp"
#include "cli/study.hpp"
#include "cli/system_choice.hpp"
#include "cli/system_restart.hpp"
#include "numerics/numbers.hpp"
#include "stickslip/basin/branch_disturbance.hpp"
#include "stickslip/continuation/continuation.hpp"
#include "stickslip/estimates/comparison.hpp"
#include "stickslip/io/branch_report.hpp"
#include "stickslip/io/report.hpp"

namespace ss = stickslip;
namespace cli = stickslip::cli;
namespace po = boost::program_options;

namespace {

constexpr const char* kProg = "ss_continue";
constexpr const char* kNotes =
    "Outputs in --out, written as one set (docs/reliability.md): branch.tsv (one row per\n"
    "point; kind stick-slip / pure-slip / equilibrium; multiplier = nontrivial Floquet\n"
    "multiplier, for the equilibrium the largest real part of its eigenvalues; then\n"
    "dist_x dist_xdot dist_energy newton_stalled; every column in docs/formats.md),\n"
    "special_points.tsv (GR grazing-sliding, HB Hopf, LP fold), bifurcation.gp and its\n"
    "figures bifurcation_x.png, bifurcation_xdot.png, period.png, multiplier.png\n"
    "(estimates.png with the estimates; .pdf or .svg with --format). Only regular files (or new "
    "names) are replaced;\n"
    "a symlink at an output's place is refused.\n"
    "Each TSV starts with '# key: value' lines (tool, command, model, range, tolerances,\n"
    "integrator, status), then one header line without '#'.\n"
    "Study files: model and solver keys at top level, this app's keys in [continue].\n"
    "The estimates apply to the cubic law with k5 = 0; elsewhere they are skipped, with\n"
    "a note on stderr.\n"
    "Points: branch.tsv numbers its rows (pt); special_points.tsv gives each point its row\n"
    "(pt) and a label (lab: GR1, HB1, LP1, ... per type in branch order). --restart DIR\n"
    "--point HB1 starts at that point: its parameters, solver options and continued\n"
    "parameter are the defaults, --from is its value (--to the far end of the range).\n"
    "A forced run (--param: its law's, force or omega) restarts from a point (PD1, ...)\n"
    "at its stroboscopic state (x_0, xdot_0); no --force needed.\n";
constexpr const char* kExample =
    "\nExample: ss_continue --study studies/seed.ini --param v --from 0.05 --to 0.5\n"
    "         ss_continue --restart plots --point HB1 --param beta --out hb_beta";

po::options_description AppOptions() {
  po::options_description d("Continuation (study section [continue])");
  d.add_options()("param", cli::Value()->value_name("NAME"),
                  ("parameter to continue: " + ss::ParameterNameList() +
                   " (default v); with physical inputs also belt_speed, damping, speed_m, "
                   "speed_s, delta_phys, in physical units")
                      .c_str())(
      "from", cli::Value()->value_name("A"),
      "start value; the first row is here (default: the parameter's range, v 0.05, beta 0.01, "
      "mu_s 1.2 mu_m, ...)")("to", cli::Value()->value_name("B"),
                             "end value, != from (default: v 0.5, beta 0.3, ...)")(
      "max_step", cli::Value()->value_name("F"),
      "largest step as a fraction of |to - from| (default 0.01: >= 100 points)")(
      "floquet", po::bool_switch(),
      "compute stick-slip multipliers from the variational equations (else 0, exact)")(
      "no_estimates", po::bool_switch(),
      "cubic law: skip the comparison with the seed's and the averaging estimates")(
      "verbose", po::bool_switch(),
      "print a line per point (pt, kind, parameter, period, x range, multiplier, stability, "
      "label), as AUTO-07p does; the special points with their labels and pt are printed "
      "always");
  cli::AddRunOptions(d, "plots", "write the TSV files and the script, but do not run gnuplot");
  cli::AddRestartOptions(d, true);
  cli::AddStartOptions(d);
  d.add_options()("switch", po::bool_switch(),
                  "with --restart DIR --point PDn of a forced or a --system run: continue the "
                  "period-doubled branch (m -> 2m, or twice the section's returns; AUTO's "
                  "ISW=-1) from the PD point to whichever of --from, --to (default: the range of "
                  "the run the point came from) it opens toward");
  return d;
}

using cli::Fixed;
using cli::PrintComparison;

// Physical copies of the parameter axis (if it has units), x and the period,
// for branch points or special points.
template <typename Point>
std::vector<ss::ExtraColumn> PhysicalColumns(const cli::Scales& s, const std::string& param,
                                             const std::vector<Point>& points) {
  const auto axis = cli::AxisOf(param, s);
  std::vector<ss::ExtraColumn> c;
  if (axis) c.push_back({axis->physical, {}});
  c.insert(c.end(), {{"x_min_m", {}}, {"x_max_m", {}}, {"period_s", {}}});
  for (const Point& pt : points) {
    auto col = c.end() - 3;
    if (axis) col[-1].values.push_back(pt.p / axis->factor);
    col[0].values.push_back(pt.extrema.x_min * s.L);
    col[1].values.push_back(pt.extrema.x_max * s.L);
    col[2].values.push_back(pt.period * s.t0);
  }
  return c;
}

// Physical inputs: the scales, and how the physical axis relates to the continued one.
void AddScales(const cli::Scales& s, const std::string& param, cli::Metadata& meta) {
  meta.insert(meta.end(), {{"L", ss::FormatNumber(s.L) + " m (M g / K)"},
                           {"t0", ss::FormatNumber(s.t0) + " s (sqrt(M / K))"}});
  if (const auto axis = cli::AxisOf(param, s))
    meta.emplace_back("continued_physical",
                      axis->physical + " = " + param + " / " + ss::FormatNumber(axis->factor));
}

// The options, validated (UsageError naming the option otherwise).
// With --restart, the point's parameters, solver options and continued
// parameter are the defaults, and the run starts at the point.
ss::ContinuationOptions Configure(const cli::Arguments& args, ss::Params* base,
                                  const std::optional<ss::LabelledPoint>& point) {
  ss::ContinuationOptions opts;
  const ss::Params defaults = point ? point->params : ss::Params();
  // With physical inputs, --param belt_speed (damping, speed_m, ...) runs in
  // physical units: its dimensionless parameter is continued over the range
  // converted by the seed's scaling.
  const std::optional<cli::Scales> scales = cli::ScalesFromArguments(args);
  const std::string asked = args.Text("param", point ? point->ParamName() : "v");
  const auto axis = cli::AxisOf(asked, scales.value_or(cli::Scales()));
  const bool physical_param = axis && asked == axis->physical;
  if (physical_param && !scales)
    throw cli::UsageError("--param " + asked + " is a physical input: give the physical model " +
                          "(--mass --damping --stiffness --belt_speed ...), or use --param " +
                          axis->dimensionless);
  const double to_param = physical_param ? axis->factor : 1.0;  // dimensionless per given
  const std::string name = physical_param ? axis->dimensionless : asked;
  if (!ss::IsParameterName(name))  // parsed once, here: the library takes the axis
    throw cli::UsageError("--param: unknown parameter '" + name + "' (expected one of " +
                          ss::ParameterNameList() + ")");
  opts.param = ss::ParameterAxis(name);
  // Each parameter's own default range (v 0.05 -> 0.5, beta 0.01 -> 0.3, ...).
  const ss::Params given = cli::UncheckedModelFromArguments(args, defaults);
  // A restart runs from the point to the far end of the default range.
  const ss::ParameterRange range =
      point ? ss::RangeFromPoint(given, opts.param) : ss::DefaultRange(given, opts.param);
  opts.from = args.Number("from", range.from / to_param) * to_param;
  *base = cli::ModelFromArguments(args, opts.param.name(), opts.from, defaults);
  opts.orbit.flow = cli::FlowOptionsFromArguments(args, point ? point->flow : ss::FlowOptions());
  opts.to = args.Number("to", range.to / to_param) * to_param;
  opts.max_step = args.Number("max_step", opts.max_step);
  opts.stick_slip_floquet = args.Flag("floquet");
  if (std::isfinite(opts.to))  // the model at --to, blamed on --to
    if (const std::string e = ss::ValidationError(opts.param.At(*base, opts.to)); !e.empty())
      throw cli::UsageError(args.Source("to") + " = " + ss::FormatNumber(opts.to) + ": " + e);
  const std::string err = opts.ValidationError(*base);
  if (!err.empty()) {
    const bool is_param = err.find("parameter") != std::string::npos;
    throw cli::UsageError(std::string(is_param ? "--param: " : "") + err);
  }
  // Memory bound: the equilibrium branch alone has 1 / max_step rows.
  if (std::ceil(1.0 / opts.max_step) > opts.max_points)
    throw cli::UsageError("max_step = " + ss::FormatNumber(opts.max_step) + " (" +
                          args.Source("max_step") + ") needs more than " +
                          std::to_string(opts.max_points) +
                          " points per branch, the memory bound; use max_step >= " +
                          ss::FormatNumber(1.0 / opts.max_points));
  return opts;
}

void PrintSummary(const ss::ContinuationResult& r, const ss::ContinuationOptions& opts,
                  const std::string& model, double seconds, cli::LogDetail detail,
                  const std::optional<cli::Scales>& scales) {
  int counts[3] = {0, 0, 0};
  for (const auto& pt : r.points) ++counts[static_cast<int>(pt.kind)];
  std::cout << kProg << ": " << opts.param.name() << " from " << opts.from << " to " << opts.to
            << "; " << model << "\n"
            << r.points.size() << " points: " << counts[0] << " stick-slip, " << counts[1]
            << " pure-slip, " << counts[2] << " equilibrium, in " << Fixed(seconds * 1e3, 1)
            << " ms\n";
  const ss::ContinuationCounts& n = r.counts;
  const ss::ContinuationTimes& t = r.seconds;
  std::cout << "work: " << n.orbit_solves << " orbit solves, " << n.return_maps << " return maps, "
            << n.newton_iterations << " Newton iterations, " << n.rejected_steps
            << " rejected steps, " << n.integrator_steps << " integrator steps\n"
            << "time (ms): equilibrium " << Fixed(t.equilibrium * 1e3, 1) << ", stick-slip "
            << Fixed(t.stick_slip * 1e3, 1) << ", pure-slip " << Fixed(t.pure_slip * 1e3, 1)
            << ", switching " << Fixed(t.switching * 1e3, 1) << ", discovery "
            << Fixed(t.discovery * 1e3, 1) << "\n";
  for (const std::string& w : r.warnings) std::cerr << kProg << ": warning: " << w << "\n";
  cli::PrintBranchLog(std::cout, r, detail, scales);
}

// How the files were made: tool, command, model, range, tolerances, and
// with physical inputs the scales (then BranchTable adds the status).
cli::Metadata FileMetadata(const std::string& command, const ss::Params& base,
                           const ss::ContinuationOptions& opts,
                           const std::optional<cli::Scales>& scales) {
  cli::Metadata meta = cli::RunMetadata(kProg, command, base, opts.orbit.flow, opts.param.name());
  meta.insert(meta.end(), {{"continued", opts.param.name()},
                           {"from", ss::FormatNumber(opts.from)},
                           {"to", ss::FormatNumber(opts.to)},
                           {"max_step", ss::FormatNumber(opts.max_step)},
                           {"newton_tol", ss::FormatNumber(opts.orbit.EffectiveNewtonTol())},
                           {"locate_tol", ss::FormatNumber(opts.locate_tol)}});
  if (scales) AddScales(*scales, opts.param.name(), meta);
  return meta;
}

// What Outputs writes besides the result: the metadata and the scales (if physical).
struct Provenance {
  cli::Metadata meta;
  std::optional<cli::Scales> scales;
  cli::LogDetail detail = cli::LogDetail::kSpecialPoints;  // --verbose: every point
};

int Outputs(cli::AppRun& app, const ss::ContinuationResult& r, const ss::Params& base,
            const ss::ContinuationOptions& opts, const Provenance& prov, bool estimates,
            ss::FigureFormat format);

int Main(int argc, char** argv) {
  po::options_description mine = cli::ForcingOptions();  // the forced oscillator
  mine.add(AppOptions());
  mine.add(cli::SystemRunOptions());
  const po::options_description desc = cli::AppDescription(mine);
  const cli::Arguments args = cli::ParseArguments(argc, argv, desc, "continue");
  if (cli::HelpOrVersion(std::cout, args, kProg, "ss_continue [--study FILE] [options]", desc,
                         std::string(kNotes) + cli::kExitCodeHelp + kExample))
    return 0;
  // The belt's own run, else the system run (docs/systems.md): --system,
  // --model, the forced oscillator (--force) or a restart of one of them.
  if (cli::SystemRequested(args) || cli::SystemRestartRequested(args) ||
      cli::SystemChoiceOf(args) == cli::SystemChoice::kForced)
    return cli::RunSystem(args, kProg, cli::CommandLine(argc, argv));
  cli::RefuseSystem(args, kProg, {"start_at", "transient", "disturbance"});
  cli::ForcedRequested(args);  // --omega or --param omega without a forcing: UsageError
  const std::optional<ss::LabelledPoint> restart = cli::RestartFromArguments(args);
  if (restart && restart->forced)  // a forced run's point from before its files named the system
    return cli::RunSystem(args, kProg, cli::CommandLine(argc, argv));
  for (const char* o : {"all", "m"})
    if (args.Given(o) && (std::string(o) != "all" || args.Flag("all")))
      throw cli::UsageError(args.Source(o) +
                            " chooses a start orbit of the forced oscillator or a --system or "
                            "--model run (the belt's start is its attractor)");
  if (args.Flag("switch"))
    throw cli::UsageError(args.Source("switch") +
                          " needs --restart DIR --point PDn of a forced run (the belt's "
                          "branches have no period doubling)");
  ss::Params base;
  const ss::ContinuationOptions opts = Configure(args, &base, restart);
  Provenance prov;
  prov.scales = cli::ScalesFromArguments(args);
  if (args.Flag("verbose")) prov.detail = cli::LogDetail::kEveryPoint;
  prov.meta = FileMetadata(cli::CommandLine(argc, argv), base, opts, prov.scales);
  if (restart) prov.meta.emplace_back("restart", cli::DescribeRestart(args, *restart));
  std::vector<std::string> names = {"branch.tsv", "special_points.tsv", "bifurcation.gp"};
  const ss::FigureFormat format = cli::FigureFormatOf(args);
  const std::vector<std::string> all_figures = ss::BifurcationFigures(true, format);
  names.insert(names.end(), all_figures.begin(), all_figures.end());
  cli::AppRun app(kProg, args, "plots", names);
  const ss::ContinuationResult r = cli::RunContinuation(base, opts, app.run());
  return Outputs(app, r, base, opts, prov, !args.Flag("no_estimates"), format);
}

// The estimate comparison, if it applies (cubic law, k5 = 0); otherwise, or
// if it cannot be made at these parameters, a note on stderr and no columns.
ss::EstimateComparison Estimates(const ss::Params& base, const ss::ContinuationResult& r,
                                 cli::RunControl& run) {
  ss::EstimateComparison cmp;
  run.Phase("comparing with the estimates");
  try {
    cmp = ss::CompareEstimates(base, r, 2001, [&run] { return run.Cancelled(); });
  } catch (const ss::InvalidArgument& e) {  // outside the estimates' own assumptions
    cmp = ss::EstimateComparison();
    cmp.reason = e.what();
  }
  if (!cmp.applies && base.law == ss::LawKind::kCubic)
    std::cerr << kProg << ": note: estimates skipped (" << cmp.reason
              << "); --no_estimates turns them off\n";
  return cmp;
}

// Writes the set, draws the figures, prints the summary; returns the exit code.
int Outputs(cli::AppRun& app, const ss::ContinuationResult& r, const ss::Params& base,
            const ss::ContinuationOptions& opts, const Provenance& prov, bool estimates,
            ss::FigureFormat format) {
  cli::RunControl& run = app.run();
  const double seconds = run.Elapsed();
  const std::string model = cli::DescribeModel(base, opts.param.name(), opts.from, opts.to);
  ss::EstimateComparison cmp;
  if (estimates && !run.Cancelled()) cmp = Estimates(base, r, run);
  // Estimate columns first (the figure script counts on their numbers), then
  // the smallest disturbance and the Newton-stall mark.
  std::vector<ss::ExtraColumn> extra = cmp.columns;
  run.Phase("smallest disturbances");
  auto cancelled = [&run] { return run.Cancelled(); };
  ss::ExtraColumn dx{"dist_x", {}}, dy{"dist_xdot", {}}, de{"dist_energy", {}};
  for (const ss::Disturbance& d : ss::BranchDisturbances(base, r, opts.orbit.flow, cancelled))
    dx.values.push_back(d.x), dy.values.push_back(d.xdot), de.values.push_back(d.energy);
  for (ss::ExtraColumn* c : {&dx, &dy, &de}) extra.push_back(std::move(*c));
  ss::ExtraColumn stalled{"newton_stalled", {}};
  for (const auto& pt : r.points) stalled.values.push_back(pt.newton_stalled ? 1 : 0);
  extra.push_back(std::move(stalled));
  std::vector<ss::ExtraColumn> special_extra;
  if (prov.scales) {  // physical copies last
    const auto phys = PhysicalColumns(*prov.scales, opts.param.name(), r.points);
    extra.insert(extra.end(), phys.begin(), phys.end());
    special_extra = PhysicalColumns(*prov.scales, opts.param.name(), r.special);
  }
  run.Phase("writing");
  ss::TsvTable branch = ss::BranchTable(r, model, extra);
  branch.PrependMeta(prov.meta);
  ss::TsvTable special = ss::SpecialPointTable(r, special_extra);
  special.PrependMeta(prov.meta);
  app.out().Write("branch.tsv", branch.str());
  app.out().Write("special_points.tsv", special.str());
  const std::string title = model + (r.partial() ? " (partial)" : "");
  app.out().Write("bifurcation.gp",
                  ss::BifurcationScript(r, title, cmp.applies, format,
                                        cli::FigureUnitsOf(prov.scales, opts.param)));
  if (!app.Finish("bifurcation.gp", ss::BifurcationFigures(cmp.applies, format),
                  ss::BifurcationFigures(true, format)))
    return cli::kExitFailed;

  PrintSummary(r, opts, model, seconds, prov.detail, prov.scales);
  std::cout << "wrote " << app.out().dir() << "/branch.tsv, special_points.tsv, bifurcation.gp"
            << (app.gnuplot().ok() ? std::string(" and the ") + ss::Name(format) + " figures"
                                   : std::string())
            << "\n";
  if (cmp.applies && !cmp.rows.empty() && !cmp.cancelled) PrintComparison(cmp, opts.param.name());
  std::string partial;
  if (r.partial())
    partial = "partial branch written (" + std::string(ss::Name(r.status)) + "): " + r.message;
  return app.ExitCode(partial);
}

}  // namespace

int main(int argc, char** argv) {
  return cli::RunApp(kProg, [&] { return Main(argc, argv); });
}
