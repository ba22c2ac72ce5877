// ss_basin: basins of attraction at one parameter point: a grid of starts
// classified by the exact flow (steady sliding, stick-slip, pure slip,
// undecided), every periodic orbit with its stability, and the smallest
// disturbance that tips steady sliding into oscillation.
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
#include "cli/basin_curve.hpp"
#include "cli/output.hpp"
#include "cli/study.hpp"
#include "stickslip/basin_report.hpp"

namespace ss = stickslip;
namespace cli = stickslip::cli;
namespace po = boost::program_options;

namespace {

constexpr const char* kProg = "ss_basin";
constexpr const char* kNotes =
    "Outputs in --out (each written whole or not at all): basins.tsv (one row per start:\n"
    "x, xdot, fate = steady-sliding / stick-slip / pure-slip / undecided, t_settle; `# key:\n"
    "value` lines list the periodic orbits and the smallest disturbance), orbits.tsv (each\n"
    "periodic orbit sampled), basins.gp and basins.png.\n"
    "A start is undecided if it has not settled by --t_cap.\n"
    "Study files: model and solver keys at top level, this app's keys in [basin].\n"
    "Exit status: 0 done; 1 numerical failure, interruption (SIGINT/SIGTERM) or time\n"
    "limit: the starts so far are written, marked partial; 2 bad input (nothing written).\n"
    "Basin stability (exact): the fraction of the box reaching each attractor, from the\n"
    "areas the unstable pure-slip orbits enclose in it; printed as `basin stability\n"
    "<attractor> <fraction>` and written to orbits.tsv (comment lines and the column\n"
    "basin_stability). With --param the curve of it against that parameter in the given\n"
    "box: basin_stability.tsv, basin_stability.gp and basin_stability.png, no grid.\n"
    "Example: ss_basin --study studies/stribeck_basin.ini\n"
    "         ss_basin --study studies/stribeck_basin_stability.ini";

volatile std::sig_atomic_t g_signal = 0;
void OnSignal(int sig) { g_signal = sig; }

po::options_description AppOptions() {
  po::options_description d("Basins (study section [basin])");
  d.add_options()("nx", cli::Value()->value_name("N"), "starts along x (default 41)")(
      "ny", cli::Value()->value_name("N"), "starts along x' (default 41)")(
      "x_min", cli::Value()->value_name("X"),
      "grid box; give all four of x_min x_max xdot_min xdot_max, or none (default: the "
      "periodic orbits' box widened by a quarter)")("x_max", cli::Value()->value_name("X"), "")(
      "xdot_min", cli::Value()->value_name("Y"), "")("xdot_max", cli::Value()->value_name("Y"), "")(
      "t_cap", cli::Value()->value_name("T"),
      "time after which a start is undecided (default 2000)")(
      "out", cli::Value()->value_name("DIR"), "output directory (default plots/basin)")(
      "max_time", cli::Value()->value_name("S"),
      "wall-time limit in seconds; the starts so far are kept (default none)")(
      "no_plots", po::bool_switch(), "write the TSV files and the script, but do not run gnuplot");
  cli::AddBasinCurveOptions(d);
  return d;
}

ss::BasinOptions OptionsFromArguments(const cli::Arguments& args) {
  ss::BasinOptions o;
  o.scan.orbit.flow = cli::FlowOptionsFromArguments(args);
  auto count = [&](const char* name) {
    const long n = args.Integer(name, 41);
    if (n < 1 || n > 2000)
      throw cli::UsageError("invalid value '" + args.Text(name) + "' for " + args.Source(name) +
                            ": must be in [1, 2000]");
    return static_cast<int>(n);
  };
  o.nx = count("nx");
  o.ny = count("ny");
  const char* box[] = {"x_min", "x_max", "xdot_min", "xdot_max"};
  int given = 0;
  for (const char* k : box) given += args.Given(k);
  if (given != 0 && given != 4)
    throw cli::UsageError("--x_min --x_max --xdot_min --xdot_max: give all four or none");
  if (given == 4) {
    o.auto_range = false;
    o.x_lo = args.Number("x_min", 0), o.x_hi = args.Number("x_max", 0);
    o.xdot_lo = args.Number("xdot_min", 0), o.xdot_hi = args.Number("xdot_max", 0);
    if (!(o.x_lo < o.x_hi))
      throw cli::UsageError("--x_min = " + args.Text("x_min") +
                            " must be < --x_max = " + args.Text("x_max"));
    if (!(o.xdot_lo < o.xdot_hi))
      throw cli::UsageError("--xdot_min = " + args.Text("xdot_min") +
                            " must be < --xdot_max = " + args.Text("xdot_max"));
  }
  o.t_cap = args.Number("t_cap", o.t_cap);
  if (!(o.t_cap > 0))
    throw cli::UsageError("invalid value '" + args.Text("t_cap") + "' for " + args.Source("t_cap") +
                          ": must be > 0");
  const std::string err = o.ValidationError();
  if (!err.empty()) throw cli::UsageError(err);
  return o;
}

// Renders basins.png under a temporary name, then renames it.
bool Plot(const std::string& dir) {
  const std::string wrapper = dir + "/.basins.part.gp";
  ss::WriteFileAtomically(wrapper, "suffix = '.part'\nload 'basins.gp'\n");
  std::string gp_error;
  bool ok = ss::RunGnuplot(wrapper, dir, &gp_error);
  std::remove(wrapper.c_str());
  const std::string final_name = dir + "/basins.png", part = final_name + ".part";
  if (ok && std::rename(part.c_str(), final_name.c_str()) != 0) ok = false;
  std::remove(part.c_str());
  if (!ok) cli::PrintError(kProg, "gnuplot failed: " + gp_error);
  return ok;
}

int Main(int argc, char** argv) {
  const po::options_description desc = cli::AppDescription(AppOptions());
  const cli::Arguments args = cli::ParseArguments(argc, argv, desc, "basin");
  if (cli::HelpOrVersion(std::cout, args, kProg, "ss_basin [--study FILE] [options]", desc, kNotes))
    return 0;
  const ss::Params p = cli::ModelFromArguments(args);
  ss::BasinOptions opts = OptionsFromArguments(args);
  const double max_time = args.Number("max_time", 0);
  if (max_time < 0)
    throw cli::UsageError("invalid value '" + args.Text("max_time") + "' for " +
                          args.Source("max_time") + ": must be >= 0");
  if (args.Given("param"))  // the curve of basin stability instead of the grid
    return cli::RunBasinStabilityCurve(kProg, args, p, opts, max_time,
                                       cli::RunMetadata(kProg, cli::CommandLine(argc, argv), p,
                                                        opts.scan.orbit.flow, args.Text("param")));
  const std::string dir = cli::CheckedOutputDir(args.Text("out", "plots/basin"),
                                                args.Given("out") ? args.Source("out") : "--out");
  const ss::Model model(p);

  std::signal(SIGINT, OnSignal);
  std::signal(SIGTERM, OnSignal);
  const auto start = std::chrono::steady_clock::now();
  auto elapsed = [&] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };
  opts.cancelled = [&] { return g_signal != 0 || (max_time > 0 && elapsed() > max_time); };
  double next_report = 1.0;
  opts.progress = [&](int done, int total) {
    if (elapsed() < next_report) return;
    next_report = elapsed() + 1.0;
    std::cerr << kProg << ": " << done << " of " << total << " starts after "
              << static_cast<int>(elapsed()) << " s\n";
  };
  const ss::FlowOptions& flow = opts.scan.orbit.flow;
  const ss::BasinResult r = ss::ClassifyBasins(model, opts);
  const double seconds = elapsed();
  // Exact basin stability: the basins' areas in the grid's box.
  ss::BasinStability stability;
  if (r.orbits.ok())
    stability =
        ss::ExactBasinStability(model, r.orbits, {r.x_lo, r.x_hi, r.xdot_lo, r.xdot_hi}, flow);

  // The orbits' curves and the smallest disturbances (cheap: one period each).
  std::vector<ss::OrbitCurveRows> curves;
  std::vector<ss::Disturbance> dist;
  if (r.orbits.has_stick_slip)
    curves.push_back({"stick-slip", true, ss::OrbitCurve(model, r.orbits.stick_slip, flow, 800)});
  for (const ss::Orbit& o : r.orbits.pure_slip) {
    curves.push_back({"pure-slip", o.stable, ss::OrbitCurve(model, o, flow, 800)});
    dist.push_back(ss::SmallestDisturbance(model, o, flow));
  }
  const std::string desc_model = cli::DescribeModel(p);
  // Every file starts with the tool, the command, the model and the integrator.
  const cli::Metadata meta = cli::RunMetadata(kProg, cli::CommandLine(argc, argv), p, flow);
  auto text = [&](ss::TsvTable t) {
    t.PrependMeta(meta);
    return t.str();
  };
  ss::WriteFileAtomically(dir + "/basins.tsv", text(ss::BasinTable(r, desc_model, dist)));
  ss::WriteFileAtomically(dir + "/orbits.tsv",
                          text(ss::OrbitTable(curves, r.orbits.ok() ? &stability : nullptr)));
  ss::WriteFileAtomically(
      dir + "/basins.gp",
      ss::BasinScript(r, model, curves, desc_model + (r.partial() ? " (partial)" : "")));
  const bool plots_ok = args.Flag("no_plots") || Plot(dir);

  std::cout << kProg << ": " << desc_model << "\n"
            << "steady sliding x = " << r.orbits.steady.x
            << (r.orbits.steady.stable() ? " (stable)" : " (unstable)") << "\n";
  if (r.orbits.has_stick_slip)
    std::cout << "stick-slip orbit: period " << r.orbits.stick_slip.period << " (stable)\n";
  for (size_t i = 0; i < r.orbits.pure_slip.size(); ++i) {
    const ss::Orbit& o = r.orbits.pure_slip[i];
    std::cout << "pure-slip orbit: period " << o.period << ", multiplier " << o.multiplier
              << (o.stable ? " (stable)" : " (unstable)");
    if (!o.stable)
      std::cout << "; smallest disturbance: x " << dist[i].x << ", x' " << dist[i].xdot
                << ", energy " << dist[i].energy;
    std::cout << "\n";
  }
  std::cout << r.starts.size() << " starts in " << static_cast<int>(seconds * 1e3) << " ms:";
  for (int f = 0; f < 4; ++f)
    std::cout << " " << r.count[f] << " " << ss::FateName(static_cast<ss::Fate>(f));
  std::cout << "\n";
  for (const std::string& line : ss::BasinStabilityLines(stability)) std::cout << line << "\n";
  std::cout << "wrote " << dir << "/basins.tsv, orbits.tsv, basins.gp"
            << (args.Flag("no_plots") || !plots_ok ? "" : " and basins.png") << "\n";
  if (r.partial()) {
    const std::string why = g_signal ? std::string("interrupted by signal ") +
                                           std::to_string(static_cast<int>(g_signal))
                                     : r.message;
    cli::PrintError(kProg, "partial basins written (" + std::string(ss::BasinStatusName(r.status)) +
                               "): " + why);
    return 1;
  }
  return plots_ok ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  return cli::RunApp(kProg, [&] { return Main(argc, argv); });
}
