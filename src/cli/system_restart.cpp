// A system's restart from the command line (system_restart.hpp).
#include "cli/system_restart.hpp"

#include "cli/physical.hpp"
#include "cli/restart.hpp"
#include "stickslip/io/report.hpp"
#include "stickslip/systems/forced/forced.hpp"

namespace stickslip::cli {

bool SystemRestartRequested(const Arguments& args) {
  return args.Given("restart") && args.Given("point") &&
         IsSystemRun(args.Text("restart"), args.Text("point"));
}

namespace {

// A forced run's point written before its files named the system (no
// '# system:' line; restart.hpp reads it, x0/xdot0 or the system's columns)
// as the forced system's: its m turns, its point at theta = 0.
SystemPoint ForcedPoint(const Arguments& args) {
  const LabelledPoint lp = *RestartFromArguments(args);
  if (!lp.forced)  // a belt point carries no forcing
    throw UsageError(args.Source("restart") + " " + args.Text("restart") +
                     " is a belt run: its restart cannot add a forcing (--force, --omega, "
                     "--param omega|force)");
  SystemPoint sp;
  sp.label = lp.label, sp.pt = lp.pt, sp.type = lp.type, sp.branch = 1;
  sp.system = Name(SystemChoice::kForced);
  sp.law = lp.params;
  const ForcedBelt m(ForcedBeltParams{lp.params, lp.force, lp.omega});
  for (int j = 0; j < m.parameters(); ++j)
    sp.parameters.emplace_back(m.ParameterName(j), m.ParameterValue(j));
  sp.continued = lp.ParamName(), sp.p = lp.p, sp.flow = lp.flow;
  sp.max_amplitude = 50;  // the forced run's default then
  sp.start = {0, Eigen::Vector3d(lp.state.x(), lp.state.y(), 0), ModeSet(Mode::kSlipBelow)};
  sp.section = PoincareSection::Stroboscopic(m, sp.start.z, lp.m);
  sp.contacts = 1, sp.period = lp.period, sp.run_from = lp.run_from, sp.run_to = lp.run_to;
  return sp;
}

}  // namespace

SystemPoint SystemRestartFromArguments(const Arguments& args) {
  // Without --system or --model: a forced run's older files too.
  if (args.Given("point") && !args.Given("system") && !args.Given("model") &&
      !IsSystemRun(args.Text("restart"), args.Text("point")))
    return ForcedPoint(args);
  if (!args.Given("point"))
    throw UsageError(args.Source("restart") + " " + args.Text("restart") +
                     " needs --point LABEL (LP1, PD1, GR1, ... or a point number)");
  if (ScalesFromArguments(args))
    throw UsageError(args.Source("restart") +
                     " restarts in dimensionless parameters: physical inputs cannot be combined "
                     "with it");
  SystemPoint sp;
  try {
    sp = ReadSystemPoint(args.Text("restart"), args.Text("point"));
  } catch (const RestartError& e) {
    const std::string opt = e.part() == RestartError::Part::kRun ? "restart" : "point";
    throw UsageError(args.Source(opt) + " " + args.Text(opt) + ": " + e.what());
  }
  const std::string run = args.Text("restart") + " is a run of --system " + sp.system;
  if (args.Given("system") && args.Text("system") != sp.system)
    throw UsageError(args.Source("system") + " " + args.Text("system") + ": " + run);
  if (args.Given("blocks") && args.Integer("blocks", 0) != sp.blocks)
    throw UsageError(args.Source("blocks") + " " + args.Text("blocks") + ": " + run +
                     (sp.blocks > 0 ? " of " + std::to_string(sp.blocks) + " blocks" : ""));
  if (!sp.periodic())
    throw UsageError(args.Source("point") + " " + args.Text("point") +
                     " is a point of steady sliding (branch 0): a system's restart starts on an "
                     "orbit (LP, PD, GR, CL, ... or a point number of branch 1 or 2)");
  return sp;
}

std::string DescribeSystemRestart(const Arguments& args, const SystemPoint& sp) {
  return args.Text("restart") + " point " + sp.label + " (pt " + std::to_string(sp.pt) + ", " +
         sp.type + ", " + sp.continued + " = " + FormatNumber(sp.p) + ")";
}

void AddRestartMetadata(const System& s, SystemChoice choice, const Params& law,
                        const FlowOptions& flow, double max_amplitude,
                        const PoincareSection* section, Metadata& meta) {
  std::string parameters, coefficients;
  for (int j = 0; j < s.parameters(); ++j)
    parameters += (j ? "," : "") + s.ParameterName(j) + "=" + FormatNumber(s.ParameterValue(j));
  for (const std::string& name : ParameterNames(law.law))
    coefficients +=
        (coefficients.empty() ? "" : ",") + name + "=" + FormatNumber(GetParameter(law, name));
  meta.emplace_back("system_name", Name(choice));
  if (choice == SystemChoice::kChain) meta.emplace_back("blocks", std::to_string(s.contacts()));
  if (choice != SystemChoice::kModel)  // a model file's laws are its own: in its parameters
    meta.insert(meta.end(), {{"law", Name(law.law)}, {"law_parameters", coefficients}});
  meta.insert(meta.end(), {{"parameters", parameters},
                           {"integrator", flow.integrator == Integrator::kCvode
                                              ? std::string("cvode ") + Name(flow.method)
                                              : std::string(Name(flow.integrator))},
                           {"max_steps", std::to_string(flow.max_steps)},
                           {"max_amplitude", FormatNumber(max_amplitude)}});
  if (!section) return;
  if (section->kind == SectionKind::kTime) {  // a clock's: m turns
    meta.emplace_back("section_turns", std::to_string(section->turns));
    return;
  }
  meta.insert(meta.end(), {{"section_contact", std::to_string(section->contact)},
                           {"section_returns", std::to_string(section->returns)}});
}

}  // namespace stickslip::cli
