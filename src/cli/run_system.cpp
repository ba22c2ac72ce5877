// ss_continue --system (run_system.hpp).
#include "cli/run_system.hpp"

#include <cmath>
#include <iostream>
#include <memory>

#include "cli/about.hpp"
#include "cli/app.hpp"
#include "cli/system_choice.hpp"
#include "stickslip/io/system_branch_report.hpp"
#include "stickslip/orbits/settle.hpp"

namespace stickslip::cli {

namespace {

// The rows of steady sliding are held: 1 / max_step + 1 of them at most.
constexpr double kMinMaxStep = 1e-5;

struct SystemSetup {
  std::unique_ptr<System> system;  // at --from
  SystemChoice choice = SystemChoice::kChain;
  int param = 0;
  double from = 0, to = 0, start_at = 0, max_step = 0.01, disturbance = 0.01;
  double max_amplitude = OrbitBranchOptions().max_amplitude;
  FlowOptions flow;
  SettleOptions settle;
};

SystemSetup Configure(const Arguments& args) {
  for (const char* o : {"restart", "point", "switch", "all", "m", "floquet", "no_estimates"})
    if (args.Given(o) && (args.map()[o].value().type() != typeid(bool) || args.Flag(o)))
      throw UsageError(args.Source(o) + " applies to the belt and the forced oscillator, not to " +
                       "--system " + args.Text("system"));
  SystemSetup s;
  s.choice = SystemChoiceOf(args);
  s.system = SystemFromArguments(args);
  if (!args.Given("param"))
    throw UsageError("--param is required with --system " + args.Text("system") + " (one of " +
                     ParameterList(*s.system) + ")");
  s.param = s.system->ParameterIndex(args.Text("param"));
  if (s.param < 0)
    throw UsageError(args.Source("param") + ": '" + args.Text("param") + "' is no parameter of " +
                     args.Text("system") + " (its parameters: " + ParameterList(*s.system) + ")");
  if (!args.Given("to")) throw UsageError("--to is required with --system");
  s.from = args.Number("from", s.system->ParameterValue(s.param));
  s.to = args.Number("to", 0);
  if (s.to == s.from) throw UsageError(args.Source("to") + " must differ from --from");
  for (const auto& [name, value] : {std::pair{"from", s.from}, std::pair{"to", s.to}}) {
    std::unique_ptr<System> at = s.system->Clone();
    at->SetParameterValue(s.param, value);
    if (const std::string e = at->ValidationError(); !e.empty())
      throw UsageError((args.Given(name) ? args.Source(name) : std::string("--") + name) + " = " +
                       FormatNumber(value) + ": " + e);
  }
  s.system->SetParameterValue(s.param, s.from);
  s.start_at = args.Number("start_at", s.from);
  if (!(std::min(s.from, s.to) <= s.start_at && s.start_at <= std::max(s.from, s.to)))
    throw UsageError(args.Source("start_at") + " = " + FormatNumber(s.start_at) +
                     " must lie between --from and --to");
  s.max_step = args.Number("max_step", s.max_step);
  if (!(s.max_step >= kMinMaxStep && s.max_step <= 1))
    throw UsageError(args.Source("max_step") + " = " + FormatNumber(s.max_step) + " must lie in [" +
                     FormatNumber(kMinMaxStep) + ", 1] (1 / max_step rows of steady sliding)");
  if (s.max_step * std::abs(s.to - s.from) < OrbitBranchOptions().palc.ds_min)
    throw UsageError(
        "--max_step x |--to - --from| = " + FormatNumber(s.max_step * std::abs(s.to - s.from)) +
        " is below the branch's smallest step " + FormatNumber(OrbitBranchOptions().palc.ds_min) +
        ": widen the range or raise --max_step");
  s.max_amplitude = args.Number("max_amplitude", s.max_amplitude);
  if (!(s.max_amplitude > 0))
    throw UsageError(args.Source("max_amplitude") + " = " + FormatNumber(s.max_amplitude) +
                     " must be > 0");
  s.flow = FlowOptionsFromArguments(args);
  s.settle.shooting.flow = s.flow;
  s.settle.transient = args.Number("transient", s.settle.transient);
  // Each contact may stick once per period: the recurrence looks that far.
  s.settle.max_returns = std::max(s.settle.max_returns, 2 * s.system->contacts());
  s.disturbance = args.Number("disturbance", s.disturbance);
  if (const std::string e = s.settle.ValidationError(); !e.empty())
    throw UsageError(args.Source("transient") + ": " + e);
  return s;
}

// The attractor at start_at, from steady sliding displaced by the disturbance.
SettledOrbit Settle(const SystemSetup& s, RunControl& run) {
  std::unique_ptr<System> at = s.system->Clone();
  at->SetParameterValue(s.param, s.start_at);
  SettleOptions o = s.settle;
  o.cancelled = [&run] { return run.Cancelled(); };
  return SettleOnStickSlip(*at, NearSteadySliding(*at, s.disturbance), o);
}

OrbitBranch Piece(const SystemSetup& s, const SettledOrbit& settled, double to, RunControl& run) {
  std::unique_ptr<System> at = s.system->Clone();
  at->SetParameterValue(s.param, s.start_at);
  OrbitBranchOptions o;
  o.shooting.flow = s.flow;
  o.palc.ds_max = s.max_step * std::abs(s.to - s.from);
  o.palc.ds = std::min(o.palc.ds, o.palc.ds_max);
  o.palc.cancelled = [&run] { return run.Cancelled(); };
  o.max_amplitude = s.max_amplitude;
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
               {"orbit", settled.found ? "the attractor settled on from steady sliding + " +
                                             FormatNumber(s.disturbance) + " after " +
                                             FormatNumber(s.settle.transient) + " time units"
                                       : "none: " + NoOrbit(settled)},
               {"rtol", FormatNumber(s.flow.rtol)},
               {"atol", FormatNumber(s.flow.atol)},
               {"steady_status", Name(r.steady.status)}});
  for (std::size_t i = 0; i < r.pieces.size(); ++i)
    meta.emplace_back("branch_" + std::to_string(r.numbers[i]) + "_status",
                      std::string(Name(r.pieces[i].status)) +
                          (r.pieces[i].message.empty() ? "" : ": " + r.pieces[i].message));
  return meta;
}

void PrintSummary(const std::string& prog, const std::string& model, const SystemSetup& s,
                  const SystemRun& r, const SettledOrbit& settled) {
  std::cout << prog << ": " << model << ", from " << FormatNumber(s.from) << " to "
            << FormatNumber(s.to) << "\nsteady sliding: " << r.steady.rows.size() << " rows, "
            << Name(r.steady.status) << "\n";
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
  r.steady = ContinueSteadySliding(*s.system, s.param, s.to, so);
  run.Phase("settling");
  const SettledOrbit settled = run.Cancelled() ? SettledOrbit() : Settle(s, run);
  run.Phase("continuing");
  if (settled.found) {  // 1 toward --to, 2 back toward --from
    if (s.start_at != s.to)
      r.pieces.push_back(Piece(s, settled, s.to, run)), r.numbers.push_back(1);
    if (s.start_at != s.from)
      r.pieces.push_back(Piece(s, settled, s.from, run)), r.numbers.push_back(2);
  }
  const std::string partial = Partial(r, settled, run);
  const std::string model = DescribeSystem(*s.system, s.choice, s.param);
  Metadata meta = FileMetadata(s, r, settled, model, ToolMetadata(prog, command));
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
