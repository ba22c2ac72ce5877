#include "stickslip/systems/belt/params.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>

#include "numerics/numbers.hpp"
#include "stickslip/errors.hpp"
#include "stickslip/systems/belt/parameter_axis.hpp"

namespace stickslip {

LawKind LawFromName(const std::string& name) {
  LawKind k;
  if (FromName(name, &k)) return k;
  throw InvalidArgument("unknown friction law '" + name +
                        "' (expected cubic, coulomb, stribeck or leine)");
}

double Params::k1() const { return 3.0 * (mu_s - mu_m) / (2.0 * v_m); }
double Params::k3() const { return (mu_s - mu_m) / (2.0 * v_m * v_m * v_m); }

std::vector<std::string> ParameterNames(LawKind law) {
  std::vector<std::string> names = {"beta", "v", "mu_s"};
  switch (law) {
    case LawKind::kCubic:
      names.insert(names.end(), {"mu_m", "v_m", "k5"});
      break;
    case LawKind::kCoulomb:
      names.insert(names.end(), {"mu_k"});
      break;
    case LawKind::kStribeck:
      names.insert(names.end(), {"mu_k", "v_s"});
      break;
    case LawKind::kLeine:
      names.insert(names.end(), {"delta"});
      break;
  }
  return names;
}

namespace {
// The member each parameter (EnumNames<Parameter> order) stands for.
constexpr double Params::*kMembers[] = {&Params::beta, &Params::v,     &Params::mu_s,
                                        &Params::mu_m, &Params::v_m,   &Params::mu_k,
                                        &Params::v_s,  &Params::delta, &Params::k5};
static_assert(std::size(kMembers) == kBeltParameters);
}  // namespace

double Params::*ParameterMember(Parameter p) {
  if (IsForcing(p))
    throw InvalidArgument(std::string(Name(p)) +
                          " is a parameter of the forcing: the belt oscillator has none");
  return kMembers[static_cast<int>(p)];
}

std::vector<std::string> AllParameterNames() {
  std::vector<std::string> names;
  for (int i = 0; i < kBeltParameters; ++i) names.push_back(EnumNames<Parameter>::kTable[i].name);
  return names;
}

namespace {
// "beta, v, ... or k5": the first n names of EnumNames<Parameter>.
std::string NameList(size_t n) {
  std::string list;
  for (size_t i = 0; i < n; ++i)
    list += std::string(i == 0       ? ""
                        : i + 1 == n ? " or "
                                     : ", ") +
            EnumNames<Parameter>::kTable[i].name;
  return list;
}
}  // namespace

std::string ParameterNameList() { return NameList(kBeltParameters); }

double Params::*ParameterMember(const std::string& name) {
  Parameter p;
  if (FromName(name, &p) && !IsForcing(p)) return ParameterMember(p);
  throw InvalidArgument("unknown parameter '" + name + "' (expected one of " + ParameterNameList() +
                        ")");
}

bool IsParameterName(const std::string& name) {
  Parameter p;
  return FromName(name, &p) && !IsForcing(p);
}

double GetParameter(const Params& p, const std::string& name) { return p.*ParameterMember(name); }

void SetParameter(Params& p, const std::string& name, double value) {
  p.*ParameterMember(name) = value;
}

namespace {
// The quintic term: k5 >= 0, and mu > 0 at the steady state's slip speed v.
std::string QuinticError(const Params& p) {
  if (p.k5 < 0) return "k5 = " + Num(p.k5, 12) + " must be >= 0";
  const double v = p.v, mu = p.mu_s - p.k1() * v + p.k3() * v * v * v - p.k5 * std::pow(v, 5);
  if (!(mu > 0))
    return "k5 = " + Num(p.k5, 12) + " makes mu(v) = " + Num(mu, 12) +
           " <= 0 at the belt speed v = " + Num(v, 12) + " (steady sliding is not physical)";
  return "";
}
}  // namespace

ParameterRange DefaultRange(const Params& base, const ParameterAxis& axis) {
  if (axis.forcing()) throw InvalidArgument(AxisError(axis, base.law));
  const double x = axis.Get(base);
  switch (axis.id()) {
    case Parameter::kBeta:
      return {0.01, 0.3};
    case Parameter::kV:
      return {0.05, 0.5};
    case Parameter::kMuS:
      return {1.2 * (base.law == LawKind::kCubic ? base.mu_m : base.mu_k), 2.0 * base.mu_s};
    case Parameter::kMuM:
    case Parameter::kMuK:
      return {0.2 * base.mu_s, 0.9 * base.mu_s};
    case Parameter::kK5:
      return {0.0, std::max(1.0, 2.0 * x)};
    default:
      return {0.5 * x, 2.0 * x};  // v_m, v_s, delta: a factor of two each way
  }
}

ParameterRange DefaultRange(const ForcedBeltParams& base, const ParameterAxis& axis) {
  switch (axis.id()) {
    case Parameter::kOmega:
      return {0.75, 2.5};
    case Parameter::kForce:
      return {0.1, 2};
    case Parameter::kV:
      return {0, 0.5};
    case Parameter::kBeta:
      return {0, 0.3};
    default:
      return DefaultRange(base.base, axis);
  }
}

ParameterRange RangeFromPoint(const Params& at, const ParameterAxis& axis) {
  const ParameterRange r = DefaultRange(at, axis);
  const double x = axis.Get(at);
  return {x, std::abs(r.to - x) >= std::abs(r.from - x) ? r.to : r.from};
}

ParameterAxis::ParameterAxis(const std::string& name) {
  if (!FromName(name, &id_))
    throw InvalidArgument("unknown parameter '" + name + "' (expected one of " +
                          NameList(NameCount<Parameter>()) + ")");
  member_ = IsForcing(id_) ? nullptr : ParameterMember(id_);
}

void ParameterAxis::ForcingOnBelt() const {
  throw InvalidArgument(name() + " is a parameter of the forcing: the belt oscillator has none");
}

std::vector<ParameterAxis> ParameterAxes(LawKind law, bool forced) {
  std::vector<ParameterAxis> axes;
  for (const std::string& name : ParameterNames(law)) axes.emplace_back(name);
  if (forced) axes.insert(axes.end(), {Parameter::kForce, Parameter::kOmega});
  return axes;
}

std::string AxisError(const ParameterAxis& axis, LawKind law, bool forced) {
  if (forced && axis.forcing()) return "";
  const auto names = ParameterNames(law);
  if (std::find(names.begin(), names.end(), axis.name()) != names.end()) return "";
  return "parameter '" + axis.name() + "' does not apply to the " +
         (forced ? "forced oscillator" : std::string(Name(law)) + " law") +
         (forced ? " under the " + std::string(Name(law)) + " law" : std::string());
}

namespace {
// ParameterAxes(law), built once per law: ValidationError runs for every
// Model (every continuation row), where looking the members up by their
// names cost more than the checks.
const std::vector<ParameterAxis>& LawAxes(LawKind law) {
  static const std::vector<ParameterAxis> cubic = ParameterAxes(LawKind::kCubic),
                                          coulomb = ParameterAxes(LawKind::kCoulomb),
                                          stribeck = ParameterAxes(LawKind::kStribeck),
                                          leine = ParameterAxes(LawKind::kLeine);
  switch (law) {
    case LawKind::kCoulomb:
      return coulomb;
    case LawKind::kStribeck:
      return stribeck;
    case LawKind::kLeine:
      return leine;
    case LawKind::kCubic:
      break;
  }
  return cubic;
}
}  // namespace

std::string ValidationError(const Params& p) {
  const std::vector<ParameterAxis>& axes = LawAxes(p.law);
  for (const ParameterAxis& a : axes) {
    const double x = a.Get(p);
    if (!std::isfinite(x)) return a.name() + " = " + Num(x, 12) + " is not a finite number";
  }
  if (p.beta < 0) return "beta = " + Num(p.beta, 12) + " must be >= 0";
  if (p.v <= 0) return "v = " + Num(p.v, 12) + " must be > 0";
  if (p.mu_s <= 0) return "mu_s = " + Num(p.mu_s, 12) + " must be > 0";
  switch (p.law) {
    case LawKind::kCubic:
      if (p.mu_m <= 0) return "mu_m = " + Num(p.mu_m, 12) + " must be > 0";
      if (p.mu_m >= p.mu_s)
        return "mu_m = " + Num(p.mu_m, 12) + " must be < mu_s = " + Num(p.mu_s, 12);
      if (p.v_m <= 0) return "v_m = " + Num(p.v_m, 12) + " must be > 0";
      if (p.k5 < 0) return "k5 = " + Num(p.k5, 12) + " must be >= 0";
      break;
    case LawKind::kCoulomb:
    case LawKind::kStribeck:
      if (p.mu_k <= 0) return "mu_k = " + Num(p.mu_k, 12) + " must be > 0";
      if (p.mu_k >= p.mu_s)
        return "mu_k = " + Num(p.mu_k, 12) + " must be < mu_s = " + Num(p.mu_s, 12);
      if (p.law == LawKind::kStribeck && p.v_s <= 0)
        return "v_s = " + Num(p.v_s, 12) + " must be > 0";
      break;
    case LawKind::kLeine:
      if (p.delta < 0) return "delta = " + Num(p.delta, 12) + " must be >= 0";
      break;
  }
  // Beyond these scales k3 = (mu_s - mu_m) / (2 v_m^3) and the state over- or
  // underflow and the results would be nan or inf.
  // A small quintic coefficient k5 or damping ratio beta is harmless (beta = 0
  // is the undamped oscillator): only their upper end counts.
  for (const ParameterAxis& a : axes) {
    const double x = a.Get(p);
    const double lo = a.id() == Parameter::kK5 || a.id() == Parameter::kBeta ? 0.0 : kMinScale;
    if (x != 0 && !(x >= lo && x <= kMaxScale))
      return a.name() + " = " + Num(x) + " is outside [" + Num(lo) + ", " + Num(kMaxScale) +
             "]: scales beyond it make the computation meaningless";
  }
  // After the scales: a subnormal v_m overflows k3, and mu(v) would be nan.
  if (p.law == LawKind::kCubic) return QuinticError(p);
  return "";
}

void Validate(const Params& p) {
  const std::string err = ValidationError(p);
  if (!err.empty()) throw InvalidArgument(err);
}

double LengthScale(double mass, double stiffness, double gravity) {
  return mass * gravity / stiffness;
}
double TimeScale(double mass, double stiffness) { return std::sqrt(mass / stiffness); }

namespace {
void RequirePositive(const char* name, double x) {
  if (!std::isfinite(x) || x <= 0)
    throw InvalidArgument(std::string(name) + " = " + Num(x, 12) + " must be a finite number > 0");
}
}  // namespace

Params ToDimensionless(const PhysicalParams& phys) {
  RequirePositive("mass", phys.mass);
  RequirePositive("stiffness", phys.stiffness);
  RequirePositive("gravity", phys.gravity);
  if (!std::isfinite(phys.damping) || phys.damping < 0)
    throw InvalidArgument("damping = " + Num(phys.damping, 12) + " must be a finite number >= 0");
  const double L = LengthScale(phys.mass, phys.stiffness, phys.gravity);
  const double t0 = TimeScale(phys.mass, phys.stiffness);
  const double speed = L / t0;  // V = v L / t0
  Params p;
  p.law = phys.law;
  p.beta = phys.damping / (2.0 * std::sqrt(phys.stiffness * phys.mass));
  p.v = phys.belt_speed / speed;
  p.mu_s = phys.mu_s;
  p.mu_m = phys.mu_m;
  p.v_m = phys.speed_m / speed;
  p.mu_k = phys.mu_k;
  p.v_s = phys.speed_s / speed;
  p.delta = phys.delta * speed;  // delta s is dimensionless
  return p;
}

PhysicalParams ToPhysical(const Params& p, double mass, double stiffness, double gravity) {
  RequirePositive("mass", mass);
  RequirePositive("stiffness", stiffness);
  RequirePositive("gravity", gravity);
  const double L = LengthScale(mass, stiffness, gravity);
  const double speed = L / TimeScale(mass, stiffness);
  PhysicalParams phys;
  phys.law = p.law;
  phys.mass = mass;
  phys.stiffness = stiffness;
  phys.gravity = gravity;
  phys.damping = 2.0 * p.beta * std::sqrt(stiffness * mass);
  phys.belt_speed = p.v * speed;
  phys.mu_s = p.mu_s;
  phys.mu_m = p.mu_m;
  phys.speed_m = p.v_m * speed;
  phys.mu_k = p.mu_k;
  phys.speed_s = p.v_s * speed;
  phys.delta = p.delta / speed;
  return phys;
}

}  // namespace stickslip
