// ss_continue's forced run (run_forced.hpp).
#include "cli/run_forced.hpp"

#include <cmath>
#include <iostream>
#include <optional>

#include "cli/about.hpp"
#include "cli/app.hpp"
#include "cli/clock_start.hpp"
#include "cli/restart.hpp"
#include "cli/run_log.hpp"
#include "stickslip/basin/attractors.hpp"
#include "stickslip/chaos/lyapunov.hpp"
#include "stickslip/continuation/forced_branch.hpp"
#include "stickslip/errors.hpp"
#include "stickslip/io/resonance_report.hpp"
#include "stickslip/io/system_branch_report.hpp"
#include "stickslip/systems/forced/flow.hpp"

namespace stickslip::cli {

namespace {

struct BranchSetup {
  ForcedParams p;
  ParameterAxis axis = Parameter::kOmega;
  double from = 0, to = 0;
  OrbitBranchOptions opts = OrbitBranchOptions(ForcedModel::FlowDefaults());
  int m = 1;                             // the period multiple (a restart's)
  FlowOptions flow;                      // rtol and atol as given, for the metadata
  std::optional<LabelledPoint> restart;  // a forced run's point to start from
  bool doubled = false;                  // --switch: the 2m branch from a PD point
  double lo = 0, hi = 0;                 // --switch: the bounds the 2m branch runs to
  StartChoice choice;                    // --all, --m, --point without --restart
};

// --switch at a PD point (AUTO-07p's ISW = -1): the 2m branch starts at the
// point and runs to whichever of --from, --to (default: the axis's range) it
// opens toward.
void ConfigureSwitch(const Arguments& args, const ParameterRange& range, BranchSetup& s) {
  if (!s.restart || s.restart->type != "PD")
    throw UsageError(
        args.Source("switch") +
        " needs --restart DIR --point PDn (a period "
        "doubling of a forced run)" +
        (s.restart ? ", not " + args.Text("point") + " (" + s.restart->type + ")" : std::string()));
  if (args.Given(s.axis.name()) || s.axis != s.restart->param)
    throw UsageError(args.Source("switch") + " continues the doubled branch in " +
                     s.restart->ParamName() + ", the PD point's parameter");
  s.doubled = true;
  const double p = s.axis.Get(s.p);
  // By default the range of the run the PD point came from (AUTO's RL0, RL1).
  const bool recorded = std::isfinite(s.restart->run_from) && std::isfinite(s.restart->run_to);
  s.lo = args.Number("from", recorded ? s.restart->run_from : range.from);
  s.hi = args.Number("to", recorded ? s.restart->run_to : range.to);
  if (s.lo > s.hi) std::swap(s.lo, s.hi);
  if (!(s.lo < p && p < s.hi))
    throw UsageError(args.Source("switch") + ": the PD point's " + s.restart->ParamName() + " = " +
                     FormatNumber(p) + " must lie strictly between --from " + FormatNumber(s.lo) +
                     " and --to " + FormatNumber(s.hi));
  s.from = p, s.to = s.hi;  // to: set from the branch's side once traced
}

BranchSetup Configure(const Arguments& args, const std::optional<LabelledPoint>& restart) {
  if (restart && !restart->forced)  // a belt point carries no forcing
    throw UsageError(args.Source("restart") + " " + args.Text("restart") +
                     " is a belt run: its restart cannot add a forcing (--force, --omega, "
                     "--param omega|force)");
  for (const char* phys : {"mass", "damping", "stiffness", "belt_speed"})
    if (args.Given(phys))
      throw UsageError(args.Source(phys) + ": the forced oscillator takes dimensionless inputs");
  BranchSetup s;
  s.restart = restart;
  s.choice = StartChoiceFromArguments(args, restart.has_value());
  s.p.base = UncheckedModelFromArguments(args, restart ? restart->params : Params());
  s.p.force = args.Number("force", restart ? restart->force : 0);
  s.p.omega = args.Number("omega", restart ? restart->omega : 1);
  s.axis = AxisFromArguments(args, "param", restart ? restart->param.name() : "omega", s.p.base.law,
                             true);
  const ParameterRange range = DefaultRange(s.p, s.axis);
  double from = range.from, to = range.to;
  if (restart) {  // from the point to the far end of the default range (RangeFromPoint)
    const double x = s.axis.Get(s.p);
    to = std::abs(to - x) >= std::abs(from - x) ? to : from;
    from = x;
  }
  s.from = args.Number("from", from);
  s.to = args.Number("to", to);
  if (args.Flag("switch")) ConfigureSwitch(args, range, s);
  if (s.from == s.to)
    throw UsageError(args.Source("to") + " = " + FormatNumber(s.to) + " equals the start");
  ForcedParams at = s.p;
  if (!args.Given(s.axis.name())) s.axis.Set(at, s.from);
  CheckForcedModel(args, at);
  s.axis.Set(at, s.from);
  CheckForcedModel(args, at, " at --from");
  s.axis.Set(at, s.to);
  CheckForcedModel(args, at, " at --to");
  s.flow = FlowOptionsFromArguments(args, restart ? restart->flow : FlowOptions());  // validated
  // The forced flow's own defaults (1e-12): at the belt's rtol 1e-11 the
  // corrector (tol 1e-11) stalls on the flow's noise (measured: step-too-small).
  if (!args.Given("rtol") && !restart) s.flow.rtol = s.opts.shooting.flow.rtol;
  if (!args.Given("atol") && !restart) s.flow.atol = s.opts.shooting.flow.atol;
  if (restart) s.m = restart->m;
  s.opts.shooting.flow.rtol = s.flow.rtol, s.opts.shooting.flow.atol = s.flow.atol;
  s.opts.shooting.flow.max_steps = s.opts.shooting.max_steps = s.flow.max_steps;
  s.opts.palc.ds_max = args.Number("max_step", 0.02) * std::abs(s.to - s.from);
  if (!(s.opts.palc.ds_max > 0) || s.opts.palc.ds_max > std::abs(s.to - s.from))
    throw UsageError(args.Source("max_step") + " must be in (0, 1]");
  s.opts.palc.ds = std::min(s.opts.palc.ds, s.opts.palc.ds_max);
  s.opts.max_amplitude = args.Number("max_amplitude", 50);
  if (!(s.opts.max_amplitude > 0)) throw UsageError(args.Source("max_amplitude") + " must be > 0");
  return s;
}

// ContinueForced from the orbit o (its m and point), cancelled by run.
OrbitBranch ContinueFrom(const ForcedParams& base, ParameterAxis axis, double from, double to,
                         const StartOrbit& o, const OrbitBranchOptions& opts, RunControl& run) {
  OrbitBranchOptions c = opts;
  c.palc.cancelled = [&run] { return run.Cancelled(); };  // SIGINT, --max_time
  OrbitBranch b = ContinueForced(base, axis, from, to, o.z[0], o.z[1], o.m, c);
  if (b.status == BranchStatus::kCancelled) b.message = run.Reason();
  return b;
}

// The forced oscillator's start (clock_start.hpp): from rest (x, x') = (0, v),
// the scan's box its SearchBox.
ClockStart StartOf(const ForcedModel& model, const OrbitBranchOptions& opts) {
  ClockStart c;
  c.rest = ForcedStart(model, 0, 0, model.v()).z;
  c.opts = opts;
  c.box = model.SearchBox();
  return c;
}

// A restart's branch from its point, else the branch from the default start
// (TraceFromDefaultStart, clock_start.hpp: a period-11 attractor at Omega 1.5
// on the seed belt at A 0.1).
OrbitBranch Trace(const BranchSetup& s, double from, double to, RunControl& run) {
  ForcedParams p = s.p;
  s.axis.Set(p, from);
  const ForcedModel model(p);
  if (s.restart && from == s.from) {  // the point's stroboscopic state
    OrbitBranchOptions opts = s.opts;
    opts.palc.cancelled = [&run] { return run.Cancelled(); };  // SIGINT, --max_time
    const double x = s.restart->state.x(), xdot = s.restart->state.y();
    OrbitBranch b = s.doubled ? ContinueDoubled(p, s.axis, x, xdot, s.lo, s.hi, s.m, opts)
                              : ContinueForced(s.p, s.axis, from, to, x, xdot, s.m, opts);
    if (b.status == BranchStatus::kCancelled) b.message = run.Reason();
    return b;
  }
  SettledOrbit used;
  ClockStart c = StartOf(model, s.opts);
  c.newton_m = s.m;  // a restart's m at its far end
  return TraceFromDefaultStart(
      model, c, run,
      [&](const SettledOrbit& o) {
        StartOrbit start;
        start.m = o.section.turns;
        start.z = o.orbit.start.z.head(2);
        return ContinueFrom(s.p, s.axis, from, to, start, s.opts, run);
      },
      &used);
}

// --all, --m, --point: the branches from the chosen orbits of the start list,
// printed first (UsageError if --point names none).
std::vector<OrbitBranch> TraceChosen(const BranchSetup& s, const StartChoice& c, RunControl& run) {
  ForcedParams p = s.p;
  s.axis.Set(p, s.from);
  const ForcedModel model(p);
  const ClockStart start = StartOf(model, s.opts);
  const std::optional<StartOrbit> settled =
      SettledStart(model, SettledState(model, start), start, run);
  const std::vector<StartOrbit> list = StartOrbits(model, settled, start, c.m, run);
  const std::string where = std::string(s.axis.name()) + " = " + FormatNumber(s.from);
  PrintStartOrbits(std::cout, list, where);
  const std::vector<StartOrbit> chosen = ChooseStart(list, c, where);
  std::vector<OrbitBranch> pieces;
  for (const StartOrbit& o : chosen) {
    if (run.Cancelled()) break;
    pieces.push_back(ContinueFrom(s.p, s.axis, s.from, s.to, o, s.opts, run));
  }
  return pieces;
}

std::string Describe(const BranchSetup& s) {
  std::string d = "law=" + std::string(Name(s.p.base.law));
  for (const ParameterAxis& a : ParameterAxes(s.p.base.law, true))
    d += " " + a.name() + "=" +
         (a == s.axis ? "[" + FormatNumber(s.from) + ", " + FormatNumber(s.to) + "]"
                      : FormatNumber(a.Get(s.p)));
  return d;
}

// A forcing value for the metadata; the continued one as its range.
std::string Value(const BranchSetup& s, ParameterAxis a) {
  if (a != s.axis) return FormatNumber(a.Get(s.p));
  return "[" + FormatNumber(s.from) + ", " + FormatNumber(s.to) + "] (continued)";
}

// "branch 1 reached-end; branch 2 ..." for the metadata and the summary.
std::string StatusOf(const std::vector<OrbitBranch>& pieces) {
  std::string status;
  for (size_t i = 0; i < pieces.size(); ++i)
    status += (status.empty() ? "" : "; ") + std::string("branch ") + std::to_string(i + 1) + " " +
              Name(pieces[i].status) +
              (pieces[i].message.empty() ? "" : " (" + pieces[i].message + ")");
  return status;
}

// The run's summary on stdout: range, rows, status, gap and special points.
void PrintSummary(const std::string& prog, const BranchSetup& s, const std::string& model,
                  const std::string& status, const std::string& gap,
                  const std::vector<OrbitBranch>& pieces, LogDetail detail) {
  size_t rows = 0;
  for (const OrbitBranch& piece : pieces) rows += piece.rows.size();
  std::cout << prog << ": forced oscillator, " << s.axis.name() << " from " << FormatNumber(s.from)
            << " to " << FormatNumber(s.to) << "; " << model << "\n"
            << rows << " rows; " << status << "\n";
  if (!gap.empty()) std::cout << "gap: " << gap << "\n";
  PrintForcedLog(std::cout, pieces, s.p, s.axis, detail);
}

// True (after one line on stderr) if no branch has a row.
bool NoRows(const std::string& prog, const BranchSetup& s, const std::vector<OrbitBranch>& pieces) {
  for (const OrbitBranch& piece : pieces)
    if (!piece.rows.empty()) return false;
  std::cerr << prog << ": error: no periodic orbit"
            << (s.choice.m > 0 ? " of period m = " + std::to_string(s.choice.m) : "") << " at "
            << s.axis.name() << " = " << FormatNumber(s.from);
  if (pieces.empty())
    std::cerr << " in the start list";
  else
    std::cerr << " (" << Name(pieces[0].status)
              << (pieces[0].message.empty() ? "" : ": " + pieces[0].message) << ")";
  std::cerr << "; nothing written\n";
  return true;
}

}  // namespace

po::options_description ForcingOptions() {
  po::options_description d("Model, forcing (x'' + 2 beta x' + x = F(x' - v) + A cos(Omega t))");
  d.add_options()("force", Value()->value_name("A"),
                  "force amplitude A >= 0; != 0 selects the forced oscillator (default 0: the "
                  "belt model)")("omega", Value()->value_name("W"),
                                 "forcing frequency over the natural one, > 0 (default 1)")(
      "max_amplitude", Value()->value_name("X"),
      "forced: a branch ends where |x| passes X (default 50); ss_chart: seed branches and "
      "grid cells end there (forced 50, --system 1000); the forced oscillator's rtol and "
      "atol default to 1e-12");
  return d;
}

bool ForcedRequested(const Arguments& args) {
  const std::string param = args.Text("param", "");
  const bool forced = args.Number("force", 0) != 0 || param == "force";
  if (!forced && (args.Given("omega") || param == "omega"))
    throw UsageError((args.Given("omega") ? args.Source("omega") : args.Source("param")) +
                     " needs the forced oscillator: give --force A > 0");
  return forced;
}

int RunForced(const Arguments& args, const std::string& prog, const std::string& command,
              const std::optional<LabelledPoint>& restart) {
  BranchSetup s = Configure(args, restart);
  const FigureFormat format = FigureFormatOf(args);
  const std::string figure = FigureFile("resonance", format);
  const std::vector<std::string> names = {"branch.tsv", "special_points.tsv", "resonance.gp",
                                          figure};
  AppRun app(prog, args, "plots", names);
  app.run().Phase("continuing");
  std::vector<OrbitBranch> pieces(1);
  if (s.choice.scan())
    pieces = TraceChosen(s, s.choice, app.run());
  else
    pieces[0] = Trace(s, s.from, s.to, app.run());
  if (s.doubled && !pieces[0].rows.empty())  // the side the 2m branch opens toward
    s.to = pieces[0].rows.front().p < s.from ? s.lo : s.hi;
  if (NoRows(prog, s, pieces)) return kExitFailed;  // nothing to write or draw
  std::string gap;
  std::vector<double> gap_ends;
  if (pieces[0].status == BranchStatus::kUnbounded && !s.doubled && !s.choice.scan()) {
    // Undamped resonance: trace the other end too; between them x is unbounded.
    pieces.push_back(Trace(s, s.to, s.from, app.run()));
    const auto& a = pieces[0].rows;
    const auto& b = pieces[1].rows;
    if (!a.empty() && !b.empty()) {
      gap_ends = {a.back().p, b.back().p};
      gap = "not traced between " + FormatNumber(a.back().p) + " and " + FormatNumber(b.back().p) +
            ": |x| > max_amplitude " + FormatNumber(s.opts.max_amplitude) +
            " there (unbounded resonance)";
    }
  }
  const std::string model = Describe(s);
  // v, beta: "continued", not a value
  Metadata meta = RunMetadata(prog, command, s.p.base, s.flow, s.axis.name());
  meta.insert(meta.end(),
              {{"model", "forced oscillator, " + model},
               {"force", Value(s, Parameter::kForce)},
               {"omega", Value(s, Parameter::kOmega)},
               {"continued", s.axis.name()},
               {"from", FormatNumber(s.from)},
               {"to", FormatNumber(s.to)},
               {"transient", restart ? "none: from the restart point's state"
                                     : std::to_string(kTransientPeriods) + " forcing periods"},
               {"max_amplitude", FormatNumber(s.opts.max_amplitude)}});
  const std::string status = StatusOf(pieces);
  if (restart) meta.emplace_back("restart", DescribeRestart(args, *restart));
  if (s.doubled)
    meta.emplace_back("switch", "period-doubled branch, m = " + std::to_string(s.m) + " -> " +
                                    std::to_string(2 * s.m));
  meta.emplace_back("status", status);
  if (!gap.empty()) meta.emplace_back("gap", gap);
  int specials = 0;
  for (const OrbitBranch& piece : pieces) specials += static_cast<int>(piece.special.size());
  SystemRun r;  // the system's tables (system_branch_report.hpp): no steady sliding
  r.parameter = s.axis.index();
  r.pieces = pieces;
  for (std::size_t i = 0; i < pieces.size(); ++i) r.numbers.push_back(static_cast<int>(i) + 1);
  const ForcedModel system(s.p);
  TsvTable branch = SystemBranchTable(system, r), special = SystemSpecialTable(system, r);
  branch.PrependMeta(meta);
  special.PrependMeta(meta);
  app.out().Write("branch.tsv", branch.str());
  app.out().Write("special_points.tsv", special.str());
  app.out().Write("resonance.gp", ResonanceScript(s.p, s.axis, static_cast<int>(pieces.size()),
                                                  model, gap_ends, specials, format));
  if (!app.Finish("resonance.gp", {figure}, {figure})) return kExitFailed;
  PrintSummary(prog, s, model, status, gap, pieces,
               args.Flag("verbose") ? LogDetail::kEveryPoint : LogDetail::kSpecialPoints);
  std::cout << "wrote " << app.out().dir() << "/branch.tsv, special_points.tsv, resonance.gp"
            << (app.gnuplot().ok() ? " and " + figure : "") << "\n";
  std::string partial;
  const BranchStatus last = pieces.back().status;
  if (!Complete(last) && !(pieces.size() == 2 && last == BranchStatus::kUnbounded))
    partial = "partial branch written (" + status + ")";
  return app.ExitCode(partial);
}

}  // namespace stickslip::cli
