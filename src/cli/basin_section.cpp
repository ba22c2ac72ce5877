// ss_basin's section path (basin_section.hpp).
#include "cli/basin_section.hpp"

#include <cmath>
#include <iostream>
#include <memory>
#include <sstream>

#include "cli/about.hpp"
#include "cli/app.hpp"
#include "cli/system_choice.hpp"
#include "stickslip/basin/basin.hpp"
#include "stickslip/equilibria/steady_sliding.hpp"
#include "stickslip/io/attractor_report.hpp"
#include "stickslip/io/system_branch_report.hpp"

namespace stickslip::cli {

po::options_description SectionBasinOptionGroup() {
  po::options_description d("Basins on a section (with --force or --system; section [basin])");
  d.add_options()(
      "transient", Value()->value_name("P"),
      "returns (forcing periods) before a start is classified, in [0, 1e6] (default 300)")(
      "keep", Value()->value_name("K"),
      "returns that classify it (period and exponent), in [8, 1e6] (default 64)")(
      "max_period", Value()->value_name("M"),
      "the longest period looked for, in returns, in [1, keep/2] (default 16)")(
      "threads", Value()->value_name("N"),
      "worker threads, in [1, 1024], capped by the machine's hardware threads (default: all of "
      "them)")("slice", Value()->value_name("A,B"),
               "--system: the two state components the grid spans, by name (default: the first "
               "two, x1 and x1'); the others stay at steady sliding");
  return d;
}

namespace {

// The forced oscillator of --force and --omega, checked.
ForcedBeltParams ForcedFromArguments(const Arguments& args) {
  for (const char* phys : {"mass", "damping", "stiffness", "belt_speed"})
    if (args.Given(phys))
      throw UsageError(args.Source(phys) + ": the forced oscillator takes dimensionless inputs");
  if (args.Given("slice")) throw UsageError(args.Source("slice") + " needs --system");
  ForcedBeltParams p;
  p.base = UncheckedModelFromArguments(args);
  p.force = args.Number("force", 0);
  p.omega = args.Number("omega", 1);
  const std::string e = ValidationError(p);
  if (!e.empty()) throw UsageError("invalid forced model: " + e);
  return p;
}

// The component a --slice item names (its StateName or its column name).
int Component(const Arguments& args, const System& s, const std::string& item) {
  const int i = StateIndex(s, item);
  if (i < 0)
    throw UsageError(args.Source("slice") + " = '" + args.Text("slice") +
                     "': no state component '" + item + "' (" + StateNameList(s) + ")");
  return i;
}

// The slice: --slice's components through the base state, the box about it.
void SliceFromArguments(const Arguments& args, const System& s, bool forced, StartSlice* g) {
  if (!forced) {
    g->base = NearSteadySliding(s, 0);
    if (args.Given("slice")) {
      const std::vector<std::string> items = CommaItems(args.Text("slice"));
      if (items.size() != 2)
        throw UsageError(args.Source("slice") + " = '" + args.Text("slice") +
                         "': give two comma-separated state names");
      g->components = {Component(args, s, items[0]), Component(args, s, items[1])};
      if (g->components[0] == g->components[1])
        throw UsageError(args.Source("slice") + " = '" + args.Text("slice") +
                         "': the two components must differ");
    }
    for (int c = 0; c < 2; ++c)  // steady sliding +-1 by default
      g->lo[c] = g->base[g->components[c]] - 1, g->hi[c] = g->base[g->components[c]] + 1;
  }
  g->n[0] = static_cast<int>(args.IntegerIn("nx", 41, 1, 2000));
  g->n[1] = static_cast<int>(args.IntegerIn("ny", 41, 1, 2000));
  const char* box[] = {"x_min", "x_max", "xdot_min", "xdot_max"};
  int given = 0;
  for (const char* k : box) given += args.Given(k);
  if (given != 0 && given != 4)
    throw UsageError("--x_min --x_max --xdot_min --xdot_max: give all four or none");
  g->lo[0] = args.Number("x_min", g->lo[0]), g->hi[0] = args.Number("x_max", g->hi[0]);
  g->lo[1] = args.Number("xdot_min", g->lo[1]), g->hi[1] = args.Number("xdot_max", g->hi[1]);
  CheckBoxCorners(args);
  if (!(g->lo[0] < g->hi[0])) throw UsageError("--x_min must be < --x_max");
  if (!(g->lo[1] < g->hi[1])) throw UsageError("--xdot_min must be < --xdot_max");
}

AttractorOptions Configure(const Arguments& args, const System& s, bool forced, FlowOptions* flow) {
  for (const char* o : {"t_cap", "param"})
    if (args.Given(o))
      throw UsageError(args.Source(o) + ": not with " + (forced ? "--force" : "--system"));
  AttractorOptions o;
  SliceFromArguments(args, s, forced, &o.slice);
  o.iterate.transient = static_cast<int>(args.IntegerIn("transient", 300, 0, 1000000));
  o.iterate.keep = static_cast<int>(args.IntegerIn("keep", 64, 8, 1000000));
  o.iterate.align = std::min(o.iterate.align, o.iterate.transient);
  o.iterate.batches = std::min(o.iterate.batches, o.iterate.keep);
  o.max_period = static_cast<int>(args.IntegerIn("max_period", 16, 1, o.iterate.keep / 2));
  o.threads = args.Given("threads") ? static_cast<int>(args.IntegerIn("threads", 0, 1, 1024)) : 0;
  o.max_amplitude = args.Number("max_amplitude", 50);
  if (!(o.max_amplitude > 0)) throw UsageError(args.Source("max_amplitude") + " must be > 0");
  *flow = FlowOptionsFromArguments(args);
  if (!args.Given("rtol")) flow->rtol = o.iterate.flow.rtol;
  if (!args.Given("atol")) flow->atol = o.iterate.flow.atol;
  o.iterate.flow.rtol = flow->rtol, o.iterate.flow.atol = flow->atol;
  o.iterate.flow.max_steps = flow->max_steps;
  o.iterate.flow.integrator = flow->integrator, o.iterate.flow.method = flow->method;
  const std::string oe = o.ValidationError(s);
  if (!oe.empty()) throw UsageError(oe);
  return o;
}

// text broken at blanks into lines of at most `width` characters.
std::string Wrapped(const std::string& text, size_t width) {
  std::string out, line, word;
  std::istringstream in(text);
  while (in >> word) {
    if (!line.empty() && line.size() + 1 + word.size() > width) out += line + "\n", line.clear();
    line += (line.empty() ? "" : " ") + word;
  }
  return out + line;
}

// What the run's files say of the system, its section and its figure.
struct Described {
  std::string model;  // one line
  std::string title;  // the figure's (with --system: the model wrapped)
  Metadata meta;
  AttractorFigure figure;
};

Described Describe(const Arguments& args, const std::string& prog, const std::string& command,
                   const System& s, const ForcedBeltParams* fp, const AttractorOptions& o,
                   const FlowOptions& flow) {
  Described d;
  const std::string u = s.StateName(o.slice.components[0]), w = s.StateName(o.slice.components[1]);
  std::string section = "forcing phase 0 (cos Omega t = 1)", unit = "forcing periods";
  if (fp) {
    d.model = DescribeModel(fp->base) + " force=" + FormatNumber(fp->force) +
              " omega=" + FormatNumber(fp->omega);
    d.meta = RunMetadata(prog, command, fp->base, flow);
    d.meta.emplace_back("model", "forced oscillator, " + d.model);
    d.title = FigureTitle(d.model, {});
  } else {
    d.model = DescribeSystem(s, SystemChoiceOf(args), -1);
    d.meta = ToolMetadata(prog, command);
    d.meta.insert(d.meta.end(), {{"system", d.model},
                                 {"integrator", Name(flow.integrator)},
                                 {"rtol", FormatNumber(flow.rtol)},
                                 {"atol", FormatNumber(flow.atol)}});
    section = "returns to " + DefaultSectionText(s);
    unit = "returns";
    d.title = EnhancedText(Wrapped(d.model, 90));
    d.figure.stem = "basins";
    d.figure.xlabel = u + " at the start";
    d.figure.ylabel = w + " at the start";
    d.figure.comment =
        "Basins of ss_basin --system on the slice (" + u + ", " + w + ") through steady sliding.";
  }
  d.meta.insert(d.meta.end(),
                {{"section", section},
                 {"transient", std::to_string(o.iterate.transient) + " " + unit},
                 {"keep", std::to_string(o.iterate.keep) + " " + unit},
                 {"undecided_run_on", "x4 while undecided, up to " + std::to_string(o.max_keep) +
                                          (fp ? " periods" : " returns")}});
  return d;
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

int RunSectionBasin(const Arguments& args, const std::string& prog, const std::string& command) {
  const bool forced = !SystemRequested(args);
  std::unique_ptr<ForcedBeltParams> fp;
  std::unique_ptr<System> s;
  if (forced) {
    RefuseSystem(args, prog);  // --set, --blocks or a [system] section without --system
    fp = std::make_unique<ForcedBeltParams>(ForcedFromArguments(args));
    s = std::make_unique<ForcedBelt>(*fp);
  } else {
    s = SystemFromArguments(args);
  }
  FlowOptions flow;
  AttractorOptions o = Configure(args, *s, forced, &flow);
  const Described d = Describe(args, prog, command, *s, fp.get(), o, flow);
  const FigureFormat format = FigureFormatOf(args);
  const std::string stem = d.figure.stem, figure = FigureFile(stem, format);
  AppRun app(prog, args, "plots/basin", {stem + ".tsv", "attractors.tsv", stem + ".gp", figure});
  RunControl& run = app.run();
  run.Phase("classifying starts");
  o.cancelled = [&run] { return run.Cancelled(); };
  o.progress = [&run](int done, int total) {
    if (run.ProgressDue())
      run.Progress(std::to_string(done) + " of " + std::to_string(total) + " starts",
                   static_cast<double>(done) / total, done, "starts");
  };
  const AttractorBasins b = ClassifyAttractors(*s, o);
  if (!b.error.empty()) {  // nothing classified: nothing written
    std::cerr << prog << ": " << b.error << "\n";
    return kExitFailed;
  }
  Metadata meta = d.meta;
  meta.emplace_back("status", b.cancelled ? "partial (" + run.Reason() + ")"
                                          : std::to_string(b.failed) + " starts failed");
  TsvTable starts = AttractorStartTable(*s, b, o.slice), attractors = AttractorTable(*s, b);
  starts.PrependMeta(meta);
  attractors.PrependMeta(meta);
  run.Phase("writing");
  app.out().Write(stem + ".tsv", starts.str());
  app.out().Write("attractors.tsv", attractors.str());
  app.out().Write(stem + ".gp",
                  AttractorScript(*s, b, o.slice, d.figure,
                                  d.title + (b.cancelled ? " (partial)" : ""), format));
  if (!app.Finish(stem + ".gp", {figure}, {figure})) return kExitFailed;
  std::cout << prog << ": " << (forced ? "forced oscillator, " : "") << d.model << "\n"
            << starts.rows() << " starts in " << FormatNumber(std::round(b.seconds * 1e3) / 1e3)
            << " s\n";
  for (size_t i = 0; i < b.attractors.size(); ++i)
    std::cout << "attractor " << i << ": " << AttractorLabel(b.attractors[i]) << ", "
              << b.attractors[i].starts << " starts\n";
  std::cout << "wrote " << app.out().dir() << "/" << stem << ".tsv, attractors.tsv, " << stem
            << ".gp" << (app.gnuplot().ok() ? " and " + figure : std::string()) << "\n";
  std::string partial;
  if (b.cancelled) partial = "partial basins written: " + run.Reason();
  if (partial.empty() && b.failed > 0)
    partial = std::to_string(b.failed) + " starts failed (see the # failed: lines)";
  return app.ExitCode(partial);
}

}  // namespace stickslip::cli
