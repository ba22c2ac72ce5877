// ss_continue: the bifurcation diagram of a study in one parameter: branches
// of stick-slip and pure-slip orbits and of steady sliding, their special
// points (GR, HB, LP), TSV files and gnuplot figures in --out.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include "cli/about.hpp"
#include "cli/output.hpp"
#include "cli/physical.hpp"
#include "cli/run_continuation.hpp"
#include "cli/run_control.hpp"
#include "cli/study.hpp"
#include "stickslip/branch_disturbance.hpp"
#include "stickslip/branch_report.hpp"
#include "stickslip/comparison.hpp"
#include "stickslip/continuation.hpp"
#include "stickslip/numbers.hpp"
#include "stickslip/report.hpp"

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
    "(estimates.png with the estimates). Only regular files (or new names) are replaced;\n"
    "a symlink at an output's place is refused.\n"
    "Each TSV starts with '# key: value' lines (tool, command, model, range, tolerances,\n"
    "integrator, status), then one header line without '#'.\n"
    "Study files: model and solver keys at top level, this app's keys in [continue].\n"
    "Exit status: 0 done; 1 numerical failure, interruption (SIGINT/SIGTERM), time limit\n"
    "or I/O failure (the branch so far is written, marked partial; if a figure cannot be\n"
    "drawn whole, no file is replaced); 2 bad input (nothing written); 3 gnuplot is\n"
    "missing (data files and script written, no figures).\n"
    "Example: ss_continue --study studies/seed.ini --param v --from 0.05 --to 0.5";

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
      "out", cli::Value()->value_name("DIR"), "output directory (default plots)")(
      "max_step", cli::Value()->value_name("F"),
      "largest step as a fraction of |to - from| (default 0.01: >= 100 points)")(
      "floquet", po::bool_switch(),
      "compute stick-slip multipliers from the variational equations (else 0, exact)")(
      "max_time", cli::Value()->value_name("S"),
      "wall-time limit in seconds; the branch so far is kept (default none)")(
      "no_plots", po::bool_switch(), "write the TSV files and the script, but do not run gnuplot")(
      "no_estimates", po::bool_switch(),
      "cubic law: skip the comparison with the seed's and the averaging estimates");
  return d;
}

std::string Fixed(double x, int digits) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", digits, x);
  return buf;
}

// A few rows of the estimate comparison, spread over the periodic branch.
void PrintComparison(const ss::EstimateComparison& c, const std::string& param) {
  std::cout << "estimates against the branch (x'_min; error = estimate - computed):\n"
            << "  " << param << "        kind         computed   seed r1    error     "
            << "averaging -a_ps  error\n";
  const size_t n = c.rows.size();
  auto cell = [](const ss::EstimateCell& e) {
    if (!e.applies) return std::string("      n/a             ");
    char buf[64];
    std::snprintf(buf, sizeof buf, "%9.5f  %+9.5f", e.estimate, e.error);
    return std::string(buf);
  };
  for (size_t k = 0; k < 7 && n > 0; ++k) {
    const ss::ComparisonRow& row = c.rows[k * (n - 1) / 6];
    char head[96];
    std::snprintf(head, sizeof head, "  %-9.5f  %-11s  %9.5f  ", row.p, ss::PointKindName(row.kind),
                  row.xdot_min);
    std::cout << head << cell(row.r1) << "  " << cell(row.a_ps) << "\n";
  }
  auto largest = [&](double err, double p, int n, const char* what) {
    if (n == 0) return std::string("n/a (no ") + what + ")";
    return Fixed(err, 5) + " at " + param + " = " + Fixed(p, 5) + " (" + std::to_string(n) + " " +
           what + ")";
  };
  std::cout << "  largest |error|: seed r1 "
            << largest(c.max_err_r1, c.p_max_err_r1, c.r1_applies, "points") << "; averaging "
            << largest(c.max_err_a_ps, c.p_max_err_a_ps, c.a_ps_applies, "pure-slip points")
            << ", n/a on stick-slip orbits\n"
            << "  seed's displacement bound holds at " << c.bound_holds << " points, violated at "
            << c.bound_fails << "\n";
  for (const auto& s : c.special)
    std::cout << "  " << s.label << ": computed " << Fixed(s.computed, 6) << ", " << s.estimate
              << " = " << Fixed(s.estimated, 6) << " (error " << Fixed(s.estimated - s.computed, 6)
              << ")\n";
}

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
    col[0].values.push_back(pt.x_min * s.L);
    col[1].values.push_back(pt.x_max * s.L);
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
ss::ContinuationOptions Configure(const cli::Arguments& args, ss::Params* base) {
  ss::ContinuationOptions opts;
  // With physical inputs, --param belt_speed (damping, speed_m, ...) runs in
  // physical units: its dimensionless parameter is continued over the range
  // converted by the seed's scaling.
  const std::optional<cli::Scales> scales = cli::ScalesFromArguments(args);
  const std::string asked = args.Text("param", "v");
  const auto axis = cli::AxisOf(asked, scales.value_or(cli::Scales()));
  const bool physical_param = axis && asked == axis->physical;
  if (physical_param && !scales)
    throw cli::UsageError("--param " + asked + " is a physical input: give the physical model " +
                          "(--mass --damping --stiffness --belt_speed ...), or use --param " +
                          axis->dimensionless);
  const double to_param = physical_param ? axis->factor : 1.0;  // dimensionless per given
  opts.param = physical_param ? axis->dimensionless : asked;
  // Each parameter's own default range (v 0.05 -> 0.5, beta 0.01 -> 0.3, ...).
  ss::ParameterRange range{0.05, 0.5};
  if (ss::IsParameterName(opts.param))
    range = ss::DefaultRange(cli::UncheckedModelFromArguments(args), opts.param);
  opts.from = args.Number("from", range.from / to_param) * to_param;
  *base = cli::ModelFromArguments(args, opts.param, opts.from);
  opts.orbit.flow = cli::FlowOptionsFromArguments(args);
  opts.to = args.Number("to", range.to / to_param) * to_param;
  opts.max_step = args.Number("max_step", opts.max_step);
  opts.stick_slip_floquet = args.Flag("floquet");
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

// Ends the process at once, with the worker thread still inside the library:
// no destructor may run under it. stdout is checked first, as RunApp does.
[[noreturn]] void ExitLeavingWorker(int code) {
  try {
    cli::CheckStdout();
  } catch (const std::exception& e) {
    cli::PrintError(kProg, e.what());
    code = 1;
  }
  std::cerr.flush();
  std::_Exit(code);
}

void PrintSummary(const ss::ContinuationResult& r, const ss::ContinuationOptions& opts,
                  const std::string& model, double seconds) {
  int counts[3] = {0, 0, 0};
  for (const auto& pt : r.points) ++counts[static_cast<int>(pt.kind)];
  std::cout << kProg << ": " << opts.param << " from " << opts.from << " to " << opts.to << "; "
            << model << "\n"
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
  std::cout << "special points:\n";
  if (r.special.empty()) std::cout << "  none\n";
  for (const auto& s : r.special) {
    std::cout << "  " << ss::SpecialLabel(s.kind) << "  " << opts.param << " = " << Fixed(s.p, 12)
              << "  period " << Fixed(s.period, 6) << "  x in [" << Fixed(s.x_min, 6) << ", "
              << Fixed(s.x_max, 6) << "]  " << s.description << "\n";
  }
}

// How the files were made: tool, command, model, range, tolerances, and
// with physical inputs the scales (then BranchTable adds the status).
cli::Metadata FileMetadata(const std::string& command, const ss::Params& base,
                           const ss::ContinuationOptions& opts,
                           const std::optional<cli::Scales>& scales) {
  cli::Metadata meta = cli::RunMetadata(kProg, command, base, opts.orbit.flow, opts.param);
  meta.insert(meta.end(), {{"continued", opts.param},
                           {"from", ss::FormatNumber(opts.from)},
                           {"to", ss::FormatNumber(opts.to)},
                           {"max_step", ss::FormatNumber(opts.max_step)},
                           {"newton_tol", ss::FormatNumber(opts.orbit.EffectiveNewtonTol())},
                           {"locate_tol", ss::FormatNumber(opts.locate_tol)}});
  if (scales) AddScales(*scales, opts.param, meta);
  return meta;
}

// What Outputs writes besides the result: the metadata and the scales (if physical).
struct Provenance {
  cli::Metadata meta;
  std::optional<cli::Scales> scales;
};

int Outputs(cli::OutputSet& out, const ss::ContinuationResult& r, const ss::Params& base,
            const ss::ContinuationOptions& opts, const Provenance& prov, cli::RunControl& run,
            bool estimates, bool plots);

int Main(int argc, char** argv) {
  const po::options_description desc = cli::AppDescription(AppOptions());
  const cli::Arguments args = cli::ParseArguments(argc, argv, desc, "continue");
  if (cli::HelpOrVersion(std::cout, args, kProg, "ss_continue [--study FILE] [options]", desc,
                         kNotes))
    return 0;
  ss::Params base;
  const ss::ContinuationOptions opts = Configure(args, &base);
  Provenance prov;
  prov.scales = cli::ScalesFromArguments(args);
  prov.meta = FileMetadata(cli::CommandLine(argc, argv), base, opts, prov.scales);
  const double max_time = args.Number("max_time", 0);
  if (max_time < 0)
    throw cli::UsageError("invalid value '" + args.Text("max_time") + "' for " +
                          args.Source("max_time") + ": must be >= 0");
  const bool estimates = !args.Flag("no_estimates"), plots = !args.Flag("no_plots");
  std::vector<std::string> names = {"branch.tsv", "special_points.tsv", "bifurcation.gp"};
  const std::vector<std::string> all_figures = ss::BifurcationFigures(true);
  names.insert(names.end(), all_figures.begin(), all_figures.end());
  cli::OutputSet out(args.Text("out", "plots"), names,
                     args.Given("out") ? args.Source("out") : "--out", kProg);

  cli::RunControl run(kProg, max_time);
  bool abandoned = false;
  const ss::ContinuationResult r = cli::RunContinuation(base, opts, run, &abandoned);
  int code = 1;
  try {
    code = Outputs(out, r, base, opts, prov, run, estimates, plots);
  } catch (const std::exception& e) {
    if (!abandoned) throw;
    code = cli::ReportError(kProg, e);
  }
  if (abandoned) {
    out.Discard();
    ExitLeavingWorker(code);
  }
  return code;
}

// Writes the set, draws the figures, prints the summary; returns the exit code.
int Outputs(cli::OutputSet& out, const ss::ContinuationResult& r, const ss::Params& base,
            const ss::ContinuationOptions& opts, const Provenance& prov, cli::RunControl& run,
            bool estimates, bool plots) {
  const std::vector<std::string> all_figures = ss::BifurcationFigures(true);
  const double seconds = run.Elapsed();
  const std::string model = cli::DescribeModel(base, opts.param, opts.from, opts.to);
  ss::EstimateComparison cmp;
  if (estimates && !run.Cancelled()) {
    run.Phase("comparing with the estimates");
    cmp = ss::CompareEstimates(base, opts.param, r);
  }
  // Estimate columns first (the figure script counts on their numbers), then
  // the smallest disturbance and the Newton-stall mark.
  std::vector<ss::ExtraColumn> extra = cmp.columns;
  run.Phase("smallest disturbances");
  for (auto& c : ss::DisturbanceColumns(base, opts.param, r, opts.orbit.flow)) {
    // Cancelled: the columns are kept, without values.
    if (run.Cancelled()) c.values.assign(r.points.size(), ss::kNan);
    extra.push_back(std::move(c));
  }
  ss::ExtraColumn stalled{"newton_stalled", {}};
  for (const auto& pt : r.points) stalled.values.push_back(pt.newton_stalled ? 1 : 0);
  extra.push_back(std::move(stalled));
  std::vector<ss::ExtraColumn> special_extra;
  if (prov.scales) {  // physical copies last
    const auto phys = PhysicalColumns(*prov.scales, opts.param, r.points);
    extra.insert(extra.end(), phys.begin(), phys.end());
    special_extra = PhysicalColumns(*prov.scales, opts.param, r.special);
  }
  run.Phase("writing");
  ss::TsvTable branch = ss::BranchTable(r, opts.param, model, extra);
  branch.PrependMeta(prov.meta);
  ss::TsvTable special = ss::SpecialPointTable(r, opts.param, special_extra);
  special.PrependMeta(prov.meta);
  out.Write("branch.tsv", branch.str());
  out.Write("special_points.tsv", special.str());
  const std::string title = model + (r.partial() ? " (partial)" : "");
  out.Write("bifurcation.gp", ss::BifurcationScript(r, opts.param, title, cmp.applies));
  const std::vector<std::string> figures = ss::BifurcationFigures(cmp.applies);
  ss::GnuplotResult g{ss::GnuplotStatus::kCancelled, "figures not drawn (--no_plots)"};
  if (plots && !run.Cancelled()) {
    run.Phase("plotting");
    g = out.Draw("bifurcation.gp", figures, [&] { return run.Cancelled(); });
  }
  if (g.status == ss::GnuplotStatus::kFailed) {
    cli::PrintError(kProg, g.message + "; nothing replaced in '" + out.dir() + "'");
    return 1;
  }
  // Figures this run did not draw are stale beside its data: removed.
  std::vector<std::string> stale;
  for (const auto& f : all_figures)
    if (!g.ok() || std::find(figures.begin(), figures.end(), f) == figures.end())
      stale.push_back(f);
  out.Commit(stale);

  PrintSummary(r, opts, model, seconds);
  std::cout << "wrote " << out.dir() << "/branch.tsv, special_points.tsv, bifurcation.gp"
            << (g.ok() ? " and the PNGs" : "") << "\n";
  if (cmp.applies && !cmp.rows.empty()) PrintComparison(cmp, opts.param);
  if (r.partial()) {
    cli::PrintError(kProg, "partial branch written (" +
                               std::string(ss::ContinuationStatusName(r.status)) +
                               "): " + r.message);
    return 1;
  }
  if (run.Cancelled()) {
    cli::PrintError(kProg, run.Reason() + " while " + run.phase() + ": the branch is whole" +
                               (g.ok() ? "" : ", figures not drawn"));
    return 1;
  }
  if (g.status == ss::GnuplotStatus::kMissing) {
    cli::PrintError(kProg, g.message + "; data files written, no figures");
    return 3;
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return cli::RunApp(kProg, [&] { return Main(argc, argv); });
}
