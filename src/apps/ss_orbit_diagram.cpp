// ss_orbit_diagram: the orbit diagram of the forced oscillator (stroboscopic
// section points) or of any --system (its returns to x1' = 0 falling), with
// stick counts and exit phases against one parameter, swept up and down, and
// the largest Lyapunov exponent below.
#include <cmath>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "cli/about.hpp"
#include "cli/app.hpp"
#include "cli/study.hpp"
#include "cli/system_choice.hpp"
#include "stickslip/io/orbit_diagram_report.hpp"

namespace ss = stickslip;
namespace cli = stickslip::cli;
namespace po = boost::program_options;

namespace {

constexpr const char* kProg = "ss_orbit_diagram";
constexpr const char* kNotes =
    "For each parameter value the stroboscopic map (forcing phase 0, cos Omega t = 1) is\n"
    "iterated for --transient forcing periods, then --keep periods are recorded with the\n"
    "largest Lyapunov exponent (variational equations with saltation at every switch,\n"
    "docs/theory.md). Each value starts from the last state of the one before, in both\n"
    "directions (--direction), so hysteresis shows; the directions (and their --chunks)\n"
    "run on at most --threads threads, capped by the machine's hardware threads.\n"
    "Outputs in --out (written as one set): orbit_diagram.tsv (one row per section point),\n"
    "lyapunov.tsv (one row per value), orbit_diagram.gp and orbit_diagram.png (.pdf, .svg).\n"
    "A value whose flow fails or passes --max_amplitude is a `# failed:` line, one whose\n"
    "contact opens a `# contact lost:` line (not a failure); the next starts from rest.\n"
    "An interrupted run writes the values done, marked partial.\n"
    "The forced flow's rtol and atol default to 1e-12. --integrator cvode integrates the\n"
    "slip phases by CVODE instead of Taylor series: an independent check of the exponent.\n"
    "--system chain|mode_coupling: the map is the returns to x1' = 0 falling (the maxima of\n"
    "the first component), --param any of the system's parameters, --from and --to required;\n"
    "the tables' columns are the system's states (x1, x1dot, ..., stuck1, stuck2, ...).\n";
constexpr const char* kExample =
    "\nExample: ss_orbit_diagram --law stribeck --beta 0.01 --v 0.1 --force 0.5 --param omega "
    "--from 0.2 --to 1.2 --n 400";

po::options_description AppOptions() {
  po::options_description d("Orbit diagram (study section [orbit_diagram])");
  d.add_options()(
      "param", cli::Value()->value_name("NAME"),
      "the swept parameter: one of the law's, force or omega (default omega); --system: any "
      "of its parameters (default v)")(
      "from", cli::Value()->value_name("P"),
      "first value (default: omega 0.5, else the parameter's range; --system: required)")(
      "to", cli::Value()->value_name("P"),
      "last value (default: omega 2.5, else the parameter's range; --system: required)")(
      "n", cli::Value()->value_name("N"), "parameter values, in [2, 100000] (default 200)")(
      "transient", cli::Value()->value_name("P"),
      "returns (forcing periods) discarded per value, in [0, 1e6] (default 500)")(
      "keep", cli::Value()->value_name("K"),
      "returns (forcing periods) recorded per value, in [10, 1e6] (default 200)")(
      "direction", cli::Value()->value_name("D"), "up, down or both (default both)")(
      "chunks", cli::Value()->value_name("C"),
      "pieces each sweep is cut into and run in parallel, each from rest: hysteresis shows only "
      "within a piece (default 1)")(
      "threads", cli::Value()->value_name("N"),
      "worker threads, in [1, 1024], capped by the machine's hardware threads (default: all of "
      "them)");
  cli::AddRunOptions(d, "plots/orbit_diagram",
                     "write the TSV files and the script, but do not run gnuplot");
  return d;
}

struct Setup {
  ss::ForcedBeltParams p;              // the forced oscillator's (without --system)
  std::unique_ptr<ss::System> system;  // what is swept: p's model, or --system's
  int param = 0;                       // its parameter index
  ss::OrbitDiagramOptions o;
  ss::FlowOptions flow;  // for the metadata
  ss::DiagramLabels labels;
  std::string model;  // one line
};

// The forced oscillator and its swept parameter (checked at --from and --to).
void ConfigureForced(const cli::Arguments& args, Setup& s) {
  for (const char* phys : {"mass", "damping", "stiffness", "belt_speed"})
    if (args.Given(phys))
      throw cli::UsageError(args.Source(phys) +
                            ": the forced oscillator takes dimensionless inputs");
  s.p.base = cli::UncheckedModelFromArguments(args);
  s.p.force = args.Number("force", 0.3);
  s.p.omega = args.Number("omega", 1);
  s.o.axis = cli::AxisFromArguments(args, "param", "omega", s.p.base.law, true);
  // omega's own range; the others the forced oscillator's (DefaultRange).
  const ss::ParameterRange range = s.o.axis == ss::Parameter::kOmega
                                       ? ss::ParameterRange{0.5, 2.5}
                                       : ss::DefaultRange(s.p, s.o.axis);
  s.o.from = args.Number("from", range.from);
  s.o.to = args.Number("to", range.to);
  // Every given value is checked, the swept one too (--omega -1 with --param
  // omega); a swept one not given is checked at --from and --to below only.
  if (args.Given(s.o.axis.name())) cli::CheckForcedBelt(args, s.p);
  if (s.o.from == s.o.to)
    throw cli::UsageError(args.Source("to") + " = " + args.Text("to") + " equals --from");
  for (const char* end : {"from", "to"}) {
    ss::ForcedBeltParams at = s.p;
    s.o.axis.Set(at, end[0] == 'f' ? s.o.from : s.o.to);
    cli::CheckForcedBelt(args, at, " at --" + std::string(end), s.o.axis.name());
  }
  s.system = std::make_unique<ss::ForcedBelt>(s.p);
  s.param = s.o.axis.index();
  s.labels = {s.o.axis.name(), ss::ParameterAxisLabel(s.o.axis), "forcing phase 0"};
}

// --system's system and its swept parameter (checked at --from and --to).
void ConfigureSystem(const cli::Arguments& args, Setup& s) {
  s.system = cli::SystemFromArguments(args);
  const std::string name = args.Text("param", "v");
  s.param = s.system->ParameterIndex(name);
  if (s.param < 0)
    throw cli::UsageError(args.Source("param") + " = " + name + ": no parameter of " +
                          cli::SystemLabel(args) + " (" + cli::ParameterList(*s.system) + ")");
  if (const std::string e = s.system->ParameterError(s.param); !e.empty())  // a flat diagram
    throw cli::UsageError(args.Source("param") + ": " + e);
  for (const char* end : {"from", "to"})
    if (!args.Given(end)) throw cli::UsageError(cli::SystemLabel(args) + " needs --" + end);
  s.o.from = args.Number("from", 0), s.o.to = args.Number("to", 0);
  if (s.o.from == s.o.to)
    throw cli::UsageError(args.Source("to") + " = " + args.Text("to") + " equals --from");
  for (const char* end : {"from", "to"}) {
    std::unique_ptr<ss::System> at = s.system->Clone();
    at->SetParameterValue(s.param, args.Number(end, 0));
    const std::string e = at->ValidationError();
    if (!e.empty()) throw cli::UsageError(args.Source(end) + " = " + args.Text(end) + ": " + e);
  }
  s.labels = {name, name, cli::DefaultSectionText(*s.system)};
}

Setup Configure(const cli::Arguments& args) {
  Setup s;
  if (cli::SystemRequested(args)) {
    ConfigureSystem(args, s);
  } else {
    cli::RefuseSystem(args, kProg);  // --set, --blocks or [system] without --system
    ConfigureForced(args, s);
  }
  s.o.n = static_cast<int>(args.IntegerIn("n", 200, 2, 100000));
  s.o.iterate.transient = static_cast<int>(args.IntegerIn("transient", 500, 0, 1000000));
  s.o.iterate.keep = static_cast<int>(args.IntegerIn("keep", 200, 10, 1000000));
  s.o.threads = args.Given("threads") ? static_cast<int>(args.IntegerIn("threads", 0, 1, 1024)) : 0;
  s.o.iterate.align = std::min(s.o.iterate.align, s.o.iterate.transient);
  const std::string dir = args.Text("direction", "both");
  if (dir != "up" && dir != "down" && dir != "both")
    throw cli::UsageError("invalid value '" + dir + "' for " + args.Source("direction") +
                          ": must be up, down or both");
  s.o.up = dir != "down", s.o.down = dir != "up";
  const double points = static_cast<double>(s.o.n) * s.o.iterate.keep * (s.o.up + s.o.down);
  if (points > ss::OrbitDiagramOptions::kMaxPoints)
    throw cli::UsageError(
        args.Source("n") + " " + std::to_string(s.o.n) + " x " + args.Source("keep") + " " +
        std::to_string(s.o.iterate.keep) + " x " + std::to_string(s.o.up + s.o.down) +
        " directions = " + ss::FormatNumber(points) + " section points, more than " +
        ss::FormatNumber(ss::OrbitDiagramOptions::kMaxPoints) + " (held in memory)");
  s.o.chunks = static_cast<int>(args.IntegerIn("chunks", 1, 1, s.o.n));
  s.o.max_amplitude = args.Number("max_amplitude", 50);
  if (!(s.o.max_amplitude > 0))
    throw cli::UsageError(args.Source("max_amplitude") + " must be > 0");
  s.flow = cli::FlowOptionsFromArguments(args);
  if (!args.Given("rtol")) s.flow.rtol = s.o.iterate.flow.rtol;
  if (!args.Given("atol")) s.flow.atol = s.o.iterate.flow.atol;
  s.o.iterate.flow.rtol = s.flow.rtol, s.o.iterate.flow.atol = s.flow.atol;
  s.o.iterate.flow.max_steps = s.flow.max_steps;
  s.o.iterate.flow.integrator = s.flow.integrator, s.o.iterate.flow.method = s.flow.method;
  const std::string e = s.o.ValidationError();
  if (!e.empty()) throw cli::UsageError(e);
  return s;
}

std::string Describe(const cli::Arguments& args, const Setup& s) {
  if (cli::SystemRequested(args)) {
    std::string d = cli::DescribeSystem(*s.system, cli::SystemChoiceOf(args), s.param);
    const size_t at = d.find("[continued]");
    return at == std::string::npos ? d : d.replace(at, 11, "[swept]");
  }
  std::string d = std::string("law=") + ss::Name(s.p.base.law);
  for (const ss::ParameterAxis& a :
       ss::ParameterAxes(s.p.base.law, true))  // the swept one left out
    if (a != s.o.axis) d += " " + a.name() + "=" + ss::FormatNumber(a.Get(s.p));
  return d;
}

// The files' metadata: the tool, the model, the integrator.
cli::Metadata Metadata(const cli::Arguments& args, const Setup& s, const std::string& command,
                       const std::string& model) {
  if (!cli::SystemRequested(args)) {
    cli::Metadata m = cli::RunMetadata(kProg, command, s.p.base, s.flow, s.labels.param);
    m.emplace_back("model", "forced oscillator, " + model);
    return m;
  }
  cli::Metadata m = cli::ToolMetadata(kProg, command);
  m.insert(m.end(), {{"system", model},
                     {"integrator", ss::Name(s.flow.integrator)},
                     {"rtol", ss::FormatNumber(s.flow.rtol)},
                     {"atol", ss::FormatNumber(s.flow.atol)}});
  return m;
}

int Main(int argc, char** argv) {
  po::options_description mine = AppOptions();
  mine.add(cli::ForcingOptions());
  const po::options_description desc = cli::AppDescription(mine);
  const cli::Arguments args = cli::ParseArguments(argc, argv, desc, "orbit_diagram");
  if (cli::HelpOrVersion(std::cout, args, kProg, "ss_orbit_diagram [--study FILE] [options]", desc,
                         std::string(kNotes) + cli::kExitCodeHelp + kExample))
    return 0;
  Setup s = Configure(args);
  const ss::FigureFormat format = cli::FigureFormatOf(args);
  const std::string figure = ss::FigureFile("orbit_diagram", format);
  cli::AppRun app(kProg, args, "plots/orbit_diagram",
                  {"orbit_diagram.tsv", "lyapunov.tsv", "orbit_diagram.gp", figure});
  cli::RunControl& run = app.run();
  run.Phase("iterating the Poincare map");
  s.o.cancelled = [&run] { return run.Cancelled(); };
  s.o.progress = [&run](int done, int total) {
    if (run.ProgressDue())
      run.Progress(std::to_string(done) + " of " + std::to_string(total) + " values",
                   static_cast<double>(done) / total, done, "values");
  };
  const ss::OrbitDiagram d = ss::ComputeOrbitDiagram(*s.system, s.param, s.o);
  if (!d.error.empty()) {  // nothing computed: nothing written
    std::cerr << kProg << ": " << d.error << "\n";
    return cli::kExitFailed;
  }
  const bool forced = !cli::SystemRequested(args);
  const std::string model = Describe(args, s), axis = s.labels.param;
  const std::string unit = forced ? " forcing periods" : " returns";
  cli::Metadata meta = Metadata(args, s, cli::CommandLine(argc, argv), model);
  meta.insert(
      meta.end(),
      {{"swept", axis + " from " + ss::FormatNumber(s.o.from) + " to " + ss::FormatNumber(s.o.to) +
                     ", " + std::to_string(s.o.n) + " values"},
       {"transient", std::to_string(s.o.iterate.transient) + unit},
       {"keep", std::to_string(s.o.iterate.keep) + unit},
       {"section", forced ? "forcing phase 0 (cos Omega t = 1)" : s.labels.section},
       {"status", d.cancelled ? "partial (" + run.Reason() + ")"
                              : std::to_string(d.failed) + " values failed" +
                                    (d.contact_lost > 0
                                         ? ", " + std::to_string(d.contact_lost) + " lost contact"
                                         : std::string())}});
  run.Phase("writing");
  ss::TsvTable points = ss::OrbitDiagramTable(*s.system, d, s.labels),
               exps = ss::ExponentTable(*s.system, d, s.labels);
  points.PrependMeta(meta);
  exps.PrependMeta(meta);
  app.out().Write("orbit_diagram.tsv", points.str());
  app.out().Write("lyapunov.tsv", exps.str());
  const std::string title = forced ? ss::FigureTitle(model, {axis}) : ss::EnhancedText(model);
  app.out().Write(
      "orbit_diagram.gp",
      ss::OrbitDiagramScript(*s.system, format, s.labels, title + (d.cancelled ? " (partial)" : ""),
                             s.o.up, s.o.down));
  // No value done (every one failed): the tables with their `# failed:` lines, no figure.
  const std::vector<std::string> drawn =
      exps.rows() > 0 ? std::vector<std::string>{figure} : std::vector<std::string>{};
  if (!app.Finish("orbit_diagram.gp", drawn, {figure})) return cli::kExitFailed;
  std::cout << kProg << ": " << (forced ? "forced oscillator, " : "") << model << "\n"
            << axis << " from " << ss::FormatNumber(s.o.from) << " to " << ss::FormatNumber(s.o.to)
            << ": " << exps.rows() << " values done, " << d.failed << " failed, " << d.contact_lost
            << " lost contact, in " << ss::FormatNumber(std::round(d.seconds * 1e3) / 1e3) << " s\n"
            << "wrote " << app.out().dir() << "/orbit_diagram.tsv, lyapunov.tsv, orbit_diagram.gp"
            << (app.gnuplot().ok() && !drawn.empty() ? " and " + figure : std::string()) << "\n";
  std::string partial;
  if (d.cancelled) partial = "partial orbit diagram written: " + run.Reason();
  if (partial.empty() && d.failed > 0)
    partial = std::to_string(d.failed) + " values failed (see the # failed: lines)";
  return app.ExitCode(partial);
}

}  // namespace

int main(int argc, char** argv) {
  return cli::RunApp(kProg, [&] { return Main(argc, argv); });
}
