// ss_continue --system (run_system.hpp).
#include "cli/run_system.hpp"

#include <cmath>
#include <iostream>
#include <memory>
#include <optional>

#include "cli/about.hpp"
#include "cli/app.hpp"
#include "cli/system_choice.hpp"
#include "cli/system_restart.hpp"
#include "stickslip/equilibria/steady_sliding.hpp"
#include "stickslip/io/system_branch_report.hpp"
#include "stickslip/orbits/settle.hpp"

namespace stickslip::cli {

namespace {

// The rows of steady sliding are held: 1 / max_step + 1 of them at most.
constexpr double kMinMaxStep = 1e-5;

struct SystemSetup {
  std::unique_ptr<System> system;  // at --from
  SystemChoice choice = SystemChoice::kChain;
  Params law;  // the contacts' law, as given
  std::optional<SystemPoint> restart;
  bool doubled = false;  // --switch: the period-doubled branch from a PD point
  int param = 0;
  double from = 0, to = 0, start_at = 0, max_step = 0.01, disturbance = 0.01;
  double max_amplitude = OrbitBranchOptions().max_amplitude;
  FlowOptions flow;
  SettleOptions settle;
};

// A restart's start and range (system_restart.hpp): the run starts at the
// point's value; in the run's own parameter it goes by default to the far end
// of that run's range (at an LP: the end on the side of the fold's branch;
// --switch: the doubled branch within that range), in another --to is
// required.
void ConfigureRestart(const Arguments& args, SystemSetup& s) {
  const SystemPoint& sp = *s.restart;
  if (sp.start.z.size() != s.system->dimension() || sp.contacts != s.system->contacts())
    throw UsageError(args.Source("restart") + " " + args.Text("restart") + ": the point has " +
                     std::to_string(sp.start.z.size()) + " state components and " +
                     std::to_string(sp.contacts) + " contacts, the system " +
                     std::to_string(s.system->dimension()) + " and " +
                     std::to_string(s.system->contacts()));
  if ((sp.section.kind == SectionKind::kTime) != (s.system->clocks() == 1))
    throw UsageError(args.Source("restart") + " " + args.Text("restart") + ": its orbits are on " +
                     (sp.section.kind == SectionKind::kTime ? "a clock's turns" : "a stick exit") +
                     ", and the system has " + std::to_string(s.system->clocks()) + " clocks");
  if (args.Given("start_at"))
    throw UsageError(args.Source("start_at") + ": a restart starts at its point");
  const double p = s.system->ParameterValue(s.param);
  s.start_at = s.from = p;
  const bool same = s.system->ParameterName(s.param) == sp.continued;
  if (same) {
    s.to = std::abs(sp.run_to - p) >= std::abs(sp.run_from - p) ? sp.run_to : sp.run_from;
    const double end =
        sp.fold_side > 0 ? std::max(sp.run_from, sp.run_to) : std::min(sp.run_from, sp.run_to);
    if (sp.type == "LP" && (end - p) * sp.fold_side > 0) s.to = end;
  } else if (!args.Given("to"))
    throw UsageError("--to is required with --restart in " + s.system->ParameterName(s.param) +
                     " (the run's parameter is " + sp.continued + ")");
  if (!args.Flag("switch")) return;
  if (sp.type != "PD")
    throw UsageError(args.Source("switch") + " needs --point PDn (a period doubling), not " +
                     sp.label + " (" + sp.type + ")");
  if (!same)
    throw UsageError(args.Source("switch") + " continues the doubled branch in " + sp.continued +
                     ", the PD point's parameter");
  s.doubled = true;
  s.from = sp.run_from, s.to = sp.run_to;
}

SystemSetup Configure(const Arguments& args) {
  for (const char* o : {"all", "m", "floquet", "no_estimates"})
    if (args.Given(o) && (args.map()[o].value().type() != typeid(bool) || args.Flag(o)))
      throw UsageError(args.Source(o) + " applies to the belt and the forced oscillator, not to " +
                       SystemLabel(args));
  SystemSetup s;
  if (args.Given("restart")) s.restart = SystemRestartFromArguments(args);
  if (args.Given("point") && !s.restart)
    throw UsageError(args.Source("point") + " " + args.Text("point") + " needs --restart DIR");
  if (args.Flag("switch") && !s.restart)
    throw UsageError(args.Source("switch") + " needs --restart DIR --point PDn");
  s.law = UncheckedModelFromArguments(args, s.restart ? s.restart->law : Params());
  s.system = SystemFromArguments(args, s.restart ? &*s.restart : nullptr);
  s.choice = SystemChoiceOf(args);
  if (s.restart) FromName(s.restart->system, &s.choice);  // known: SystemFromArguments built it
  const std::string system = Name(s.choice);
  if (!args.Given("param") && !s.restart)
    throw UsageError("--param is required with " + SystemLabel(args) + " (one of " +
                     ParameterList(*s.system) + ")");
  const std::string param = args.Text("param", s.restart ? s.restart->continued : "");
  s.param = s.system->ParameterIndex(param);
  if (s.param < 0)
    throw UsageError(args.Source("param") + ": '" + param + "' is no parameter of " + system +
                     " (its parameters: " + ParameterList(*s.system) + ")");
  s.from = s.system->ParameterValue(s.param);
  if (s.restart) ConfigureRestart(args, s);
  if (!args.Given("to") && !s.restart) throw UsageError("--to is required with --system");
  s.from = args.Number("from", s.from);
  s.to = args.Number("to", s.to);
  if (s.to == s.from) throw UsageError(args.Source("to") + " must differ from --from");
  for (const auto& [name, value] : {std::pair{"from", s.from}, std::pair{"to", s.to}}) {
    std::unique_ptr<System> at = s.system->Clone();
    at->SetParameterValue(s.param, value);
    if (const std::string e = at->ValidationError(); !e.empty())
      throw UsageError((args.Given(name) ? args.Source(name) : std::string("--") + name) + " = " +
                       FormatNumber(value) + ": " + e);
  }
  s.system->SetParameterValue(s.param, s.from);
  if (!s.restart) s.start_at = args.Number("start_at", s.from);
  if (!(std::min(s.from, s.to) <= s.start_at && s.start_at <= std::max(s.from, s.to)))
    throw UsageError(
        (s.restart ? "--restart " + args.Text("restart") + " point " + args.Text("point") + ": its "
                   : args.Source("start_at") + " = ") +
        param + " = " + FormatNumber(s.start_at) + " must lie between --from and --to" +
        (s.doubled ? ", not at either" : ""));
  if (s.doubled && (s.start_at == s.from || s.start_at == s.to))
    throw UsageError(args.Source("switch") + ": the PD point's " + param + " = " +
                     FormatNumber(s.start_at) + " must lie strictly between --from and --to");
  s.max_step = args.Number("max_step", s.max_step);
  if (!(s.max_step >= kMinMaxStep && s.max_step <= 1))
    throw UsageError(args.Source("max_step") + " = " + FormatNumber(s.max_step) + " must lie in [" +
                     FormatNumber(kMinMaxStep) + ", 1] (1 / max_step rows of steady sliding)");
  if (s.max_step * std::abs(s.to - s.from) < OrbitBranchOptions().palc.ds_min)
    throw UsageError(
        "--max_step x |--to - --from| = " + FormatNumber(s.max_step * std::abs(s.to - s.from)) +
        " is below the branch's smallest step " + FormatNumber(OrbitBranchOptions().palc.ds_min) +
        ": widen the range or raise --max_step");
  s.max_amplitude =
      args.Number("max_amplitude", s.restart ? s.restart->max_amplitude : s.max_amplitude);
  if (!(s.max_amplitude > 0))
    throw UsageError(args.Source("max_amplitude") + " = " + FormatNumber(s.max_amplitude) +
                     " must be > 0");
  s.flow = FlowOptionsFromArguments(args, s.restart ? s.restart->flow : FlowOptions());
  s.settle.shooting.flow = s.flow;
  s.settle.transient = args.Number("transient", s.settle.transient);
  // Each contact may stick once per period: the recurrence looks that far (a clock: turns).
  s.settle.max_returns = std::max(s.settle.max_returns, 2 * s.system->contacts());
  s.disturbance = args.Number("disturbance", s.disturbance);
  if (const std::string e = s.settle.ValidationError(); !e.empty())
    throw UsageError(args.Source("transient") + ": " + e);
  return s;
}

// The attractor at start_at, from steady sliding (a clock: the origin) + the disturbance.
SettledOrbit Settle(const SystemSetup& s, RunControl& run) {
  std::unique_ptr<System> at = s.system->Clone();
  at->SetParameterValue(s.param, s.start_at);
  SettleOptions o = s.settle;
  o.cancelled = [&run] { return run.Cancelled(); };
  return SettleOnStickSlip(*at, NearSteadySliding(*at, s.disturbance), o);
}

// A restart's orbit, as if settled on: its point and section (a clock's turns at its parameters).
SettledOrbit AtPoint(const SystemSetup& s, const SystemPoint& sp) {
  SettledOrbit o;
  o.found = true;
  o.section = sp.section;
  if (sp.section.kind == SectionKind::kTime) {
    std::unique_ptr<System> at = s.system->Clone();
    at->SetParameterValue(s.param, s.start_at);
    o.section = PoincareSection::Stroboscopic(*at, sp.start.z, sp.section.turns);
  }
  o.orbit.start = sp.start;
  o.orbit.period = sp.period;
  return o;
}

// The branch from the start to `to`; a restart's leaves along the tangent
// (at an LP, `side` 1 or -1 picks the half; 0 elsewhere); --switch: the doubled branch from the
// PD point to whichever end it opens toward.
OrbitBranch Piece(const SystemSetup& s, const SettledOrbit& settled, double to, int side,
                  RunControl& run) {
  std::unique_ptr<System> at = s.system->Clone();
  at->SetParameterValue(s.param, s.start_at);
  OrbitBranchOptions o;
  o.shooting.flow = s.flow;
  o.palc.ds_max = s.max_step * std::abs(s.to - s.from);
  o.palc.ds = std::min(o.palc.ds, o.palc.ds_max);
  o.palc.cancelled = [&run] { return run.Cancelled(); };
  o.max_amplitude = s.max_amplitude;
  if (s.doubled)
    return ContinueDoubled(*at, s.param, settled.orbit.start, settled.section,
                           std::min(s.from, s.to), std::max(s.from, s.to), o);
  if (s.restart)
    return ContinueOrbitsFrom(*at, s.param, settled.orbit.start, settled.section, to, side, o);
  return ContinueOrbits(*at, s.param, settled.orbit.start, settled.section, to, o);
}

}  // namespace

po::options_description SystemRunOptions() {
  po::options_description d("With --system (docs/systems.md)");
  d.add_options()("start_at", Value()->value_name("P"),
                  "where the stick-slip attractor is sought, between --from and --to (default "
                  "--from); its branch is traced to --to and back to --from")(
      "transient", Value()->value_name("T"),
      "the settling run's length in time units (default 3000)")(
      "disturbance", Value()->value_name("D"),
      "the settling run starts at steady sliding with the first component moved by D "
      "(default 0.01)");
  return d;
}

namespace {

// Why no orbit was found ("cancelled" where the run was).
std::string NoOrbit(const SettledOrbit& settled) {
  return settled.message.empty() ? std::string("cancelled") : settled.message;
}

// Why the run is cut short ("" if complete): the first piece that did not
// end where it should, or a settling run that failed or was cancelled.
std::string Partial(const SystemRun& r, const SettledOrbit& settled, RunControl& run) {
  auto cut = [&](const std::string& what, BranchStatus b, const std::string& message) {
    return what + " " + Name(b) + ": " + (b == BranchStatus::kCancelled ? run.Reason() : message);
  };
  if (!Complete(r.steady.status)) return cut("steady sliding", r.steady.status, r.steady.message);
  for (std::size_t i = 0; i < r.pieces.size(); ++i)
    if (!Complete(r.pieces[i].status))
      return cut("branch " + std::to_string(r.numbers[i]), r.pieces[i].status, r.pieces[i].message);
  if (settled.found) return "";
  if (run.Cancelled()) return "no attractor: " + run.Reason();
  // Newton failed on a cycle that recurred, or the run failed: numerical
  // failures. No stick phase, no recurrence, or a contact that opens: answers.
  if (settled.recurred ||
      (settled.run != FlowStatus::kTimeLimit && settled.run != FlowStatus::kContactOpen))
    return "no attractor: " + settled.message;
  return "";
}

Metadata FileMetadata(const SystemSetup& s, const SystemRun& r, const SettledOrbit& settled,
                      const std::string& model, Metadata meta) {
  meta.insert(meta.end(),
              {{"system", model},
               {"continued", s.system->ParameterName(s.param)},
               {"from", FormatNumber(s.from)},
               {"to", FormatNumber(s.to)},
               {"start_at", FormatNumber(s.start_at)},
               {"orbit", s.restart       ? std::string("the restart point's orbit, no settling")
                         : settled.found ? "the attractor settled on from " +
                                               std::string(s.system->clocks() ? "the origin"
                                                                              : "steady sliding") +
                                               " + " + FormatNumber(s.disturbance) + " after " +
                                               FormatNumber(s.settle.transient) + " time units"
                                         : "none: " + NoOrbit(settled)},
               {"rtol", FormatNumber(s.flow.rtol)},
               {"atol", FormatNumber(s.flow.atol)},
               {"steady_status", s.system->clocks() ? std::string("none: a clock, no rest point")
                                                    : std::string(Name(r.steady.status))}});
  PoincareSection section = settled.section;  // ContinueDoubled's: twice the returns or turns
  if (section.kind == SectionKind::kTime)
    section.turns *= s.doubled ? 2 : 1;
  else
    section = PoincareSection::StickExit(section.contact, section.returns * (s.doubled ? 2 : 1));
  AddRestartMetadata(*s.system, s.choice, s.law, s.flow, s.max_amplitude,
                     settled.found ? &section : nullptr, meta);
  for (std::size_t i = 0; i < r.pieces.size(); ++i)
    meta.emplace_back("branch_" + std::to_string(r.numbers[i]) + "_status",
                      std::string(Name(r.pieces[i].status)) +
                          (r.pieces[i].message.empty() ? "" : ": " + r.pieces[i].message));
  return meta;
}

void PrintSummary(const std::string& prog, const std::string& model, const SystemSetup& s,
                  const SystemRun& r, const SettledOrbit& settled) {
  std::cout << prog << ": " << model << ", from " << FormatNumber(s.from) << " to "
            << FormatNumber(s.to) << "\n";
  if (s.system->clocks() == 0)
    std::cout << "steady sliding: " << r.steady.rows.size() << " rows, " << Name(r.steady.status)
              << "\n";
  if (!settled.found)
    std::cerr << prog << ": note: no stick-slip orbit: " << NoOrbit(settled) << "\n";
  for (std::size_t i = 0; i < r.pieces.size(); ++i)
    std::cout << "branch " << r.numbers[i] << ": " << r.pieces[i].rows.size() << " rows, "
              << Name(r.pieces[i].status) << "\n";
  auto point = [](SpecialKind k, double p, const std::string& what) {
    std::cout << "  " << Name(k) << " at " << FormatNumber(p) << ": " << what << "\n";
  };
  for (const SteadyRow& p : r.steady.special) point(p.label, p.p, p.description);
  for (const OrbitBranch& b : r.pieces)
    for (const OrbitRow& p : b.special) point(p.label, p.p, p.description);
}

}  // namespace

int RunSystem(const Arguments& args, const std::string& prog, const std::string& command) {
  SystemSetup s = Configure(args);
  const FigureFormat format = FigureFormatOf(args);
  std::vector<std::string> names = {"branch.tsv", "special_points.tsv", "bifurcation.gp"};
  for (const std::string& f : SystemBranchFigures(format)) names.push_back(f);
  AppRun app(prog, args, "plots", names);
  RunControl& run = app.run();
  SystemRun r;
  r.parameter = s.param;
  run.Phase("steady sliding");
  SteadyBranchOptions so;
  so.points = static_cast<int>(std::ceil(1 / s.max_step)) + 1;
  so.cancelled = [&run] { return run.Cancelled(); };
  r.steady.status = BranchStatus::kReachedEnd;  // a forcing has no rest point
  if (s.system->clocks() == 0) r.steady = ContinueSteadySliding(*s.system, s.param, s.to, so);
  run.Phase("settling");
  const SettledOrbit settled = run.Cancelled() ? SettledOrbit()
                               : s.restart     ? AtPoint(s, *s.restart)
                                               : Settle(s, run);
  run.Phase("continuing");
  const bool fold = s.restart && s.restart->type == "LP";
  if (s.doubled && settled.found) {
    r.pieces.push_back(Piece(s, settled, s.to, 0, run)), r.numbers.push_back(1);
  } else if (settled.found) {  // 1 toward --to, 2 back toward --from (a fold: both halves)
    if (s.start_at != s.to)
      r.pieces.push_back(Piece(s, settled, s.to, fold ? 1 : 0, run)), r.numbers.push_back(1);
    if (s.start_at != s.from || (fold && s.start_at != s.to))
      r.pieces.push_back(Piece(s, settled, fold ? s.to : s.from, fold ? -1 : 0, run)),
          r.numbers.push_back(2);
  }
  const std::string partial = Partial(r, settled, run);
  const std::string model = DescribeSystem(*s.system, s.choice, s.param);
  Metadata meta = FileMetadata(s, r, settled, model, ToolMetadata(prog, command));
  if (s.restart) meta.emplace_back("restart", DescribeSystemRestart(args, *s.restart));
  if (s.doubled) {
    const bool turns = s.restart->section.kind == SectionKind::kTime;
    const int m = turns ? s.restart->section.turns : s.restart->section.returns;
    meta.emplace_back("switch", std::string("period-doubled branch, ") +
                                    (turns ? "turns " : "returns ") + std::to_string(m) + " -> " +
                                    std::to_string(2 * m));
  }
  meta.emplace_back("status", partial.empty() ? "complete" : "partial: " + partial);
  TsvTable branch = SystemBranchTable(*s.system, r), special = SystemSpecialTable(*s.system, r);
  branch.PrependMeta(meta);
  special.PrependMeta(meta);
  app.out().Write("branch.tsv", branch.str());
  app.out().Write("special_points.tsv", special.str());
  app.out().Write("bifurcation.gp", SystemBranchScript(*s.system, r, model, format));
  if (!app.Finish("bifurcation.gp", SystemBranchFigures(format), SystemBranchFigures(format)))
    return kExitFailed;
  PrintSummary(prog, model, s, r, settled);
  std::cout << "wrote " << app.out().dir() << "/branch.tsv, special_points.tsv, bifurcation.gp"
            << (app.gnuplot().ok() ? " and the figure" : "") << "\n";
  return app.ExitCode(partial);
}

}  // namespace stickslip::cli
