// The model and the solver options from parsed arguments (study.hpp).
#include <cmath>
#include <string>
#include <vector>

#include "cli/study.hpp"
#include "stickslip/io/report.hpp"
#include "stickslip/systems/belt/parameter_axis.hpp"

namespace stickslip::cli {

namespace {

// Physical inputs and the dimensionless parameters they replace.
const std::vector<std::string> kPhysical = {"mass",    "damping", "stiffness", "belt_speed",
                                            "gravity", "speed_m", "speed_s",   "delta_phys"};
const std::vector<std::string> kScaled = {"beta", "v", "v_m", "v_s", "delta", "k5"};

// A validation message "name = value ..." with where the named value came from.
std::string WithOrigin(const Arguments& args, const std::string& err) {
  const std::string name = err.substr(0, err.find(" = "));
  if (name.size() == err.size() || !args.Given(name)) return err;
  return err + " (from " + args.Origin(name) + ")";
}

std::string FirstGiven(const Arguments& args, const std::vector<std::string>& names) {
  for (const auto& n : names)
    if (args.Given(n)) return n;
  return "";
}

// A value given for a parameter the law does not use is validated as its
// own law would (so --v_s -1 is refused with the cubic law too).
void CheckOtherLaws(const Arguments& args, const Params& p) {
  const std::map<std::string, std::string> physical = {
      {"v_m", "speed_m"}, {"v_s", "speed_s"}, {"delta", "delta_phys"}};
  for (LawKind law : {LawKind::kCubic, LawKind::kCoulomb, LawKind::kStribeck, LawKind::kLeine}) {
    if (law == p.law) continue;
    const auto names = ParameterNames(law);
    bool given = false;
    for (std::size_t i = 3; i < names.size(); ++i) {  // past beta, v, mu_s
      const auto it = physical.find(names[i]);
      given = given || args.Given(names[i]) || (it != physical.end() && args.Given(it->second));
    }
    if (!given) continue;
    Params q = p;
    q.law = law;
    const std::string err = ValidationError(q);
    if (!err.empty())
      throw UsageError("invalid model: " + WithOrigin(args, err) + " (a " + Name(law) +
                       " parameter, unused by the " + Name(p.law) + " law)");
  }
}

}  // namespace

Params ModelFromArguments(const Arguments& args) { return ModelFromArguments(args, "", 0.0); }

Params ModelFromArguments(const Arguments& args, const std::string& continued, double at,
                          const Params& defaults) {
  const Params p = UncheckedModelFromArguments(args, defaults);
  Params checked = p;
  if (!continued.empty() && IsParameterName(continued)) SetParameter(checked, continued, at);
  const std::string err = ValidationError(checked);
  if (!err.empty()) throw UsageError("invalid model: " + WithOrigin(args, err));
  CheckOtherLaws(args, checked);
  // A value given for the continued parameter is not where the branch runs,
  // but it is a model the user stated (and sets its default range): it must
  // be valid too (--param v --v -1 is refused).
  if (!continued.empty() && args.Given(continued)) {
    const std::string given = ValidationError(p);
    if (!given.empty())
      throw UsageError("invalid model: " + WithOrigin(args, given) + " (" + args.Source(continued) +
                       " is the continued parameter's base value; " +
                       "the branch runs over --from and --to)");
  }
  return p;
}

Params UncheckedModelFromArguments(const Arguments& args, const Params& defaults) {
  LawKind law = defaults.law;
  if (args.Given("law")) {
    try {
      law = LawFromName(args.Text("law"));
    } catch (const InvalidArgument& e) {
      throw UsageError(args.Source("law") + ": " + e.what());
    }
  }
  const std::string physical = FirstGiven(args, kPhysical);
  Params p = defaults;
  if (physical.empty()) {
    p.law = law;
    for (const auto& name : AllParameterNames())
      if (const auto x = args.OptionalNumber(name)) SetParameter(p, name, *x);
  } else {
    const std::string scaled = FirstGiven(args, kScaled);
    if (!scaled.empty())
      throw UsageError(args.Source(scaled) + " is dimensionless and cannot be combined with " +
                       "the physical inputs (" + args.Source(physical) + " given)");
    std::vector<std::string> required = {"mass", "damping", "stiffness", "belt_speed"};
    if (law == LawKind::kCubic) required.push_back("speed_m");
    if (law == LawKind::kStribeck) required.push_back("speed_s");
    if (law == LawKind::kLeine) required.push_back("delta_phys");
    for (const auto& name : required)
      if (!args.Given(name))
        throw UsageError("physical inputs (" + args.Source(physical) + " given) need --" + name +
                         " for the " + Name(law) + " law");
    PhysicalParams phys;
    phys.law = law;
    phys.mass = args.Number("mass", phys.mass);
    phys.damping = args.Number("damping", phys.damping);
    phys.stiffness = args.Number("stiffness", phys.stiffness);
    phys.belt_speed = args.Number("belt_speed", phys.belt_speed);
    phys.gravity = args.Number("gravity", phys.gravity);
    phys.speed_m = args.Number("speed_m", phys.speed_m);
    phys.speed_s = args.Number("speed_s", phys.speed_s);
    phys.delta = args.Number("delta_phys", phys.delta);
    phys.mu_s = args.Number("mu_s", p.mu_s);
    phys.mu_m = args.Number("mu_m", p.mu_m);
    phys.mu_k = args.Number("mu_k", p.mu_k);
    try {
      p = ToDimensionless(phys);
    } catch (const InvalidArgument& e) {
      throw UsageError("invalid physical inputs: " + WithOrigin(args, e.what()));
    }
  }
  return p;
}

FlowOptions FlowOptionsFromArguments(const Arguments& args, const FlowOptions& defaults) {
  FlowOptions f = defaults;
  f.rtol = args.Number("rtol", f.rtol);
  f.atol = args.Number("atol", f.atol);
  f.max_steps = args.Integer("max_steps", f.max_steps);
  if (args.Given("integrator")) {
    const std::string i = args.Text("integrator");
    if (i == "taylor") {
      f.integrator = Integrator::kTaylor;
    } else if (i == "cvode") {
      f.integrator = Integrator::kCvode;
    } else {
      throw UsageError("invalid value '" + i + "' for " + args.Source("integrator") +
                       ": expected taylor or cvode");
    }
  }
  if (args.Given("method")) {
    const std::string m = args.Text("method");
    if (m == "adams") {
      f.method = Method::kAdams;
    } else if (m == "bdf") {
      f.method = Method::kBdf;
    } else {
      throw UsageError("invalid value '" + m + "' for " + args.Source("method") +
                       ": expected adams or bdf");
    }
  }
  const std::string err = f.ValidationError();
  if (!err.empty()) throw UsageError("invalid solver options: " + WithOrigin(args, err));
  return f;
}

ParameterAxis AxisFromArguments(const Arguments& args, const char* key, const std::string& fallback,
                                LawKind law, bool forced) {
  const std::string name = args.Text(key, fallback);
  const std::vector<ParameterAxis> axes = ParameterAxes(law, forced);
  std::string list;
  for (size_t i = 0; i < axes.size(); ++i) {
    if (axes[i].name() == name) return axes[i];
    list += (i == 0 ? "" : i + 1 == axes.size() ? " or " : ", ") + axes[i].name();
  }
  // Not given: the default came from elsewhere (a restart's continued parameter).
  const std::string what =
      args.Given(key) ? "invalid value '" + name + "' for " + args.Source(key)
                      : "--" + std::string(key) + " defaults to '" + name + "' here (give another)";
  throw UsageError(what + ": the " + (forced ? "forced oscillator's" : "oscillator's") +
                   " parameters under the " + Name(law) + " law are " + list);
}

void CheckForcedBelt(const Arguments& args, const ForcedBeltParams& p, const std::string& where,
                     const std::string& swept) {
  const std::string err = ValidationError(p);
  if (err.empty()) return;
  const std::string name = err.substr(0, err.find(' '));
  throw UsageError("invalid forced model" + where + ": " + err +
                   (name != swept && args.Given(name) ? " (from " + args.Origin(name) + ")" : ""));
}

std::string DescribeModel(const Params& p) { return DescribeModel(p, "", 0, 0); }

std::string DescribeModel(const Params& p, const std::string& continued, double from, double to) {
  std::string s = std::string("law=") + Name(p.law);
  for (const auto& name : ParameterNames(p.law))
    s += " " + name + "=" +
         (name == continued ? "[" + FormatNumber(from) + ", " + FormatNumber(to) + "]"
                            : FormatNumber(GetParameter(p, name)));
  return s;
}

}  // namespace stickslip::cli
