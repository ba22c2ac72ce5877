// Parameters of the dimensionless belt model, seed eq. (3.5), by name.
#pragma once

#include <string>
#include <vector>

#include "stickslip/names.hpp"

namespace stickslip {

/// Friction laws mu(s), s = |x' - v| (seed eq. 3.3 and the table of laws in docs/theory.md).
enum class LawKind {
  kCubic,     // mu_s - k1 s + k3 s^3 - k5 s^5, seed eq. (3.3) (k5 = 0), Thomsen & Fidlin (2003)
  kCoulomb,   // mu_k for s > 0, static mu_s
  kStribeck,  // mu_k + (mu_s - mu_k) exp(-s / v_s)
  kLeine,     // mu_s / (1 + delta s), Leine et al. (1998)
};

template <>
struct EnumNames<LawKind> {
  static constexpr NamedValue<LawKind> kTable[] = {
      {LawKind::kCubic, "cubic"},
      {LawKind::kCoulomb, "coulomb"},
      {LawKind::kStribeck, "stribeck"},
      {LawKind::kLeine, "leine"},
  };
};
/// Throws InvalidArgument naming the string if it is no law.
LawKind LawFromName(const std::string& name);

/// All dimensionless. Defaults are the seed set (section 4 of the seed):
/// beta 0.05, v 0.25, mu_s 0.4, mu_m 0.25, v_m 0.5, so k1 = 0.45, k3 = 0.6.
struct Params {
  LawKind law = LawKind::kCubic;
  double beta = 0.05;  // damping ratio, 2 beta = C / sqrt(K M)
  double v = 0.25;     // belt speed
  double mu_s = 0.4;   // static friction coefficient
  double mu_m = 0.25;  // cubic: minimum of mu(s) ...
  double v_m = 0.5;    // cubic: ... reached at s = v_m
  double mu_k = 0.25;  // coulomb, stribeck: kinetic coefficient
  double v_s = 0.5;    // stribeck: decay speed
  double delta = 3.0;  // leine: decay rate
  double k5 = 0.0;     // cubic: optional quintic term -k5 s^5, k5 >= 0

  /// Cubic law coefficients, seed section 3: k1 = 3(mu_s - mu_m)/(2 v_m),
  /// k3 = (mu_s - mu_m)/(2 v_m^3).
  double k1() const;
  double k3() const;
};

/// The parameters of the friction oscillators by name, in the order of their
/// System parameter indexes: the belt's (the members of Params), then the
/// forcing's (force A and omega, ForcedBeltParams). EnumNames<Parameter> is the
/// one table of their printed names (options, TSV columns and metadata).
enum class Parameter { kBeta, kV, kMuS, kMuM, kVM, kMuK, kVS, kDelta, kK5, kForce, kOmega };
template <>
struct EnumNames<Parameter> {
  static constexpr NamedValue<Parameter> kTable[] = {
      {Parameter::kBeta, "beta"},   {Parameter::kV, "v"},         {Parameter::kMuS, "mu_s"},
      {Parameter::kMuM, "mu_m"},    {Parameter::kVM, "v_m"},      {Parameter::kMuK, "mu_k"},
      {Parameter::kVS, "v_s"},      {Parameter::kDelta, "delta"}, {Parameter::kK5, "k5"},
      {Parameter::kForce, "force"}, {Parameter::kOmega, "omega"}};
};
/// The belt's parameters: the first kBeltParameters of Parameter.
inline constexpr int kBeltParameters = 9;
/// A parameter of the forcing (force, omega): not one of Params.
inline bool IsForcing(Parameter p) { return static_cast<int>(p) >= kBeltParameters; }
/// The member of Params a belt parameter stands for; throws InvalidArgument
/// for a forcing parameter.
double Params::*ParameterMember(Parameter p);

/// Names of the parameters that apply to a law, in a fixed order:
/// beta, v, mu_s, then the law's own (cubic: mu_m, v_m, k5; coulomb: mu_k;
/// stribeck: mu_k, v_s; leine: delta).
std::vector<std::string> ParameterNames(LawKind law);
/// Every parameter name any law of the belt knows (not the forcing's).
std::vector<std::string> AllParameterNames();
/// True for any name in AllParameterNames() (the belt's: not force, omega).
bool IsParameterName(const std::string& name);
/// "beta, v, mu_s, mu_m, v_m, mu_k, v_s, delta or k5", for messages.
std::string ParameterNameList();
/// The member of Params a name stands for; throws InvalidArgument on an unknown name.
double Params::*ParameterMember(const std::string& name);

class ParameterAxis;  // parameter_axis.hpp

/// A continuation range of one parameter.
struct ParameterRange {
  double from = 0;
  double to = 0;
};
/// The default range of a parameter around the model `base`, valid at both
/// ends for base's other values: beta 0.01 -> 0.3, v 0.05 -> 0.5, mu_s from
/// 1.2 x (mu_m or mu_k) to 2 mu_s, mu_m and mu_k 0.2 -> 0.9 x mu_s, the
/// speeds v_m, v_s and delta 0.5 -> 2 x their base value, k5 0 -> max(1,
/// 2 k5). Throws
/// InvalidArgument on an unknown name.
ParameterRange DefaultRange(const Params& base, const ParameterAxis& axis);
/// A range that starts at `at`'s value of the parameter and runs to the far
/// end of DefaultRange(at, name): a restart's branch (AUTO-07p's IRS).
ParameterRange RangeFromPoint(const Params& at, const ParameterAxis& axis);

/// Get or set by name; throw InvalidArgument on an unknown name.
double GetParameter(const Params& p, const std::string& name);
void SetParameter(Params& p, const std::string& name, double value);

/// Every nonzero parameter of a law must lie in [kMinScale, kMaxScale] (k5 in
/// [0, kMaxScale]): beyond, the cubic law's k3 or the state over- or underflow
/// (nan or inf results).
constexpr double kMinScale = 1e-6, kMaxScale = 1e6;

/// Returns an empty string if p is a valid model, otherwise one line naming
/// the offending value, e.g. "mu_m = 0.5 must be < mu_s = 0.4".
std::string ValidationError(const Params& p);
/// Throws InvalidArgument with ValidationError(p) if it is not empty.
void Validate(const Params& p);

/// The belt parameters plus a harmonic forcing A cos(Omega t) (forced.hpp).
/// Here v >= 0 (v = 0: a fixed floor) and the coulomb law may have mu_k =
/// mu_s (Den Hartog).
struct ForcedBeltParams {
  Params base;
  double force = 0;  ///< A, in the unit of the friction coefficients
  double omega = 1;  ///< Omega, forcing over natural frequency
};

/// Empty if valid, else one line naming the offending value.
std::string ValidationError(const ForcedBeltParams& p);

/// The forced oscillator's default range of a parameter: omega 0.75 -> 2.5,
/// force 0.1 -> 2, v 0 -> 0.5 (from the fixed floor), beta 0 -> 0.3, the
/// others as the belt's (DefaultRange above).
ParameterRange DefaultRange(const ForcedBeltParams& base, const ParameterAxis& axis);

/// Physical inputs and the seed's scaling (section 3): L = M g / K,
/// omega0 = sqrt(K / M), t0 = 1 / omega0, 2 beta = C / sqrt(K M),
/// v = V t0 / L. Speeds scale by L omega0; friction coefficients are unchanged.
struct PhysicalParams {
  LawKind law = LawKind::kCubic;
  double mass = 1.0;         // M [kg]
  double damping = 0.1;      // C [N s / m]
  double stiffness = 1.0;    // K [N / m]
  double belt_speed = 0.25;  // V [m / s]
  double gravity = 9.81;     // g [m / s^2]
  double mu_s = 0.4;
  double mu_m = 0.25;
  double speed_m = 0.5;  // cubic: V_m [m / s], speed of minimum friction
  double mu_k = 0.25;
  double speed_s = 0.5;  // stribeck: V_s [m / s]
  double delta = 3.0;    // leine: [s / m]
};

/// Throws InvalidArgument if a physical input is not finite or not positive
/// where it must be.
Params ToDimensionless(const PhysicalParams& phys);
/// The inverse, for given mass, stiffness and gravity.
PhysicalParams ToPhysical(const Params& p, double mass, double stiffness, double gravity);

/// Length and time scales of the seed's scaling.
double LengthScale(double mass, double stiffness, double gravity);  // L = M g / K
double TimeScale(double mass, double stiffness);                    // t0 = sqrt(M / K)

}  // namespace stickslip
