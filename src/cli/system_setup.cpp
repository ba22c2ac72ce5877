// ss_continue --system's inputs (system_setup.hpp).
#include "cli/system_setup.hpp"

#include <algorithm>
#include <cmath>

#include "cli/app.hpp"
#include "stickslip/systems/forced/forced.hpp"

namespace stickslip::cli {

namespace {

// The rows of steady sliding are held: 1 / max_step + 1 of them at most.
constexpr double kMinMaxStep = 1e-5;
// The forced oscillator's defaults: --max_step, --max_amplitude.
constexpr double kForcedMaxStep = 0.02, kForcedMaxAmplitude = 50;

// The forced oscillator's defaults, and its --param checked against the
// law's axes and the forcing's (AxisFromArguments' messages). Its flow:
// rtol = atol = 1e-12 (ForcedBelt::FlowDefaults: at the belt's 1e-11 the
// corrector, tol 1e-11, stalls on the flow's noise) and its switch cap, with
// the apps' step cap.
void ForcedDefaults(const Arguments& args, SystemSetup& s) {
  AxisFromArguments(args, "param", s.restart ? s.restart->continued : "omega", s.law.law, true);
  s.max_step = kForcedMaxStep, s.max_amplitude = kForcedMaxAmplitude;
  s.flow = ForcedBelt::FlowDefaults();
  s.flow.max_steps = FlowOptions().max_steps;
}

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
  } else if (s.choice == SystemChoice::kForced) {  // the far end of its default range
    const auto& f = static_cast<const ForcedBelt&>(*s.system);
    const ParameterRange r =
        DefaultRange(f.params(), ParameterAxis(s.system->ParameterName(s.param)));
    s.to = std::abs(r.to - p) >= std::abs(r.from - p) ? r.to : r.from;
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

// A start list: a clock's (clock_start.hpp; --all, --m, --point N without
// --restart), else the autonomous scan's (autonomous_start.hpp; --all,
// --point N, no --m, and its own runs: no settling run's options).
void ConfigureStart(const Arguments& args, SystemSetup& s) {
  if (args.Given("m") && s.system->clocks() != 1)
    throw UsageError(args.Source("m") + " counts clock turns; " + SystemLabel(args) +
                     " has no clock (--all or --point N picks from its start list)");
  s.start = StartChoiceFromArguments(args, s.restart.has_value());
  const bool clock = s.system->clocks() == 1;
  for (const char* o : {"transient", "disturbance"})  // no settling run
    if (args.Given(o) && (clock || s.start.scan()))
      throw UsageError(args.Source(o) + ": " +
                       (clock ? "a system with a clock starts from rest on its contacts after " +
                                    std::to_string(kTransientPeriods) + " clock turns"
                              : std::string("the start list's runs start along each mode of "
                                            "steady sliding (FindAutonomousOrbits), not settled")));
}

// --param's index: a parameter of the system, and one it depends on
// (System::ParameterError: refused here, not by the branch driver later).
int ParameterOf(const Arguments& args, const System& s, const std::string& param,
                const std::string& system) {
  const int j = s.ParameterIndex(param);
  if (j < 0)
    throw UsageError(args.Source("param") + ": '" + param + "' is no parameter of " + system +
                     " (its parameters: " + ParameterList(s) + ")");
  if (const std::string e = s.ParameterError(j); !e.empty())
    throw UsageError(args.Source("param") + ": " + e);
  return j;
}

}  // namespace

// The system is built before the law is read: it names physical inputs
// (--mass, ...) as refused, where the law would ask for their partners.
SystemSetup ConfigureSystemRun(const Arguments& args) {
  for (const char* o : {"floquet", "no_estimates"})
    if (args.Given(o) && (args.map()[o].value().type() != typeid(bool) || args.Flag(o)))
      throw UsageError(args.Source(o) + " applies to the belt, not to " + SystemLabel(args));
  SystemSetup s;
  if (args.Given("restart")) s.restart = SystemRestartFromArguments(args);
  if (args.Flag("switch") && !s.restart)
    throw UsageError(args.Source("switch") + " needs --restart DIR --point PDn");
  s.system = SystemFromArguments(args, s.restart ? &*s.restart : nullptr);
  s.law = UncheckedModelFromArguments(args, s.restart ? s.restart->law : Params());
  ConfigureStart(args, s);
  s.choice = SystemChoiceOf(args);
  if (s.restart) FromName(s.restart->system, &s.choice);  // known: SystemFromArguments built it
  const std::string system = Name(s.choice);
  const bool forced = s.choice == SystemChoice::kForced;
  if (forced) ForcedDefaults(args, s);
  if (!args.Given("param") && !s.restart && !forced)
    throw UsageError("--param is required with " + SystemLabel(args) + " (one of " +
                     ParameterList(*s.system) + ")");
  const std::string param = args.Text("param", s.restart ? s.restart->continued
                                               : forced  ? "omega"
                                                         : "");
  s.param = ParameterOf(args, *s.system, param, system);
  s.from = s.system->ParameterValue(s.param);
  if (forced && !s.restart) {  // the forced oscillator's default range (params.hpp)
    const auto& f = static_cast<const ForcedBelt&>(*s.system);
    const ParameterRange range = DefaultRange(f.params(), ParameterAxis(param));
    s.from = range.from, s.to = range.to;
  }
  if (s.restart) ConfigureRestart(args, s);
  if (!args.Given("to") && !s.restart && !forced)
    throw UsageError("--to is required with " + SystemLabel(args));
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
  if (s.doubled && !(std::min(s.from, s.to) < s.start_at && s.start_at < std::max(s.from, s.to)))
    throw UsageError(args.Source("switch") + ": the PD point's " + param + " = " +
                     FormatNumber(s.start_at) + " must lie strictly between --from " +
                     FormatNumber(s.from) + " and --to " + FormatNumber(s.to));
  if (!(std::min(s.from, s.to) <= s.start_at && s.start_at <= std::max(s.from, s.to)))
    throw UsageError(
        (s.restart ? "--restart " + args.Text("restart") + " point " + args.Text("point") + ": its "
                   : args.Source("start_at") + " = ") +
        param + " = " + FormatNumber(s.start_at) + " must lie between --from and --to");
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
  s.flow = FlowOptionsFromArguments(args, s.restart ? s.restart->flow : s.flow);
  s.settle.shooting.flow = s.flow;
  s.settle.transient = args.Number("transient", s.settle.transient);
  // Each contact may stick once per period: the recurrence looks that far (a clock: turns).
  s.settle.max_returns = std::max(s.settle.max_returns, 2 * s.system->contacts());
  s.disturbance = args.Number("disturbance", s.disturbance);
  if (const std::string e = s.settle.ValidationError(); !e.empty())
    throw UsageError(args.Source("transient") + ": " + e);
  return s;
}

}  // namespace stickslip::cli
