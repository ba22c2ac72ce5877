// ss_basin: basins of attraction at one parameter point: a grid of starts
// classified by the exact flow (steady sliding, stick-slip, pure slip,
// undecided), every periodic orbit with its stability, and the smallest
// disturbance that tips steady sliding into oscillation.
#include <iostream>
#include <string>
#include <vector>

#include "cli/about.hpp"
#include "cli/app.hpp"
#include "cli/basin_curve.hpp"
#include "cli/basin_section.hpp"
#include "cli/physical.hpp"
#include "cli/study.hpp"
#include "cli/system_choice.hpp"
#include "stickslip/io/basin_report.hpp"

namespace ss = stickslip;
namespace cli = stickslip::cli;
namespace po = boost::program_options;

namespace {

constexpr const char* kProg = "ss_basin";
constexpr const char* kNotes =
    "Outputs in --out (each written whole or not at all): basins.tsv (one row per start:\n"
    "x, xdot, fate = steady-sliding / stick-slip / pure-slip / undecided, t_settle; `# key:\n"
    "value` lines list the periodic orbits and the smallest disturbance), orbits.tsv (each\n"
    "periodic orbit sampled), basins.gp and basins.png (.pdf, .svg with --format).\n"
    "A start is undecided if it has not settled by --t_cap.\n"
    "Basin stability (exact): the fraction of the box reaching each attractor, from the\n"
    "areas the unstable pure-slip orbits enclose in it; printed as `basin stability\n"
    "<attractor> <fraction>` and written to orbits.tsv (comment lines and the column\n"
    "basin_stability). With --param the curve of it against that parameter in the given\n"
    "box: basin_stability.tsv, basin_stability.gp and basin_stability.png, no grid.\n"
    "With --force A --omega W or --system NAME: basins on a Poincare section instead\n"
    "(the stroboscopic one, or the returns to x1' = 0 falling), each start classified as\n"
    "periodic (m, sticks), rest, chaotic, unbounded, contact-lost (a contact opens),\n"
    "settling (still spiralling slowly one way) or undecided: basins_forced.tsv (with\n"
    "--system basins.tsv) per start, attractors.tsv per attractor, and the figure.\n"
    "The files are written as one set (docs/reliability.md).\n"
    "Study files: model and solver keys at top level, this app's keys in [basin].\n"
    "An interrupted or failed run writes the starts so far, marked partial.\n";
constexpr const char* kExample =
    "\nExample: ss_basin --study studies/stribeck_basin.ini\n"
    "         ss_basin --study studies/stribeck_basin_stability.ini";

po::options_description AppOptions() {
  po::options_description d("Basins (study section [basin])");
  d.add_options()("nx", cli::Value()->value_name("N"), "starts along x (default 41)")(
      "ny", cli::Value()->value_name("N"), "starts along x' (default 41)")(
      "x_min", cli::Value()->value_name("X"),
      "grid box; give all four of x_min x_max xdot_min xdot_max, or none (default: the "
      "periodic orbits' box widened by a quarter)")("x_max", cli::Value()->value_name("X"), "")(
      "xdot_min", cli::Value()->value_name("Y"), "")("xdot_max", cli::Value()->value_name("Y"), "")(
      "t_cap", cli::Value()->value_name("T"),
      "time after which a start is undecided (default 2000)");
  cli::AddRunOptions(d, "plots/basin",
                     "write the TSV files and the script, but do not run gnuplot");
  cli::AddBasinCurveOptions(d);
  d.add(cli::ForcingOptions()).add(cli::SectionBasinOptionGroup());  // basin_section.hpp
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
    cli::CheckBoxCorners(args);
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

// The orbits and basins on stdout.
void PrintSummary(const ss::BasinResult& r, const std::vector<ss::Disturbance>& dist,
                  const ss::BasinStability& stability, const std::string& desc_model,
                  double seconds) {
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
    std::cout << " " << r.count[f] << " " << ss::Name(static_cast<ss::Fate>(f));
  std::cout << "\n";
  for (const std::string& line : ss::BasinStabilityLines(stability)) std::cout << line << "\n";
}

int Main(int argc, char** argv) {
  const po::options_description desc = cli::AppDescription(AppOptions());
  const cli::Arguments args = cli::ParseArguments(argc, argv, desc, "basin");
  if (cli::HelpOrVersion(std::cout, args, kProg, "ss_basin [--study FILE] [options]", desc,
                         std::string(kNotes) + cli::kExitCodeHelp + kExample))
    return 0;
  // The forced oscillator and every other system: basins on a section (basin_section.hpp).
  if (args.Number("force", 0) != 0 || cli::SystemRequested(args))
    return cli::RunSectionBasin(args, kProg, cli::CommandLine(argc, argv));
  cli::RefuseSystem(args, kProg);
  for (const char* o : {"transient", "keep", "max_period", "threads", "slice"})
    if (args.Given(o))
      throw cli::UsageError(args.Source(o) +
                            " needs --force or --system (the belt's basins "
                            "follow each start to --t_cap)");
  if (args.Given("omega"))
    throw cli::UsageError(args.Source("omega") +
                          " needs the forced oscillator: give --force A > 0");
  const ss::Params p = cli::ModelFromArguments(args);
  ss::BasinOptions opts = OptionsFromArguments(args);
  if (args.Given("param"))  // the curve of basin stability instead of the grid
    return cli::RunBasinStabilityCurve(kProg, args, p, opts, args.Number("max_time", 0),
                                       cli::RunMetadata(kProg, cli::CommandLine(argc, argv), p,
                                                        opts.scan.orbit.flow, args.Text("param")));
  const ss::FigureFormat format = cli::FigureFormatOf(args);
  const std::string figure = ss::FigureFile("basins", format);
  cli::AppRun app(kProg, args, "plots/basin", {"basins.tsv", "orbits.tsv", "basins.gp", figure});
  cli::RunControl& run = app.run();
  const ss::Model model(p);

  run.Phase("classifying starts");
  opts.cancelled = [&run] { return run.Cancelled(); };
  opts.progress = [&run](int done, int total) {
    run.Progress(std::to_string(done) + " of " + std::to_string(total) + " starts",
                 static_cast<double>(done) / total, done, "starts");
  };
  const ss::BasinResult r = ss::ClassifyBasins(model, opts);
  const double seconds = run.Elapsed();
  // Exact basin stability: the basins' areas in the grid's box.
  ss::BasinStability stability;
  if (r.orbits.ok())
    stability = ss::ExactBasinStability(model, r.orbits, {r.x_lo, r.x_hi, r.xdot_lo, r.xdot_hi},
                                        opts.scan.orbit.flow);

  // The orbits' curves and the smallest disturbances (cheap: one period each).
  run.Phase("sampling the orbits");
  const ss::FlowOptions& flow = opts.scan.orbit.flow;
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
  run.Phase("writing");
  app.out().Write("basins.tsv", text(ss::BasinTable(r, desc_model, dist)));
  app.out().Write("orbits.tsv", text(ss::OrbitTable(curves, r.orbits.ok() ? &stability : nullptr)));
  app.out().Write("basins.gp",
                  ss::BasinScript(r, model, curves, desc_model + (r.partial() ? " (partial)" : ""),
                                  format, cli::FigureUnitsOf(cli::ScalesFromArguments(args))));
  if (!app.Finish("basins.gp", {figure}, {figure})) return cli::kExitFailed;

  PrintSummary(r, dist, stability, desc_model, seconds);
  std::cout << "wrote " << app.out().dir() << "/basins.tsv, orbits.tsv, basins.gp"
            << (app.gnuplot().ok() ? " and " + figure : std::string()) << "\n";
  std::string partial;
  if (r.partial())
    partial = "partial basins written (" + std::string(ss::Name(r.status)) +
              "): " + (r.status == ss::BasinStatus::kCancelled ? run.Reason() : r.message);
  return app.ExitCode(partial);
}

}  // namespace

int main(int argc, char** argv) {
  return cli::RunApp(kProg, [&] { return Main(argc, argv); });
}
