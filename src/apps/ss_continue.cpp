// ss_continue: the bifurcation diagram of a study in one parameter: branches
// of stick-slip and pure-slip orbits and of steady sliding, their special
// points (GR, HB, LP), TSV files and gnuplot figures in --out.
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <string>

#include "cli/about.hpp"
#include "cli/physical.hpp"
#include "cli/study.hpp"
#include "stickslip/branch_report.hpp"
#include "stickslip/comparison.hpp"
#include "stickslip/continuation.hpp"
#include "stickslip/report.hpp"

namespace ss = stickslip;
namespace cli = stickslip::cli;
namespace po = boost::program_options;

namespace {

constexpr const char* kProg = "ss_continue";
constexpr const char* kNotes =
    "Outputs in --out (each written whole or not at all): branch.tsv (one row per point;\n"
    "kind stick-slip / pure-slip / equilibrium; multiplier = nontrivial Floquet multiplier,\n"
    "for the equilibrium the largest real part of its eigenvalues), special_points.tsv\n"
    "(GR grazing-sliding, HB Hopf, LP fold), bifurcation.gp and its figures\n"
    "bifurcation_x.png, bifurcation_xdot.png, period.png, multiplier.png.\n"
    "Study files: model and solver keys at top level, this app's keys in [continue].\n"
    "Exit status: 0 done; 1 numerical failure, interruption (SIGINT/SIGTERM) or time\n"
    "limit: the branch so far is written, marked partial; 2 bad input (nothing written).\n"
    "Example: ss_continue --study studies/seed.ini --param v --from 0.05 --to 0.5";

volatile std::sig_atomic_t g_signal = 0;
void OnSignal(int sig) { g_signal = sig; }

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

// --out must be a writable directory; it is created if only it is missing.
std::string CheckOutDir(const cli::Arguments& args) {
  const std::string dir = args.Text("out", "plots");
  const std::string src = args.Given("out") ? args.Source("out") : "--out";
  auto bad = [&](const std::string& why) {
    return cli::UsageError("invalid value '" + dir + "' for " + src + ": " + why);
  };
  if (dir.empty()) throw bad("empty");
  struct stat st;
  if (::stat(dir.c_str(), &st) != 0) {
    if (errno != ENOENT || ::mkdir(dir.c_str(), 0777) != 0)
      throw bad(std::string("cannot create it: ") + std::strerror(errno));
  } else if (!S_ISDIR(st.st_mode)) {
    throw bad("not a directory");
  }
  if (::access(dir.c_str(), W_OK | X_OK) != 0)
    throw bad(std::string("not writable: ") + std::strerror(errno));
  return dir;
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

int Main(int argc, char** argv) {
  const po::options_description desc = cli::AppDescription(AppOptions());
  const cli::Arguments args = cli::ParseArguments(argc, argv, desc, "continue");
  if (cli::HelpOrVersion(std::cout, args, kProg, "ss_continue [--study FILE] [options]", desc,
                         kNotes))
    return 0;
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
  const ss::Params base = cli::ModelFromArguments(args, opts.param, opts.from);
  opts.orbit.flow = cli::FlowOptionsFromArguments(args);
  opts.to = args.Number("to", range.to / to_param) * to_param;
  opts.max_step = args.Number("max_step", opts.max_step);
  opts.stick_slip_floquet = args.Flag("floquet");
  const double max_time = args.Number("max_time", 0);
  if (max_time < 0)
    throw cli::UsageError("invalid value '" + args.Text("max_time") + "' for " +
                          args.Source("max_time") + ": must be >= 0");
  const std::string err = opts.ValidationError(base);
  if (!err.empty()) {
    const bool is_param = err.find("parameter") != std::string::npos;
    throw cli::UsageError(std::string(is_param ? "--param: " : "") + err);
  }
  const std::string dir = CheckOutDir(args);

  std::signal(SIGINT, OnSignal);
  std::signal(SIGTERM, OnSignal);
  const auto start = std::chrono::steady_clock::now();
  auto elapsed = [&] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };
  opts.cancelled = [&] { return g_signal != 0 || (max_time > 0 && elapsed() > max_time); };
  double next_report = 1.0;
  opts.progress = [&](const ss::BranchPoint& pt) {
    if (elapsed() < next_report) return;
    next_report = elapsed() + 1.0;
    std::cerr << kProg << ": " << opts.param << " = " << pt.p << " (" << ss::PointKindName(pt.kind)
              << ") after " << Fixed(elapsed(), 1) << " s\n";
  };

  const ss::ContinuationResult r = ss::Continue(base, opts);
  const double seconds = elapsed();

  const std::string model = cli::DescribeModel(base);
  ss::EstimateComparison cmp;
  if (!args.Flag("no_estimates")) cmp = ss::CompareEstimates(base, opts.param, r);
  // How the files were made: tool, command, model, range, tolerances (then the status).
  cli::Metadata meta =
      cli::RunMetadata(kProg, cli::CommandLine(argc, argv), base, opts.orbit.flow, opts.param);
  meta.insert(meta.end(), {{"continued", opts.param},
                           {"from", ss::FormatNumber(opts.from)},
                           {"to", ss::FormatNumber(opts.to)},
                           {"max_step", ss::FormatNumber(opts.max_step)},
                           {"newton_tol", ss::FormatNumber(opts.orbit.EffectiveNewtonTol())},
                           {"locate_tol", ss::FormatNumber(opts.locate_tol)}});
  std::vector<ss::ExtraColumn> columns = cmp.columns, special_columns;
  if (scales) {
    AddScales(*scales, opts.param, meta);
    const auto phys = PhysicalColumns(*scales, opts.param, r.points);
    columns.insert(columns.end(), phys.begin(), phys.end());
    special_columns = PhysicalColumns(*scales, opts.param, r.special);
  }
  ss::TsvTable branch = ss::BranchTable(r, opts.param, model, columns);
  branch.PrependMeta(meta);
  ss::TsvTable special = ss::SpecialPointTable(r, opts.param, special_columns);
  special.PrependMeta(meta);
  ss::WriteFileAtomically(dir + "/branch.tsv", branch.str());
  ss::WriteFileAtomically(dir + "/special_points.tsv", special.str());
  const std::string title = model + (r.partial() ? " (partial)" : "");
  ss::WriteFileAtomically(dir + "/bifurcation.gp",
                          ss::BifurcationScript(r, opts.param, title, cmp.applies));
  bool plots_ok = true;
  if (!args.Flag("no_plots")) {
    // Render to temporary names, then rename: a reader never sees half a PNG.
    const std::string wrapper = dir + "/.bifurcation.part.gp";
    ss::WriteFileAtomically(wrapper, "suffix = '.part'\nload 'bifurcation.gp'\n");
    std::string gp_error;
    plots_ok = ss::RunGnuplot(wrapper, dir, &gp_error);
    std::remove(wrapper.c_str());
    for (const std::string& png : ss::BifurcationFigures(cmp.applies)) {
      const std::string final_name = dir + "/" + png, part = final_name + ".part";
      if (plots_ok && std::rename(part.c_str(), final_name.c_str()) != 0) plots_ok = false;
      std::remove(part.c_str());
    }
    if (!plots_ok) cli::PrintError(kProg, "gnuplot failed: " + gp_error);
  }

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
  std::cout << "special points:\n";
  if (r.special.empty()) std::cout << "  none\n";
  for (const auto& s : r.special) {
    std::cout << "  " << ss::SpecialLabel(s.kind) << "  " << opts.param << " = " << Fixed(s.p, 12)
              << "  period " << Fixed(s.period, 6) << "  x in [" << Fixed(s.x_min, 6) << ", "
              << Fixed(s.x_max, 6) << "]  " << s.description << "\n";
  }
  std::cout << "wrote " << dir << "/branch.tsv, special_points.tsv, bifurcation.gp"
            << (args.Flag("no_plots") || !plots_ok ? "" : " and the PNGs") << "\n";
  if (cmp.applies && !cmp.rows.empty()) PrintComparison(cmp, opts.param);
  if (r.partial()) {
    const std::string why = g_signal ? std::string("interrupted by signal ") +
                                           std::to_string(static_cast<int>(g_signal))
                                     : r.message;
    cli::PrintError(kProg, "partial branch written (" +
                               std::string(ss::ContinuationStatusName(r.status)) + "): " + why);
    return 1;
  }
  return plots_ok ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  return cli::RunApp(kProg, [&] { return Main(argc, argv); });
}
