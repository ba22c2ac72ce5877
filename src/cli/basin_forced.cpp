// ss_basin's forced path (basin_forced.hpp).
#include "cli/basin_forced.hpp"

#include <cmath>
#include <iostream>

#include "cli/about.hpp"
#include "cli/app.hpp"
#include "stickslip/basin/basin.hpp"
#include "stickslip/io/attractor_report.hpp"

namespace stickslip::cli {

po::options_description ForcedBasinOptionGroup() {
  po::options_description d("Basins of the forced oscillator (with --force; section [basin])");
  d.add_options()(
      "transient", Value()->value_name("P"),
      "forced: forcing periods before a start is classified, in [0, 1e6] (default 300)")(
      "keep", Value()->value_name("K"),
      "forced: forcing periods that classify it (period and exponent), in [8, 1e6] (default 64)")(
      "max_period", Value()->value_name("M"),
      "forced: the longest period looked for, in forcing periods, in [1, keep/2] (default 16)")(
      "threads", Value()->value_name("N"),
      "forced: worker threads, in [1, 1024], capped by the machine's hardware threads (default: "
      "all of them)");
  return d;
}

namespace {

long Count(const Arguments& args, const char* name, long fallback, long lo, long hi) {
  const long n = args.Integer(name, fallback);
  if (n < lo || n > hi)
    throw UsageError("invalid value '" + args.Text(name) + "' for " + args.Source(name) +
                     ": must be in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
  return n;
}

stickslip::AttractorOptions Configure(const Arguments& args, ForcedParams* p, FlowOptions* flow) {
  for (const char* phys : {"mass", "damping", "stiffness", "belt_speed"})
    if (args.Given(phys))
      throw UsageError(args.Source(phys) + ": the forced oscillator takes dimensionless inputs");
  if (args.Given("param")) throw UsageError(args.Source("param") + ": not with --force");
  p->base = UncheckedModelFromArguments(args);
  p->force = args.Number("force", 0);
  p->omega = args.Number("omega", 1);
  const std::string e = ValidationError(*p);
  if (!e.empty()) throw UsageError("invalid forced model: " + e);
  stickslip::AttractorOptions o;
  StartSlice& g = o.slice;
  g.n[0] = static_cast<int>(Count(args, "nx", 41, 1, 2000));
  g.n[1] = static_cast<int>(Count(args, "ny", 41, 1, 2000));
  const char* box[] = {"x_min", "x_max", "xdot_min", "xdot_max"};
  int given = 0;
  for (const char* k : box) given += args.Given(k);
  if (given != 0 && given != 4)
    throw UsageError("--x_min --x_max --xdot_min --xdot_max: give all four or none");
  g.lo[0] = args.Number("x_min", g.lo[0]), g.hi[0] = args.Number("x_max", g.hi[0]);
  g.lo[1] = args.Number("xdot_min", g.lo[1]), g.hi[1] = args.Number("xdot_max", g.hi[1]);
  CheckBoxCorners(args);
  if (!(g.lo[0] < g.hi[0])) throw UsageError("--x_min must be < --x_max");
  if (!(g.lo[1] < g.hi[1])) throw UsageError("--xdot_min must be < --xdot_max");
  o.iterate.transient = static_cast<int>(Count(args, "transient", 300, 0, 1000000));
  o.iterate.keep = static_cast<int>(Count(args, "keep", 64, 8, 1000000));
  o.iterate.align = std::min(o.iterate.align, o.iterate.transient);
  o.iterate.batches = std::min(o.iterate.batches, o.iterate.keep);
  o.max_period = static_cast<int>(Count(args, "max_period", 16, 1, o.iterate.keep / 2));
  o.threads = args.Given("threads") ? static_cast<int>(Count(args, "threads", 0, 1, 1024)) : 0;
  o.max_amplitude = args.Number("max_amplitude", 50);
  if (!(o.max_amplitude > 0)) throw UsageError(args.Source("max_amplitude") + " must be > 0");
  *flow = FlowOptionsFromArguments(args);
  if (!args.Given("rtol")) flow->rtol = o.iterate.flow.rtol;
  if (!args.Given("atol")) flow->atol = o.iterate.flow.atol;
  o.iterate.flow.rtol = flow->rtol, o.iterate.flow.atol = flow->atol;
  o.iterate.flow.max_steps = flow->max_steps;
  o.iterate.flow.integrator = flow->integrator, o.iterate.flow.method = flow->method;
  const std::string oe = o.ValidationError(ForcedModel(*p));
  if (!oe.empty()) throw UsageError(oe);
  return o;
}

}  // namespace

void CheckBoxCorners(const Arguments& args) {
  constexpr double kMax = stickslip::AttractorOptions::kMaxCorner;
  static_assert(kMax == BasinOptions::kMaxCorner, "one bound for both paths");
  for (const char* k : {"x_min", "x_max", "xdot_min", "xdot_max"})
    if (args.Given(k) && !(std::abs(args.Number(k, 0)) <= kMax))
      throw UsageError(args.Source(k) + " = " + args.Text(k) + ": the grid box must lie within +-" +
                       FormatNumber(kMax));
}

int RunForcedBasin(const Arguments& args, const std::string& prog, const std::string& command) {
  ForcedParams p;
  FlowOptions flow;
  stickslip::AttractorOptions o = Configure(args, &p, &flow);
  const FigureFormat format = FigureFormatOf(args);
  const std::string figure = FigureFile("basins_forced", format);
  AppRun app(prog, args, "plots/basin",
             {"basins_forced.tsv", "attractors.tsv", "basins_forced.gp", figure});
  RunControl& run = app.run();
  run.Phase("classifying starts");
  o.cancelled = [&run] { return run.Cancelled(); };
  o.progress = [&run](int done, int total) {
    if (run.ProgressDue())
      run.Progress(std::to_string(done) + " of " + std::to_string(total) + " starts",
                   static_cast<double>(done) / total, done, "starts");
  };
  const ForcedModel model(p);
  const AttractorBasins b = ClassifyAttractors(model, o);
  if (!b.error.empty()) {  // nothing classified: nothing written
    std::cerr << prog << ": " << b.error << "\n";
    return kExitFailed;
  }
  const std::string desc =
      DescribeModel(p.base) + " force=" + FormatNumber(p.force) + " omega=" + FormatNumber(p.omega);
  Metadata meta = RunMetadata(prog, command, p.base, flow);
  meta.insert(meta.end(), {{"model", "forced oscillator, " + desc},
                           {"section", "forcing phase 0 (cos Omega t = 1)"},
                           {"transient", std::to_string(o.iterate.transient) + " forcing periods"},
                           {"keep", std::to_string(o.iterate.keep) + " forcing periods"},
                           {"undecided_run_on",
                            "x4 while undecided, up to " + std::to_string(o.max_keep) + " periods"},
                           {"status", b.cancelled ? "partial (" + run.Reason() + ")"
                                                  : std::to_string(b.failed) + " starts failed"}});
  TsvTable starts = AttractorStartTable(model, b, o.slice), attractors = AttractorTable(model, b);
  starts.PrependMeta(meta);
  attractors.PrependMeta(meta);
  run.Phase("writing");
  app.out().Write("basins_forced.tsv", starts.str());
  app.out().Write("attractors.tsv", attractors.str());
  app.out().Write(
      "basins_forced.gp",
      AttractorScript(model, b, o.slice, AttractorFigure(),
                      FigureTitle(desc, {}) + (b.cancelled ? " (partial)" : ""), format));
  if (!app.Finish("basins_forced.gp", {figure}, {figure})) return kExitFailed;
  std::cout << prog << ": forced oscillator, " << desc << "\n"
            << starts.rows() << " starts in " << FormatNumber(std::round(b.seconds * 1e3) / 1e3)
            << " s\n";
  for (size_t i = 0; i < b.attractors.size(); ++i)
    std::cout << "attractor " << i << ": " << AttractorLabel(b.attractors[i]) << ", "
              << b.attractors[i].starts << " starts\n";
  std::cout << "wrote " << app.out().dir() << "/basins_forced.tsv, attractors.tsv, basins_forced.gp"
            << (app.gnuplot().ok() ? " and " + figure : std::string()) << "\n";
  std::string partial;
  if (b.cancelled) partial = "partial basins written: " + run.Reason();
  if (partial.empty() && b.failed > 0)
    partial = std::to_string(b.failed) + " starts failed (see the # failed: lines)";
  return app.ExitCode(partial);
}

}  // namespace stickslip::cli
