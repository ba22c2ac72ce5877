// A parameter of the friction oscillators as a type, the one lens: the
// continued parameter, a chart's axes, the parameter column, for the belt
// (Params) and the forced oscillator (ForcedBeltParams: the belt's and force,
// omega). Its index is the parameter's index in either System (model.hpp,
// forced.hpp). Resolved once to the member it stands for, so that a point on
// the axis is one assignment. Names are read and written at the edges only
// (options, files: EnumNames<Parameter>).
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "stickslip/systems/belt/params.hpp"

namespace stickslip {

/// One parameter of Params or ForcedBeltParams.
class ParameterAxis {
 public:
  ParameterAxis(Parameter id)  // NOLINT: implicit
      : id_(id), member_(IsForcing(id) ? nullptr : ParameterMember(id)) {}
  /// By name (an option or a file), force and omega included; throws
  /// InvalidArgument naming the string if it is no parameter.
  explicit ParameterAxis(const std::string& name);

  Parameter id() const { return id_; }
  /// The parameter's index in a System's parameters (Model, ForcedBelt).
  int index() const { return static_cast<int>(id_); }
  /// A parameter of the forcing (force, omega), which the belt has not.
  bool forcing() const { return member_ == nullptr; }
  /// The printed name (EnumNames<Parameter>).
  std::string name() const { return Name(id_); }
  bool operator==(const ParameterAxis& o) const { return id_ == o.id_; }
  bool operator!=(const ParameterAxis& o) const { return !(*this == o); }
  /// The belt's value; throws InvalidArgument on a forcing axis.
  double Get(const Params& p) const { return p.*Member(); }
  void Set(Params& p, double value) const { p.*Member() = value; }
  double Get(const ForcedBeltParams& p) const {
    return member_ ? p.base.*member_ : id_ == Parameter::kForce ? p.force : p.omega;
  }
  void Set(ForcedBeltParams& p, double value) const {
    (member_ ? p.base.*member_ : id_ == Parameter::kForce ? p.force : p.omega) = value;
  }
  /// base with this parameter set to value.
  template <class P>
  P At(const P& base, double value) const {
    P q = base;
    Set(q, value);
    return q;
  }

 private:
  double Params::*Member() const {
    if (!member_) ForcingOnBelt();
    return member_;
  }
  [[noreturn]] void ForcingOnBelt() const;
  Parameter id_ = Parameter::kV;
  double Params::*member_;
};

/// Writes the printed name.
inline std::ostream& operator<<(std::ostream& os, const ParameterAxis& a) { return os << a.name(); }

/// The parameters that apply to a law, in ParameterNames(law)'s order; with
/// `forced`, the forced oscillator's: then force and omega.
std::vector<ParameterAxis> ParameterAxes(LawKind law, bool forced = false);
/// Empty if `axis` is one of ParameterAxes(law, forced), else one line:
/// "parameter 'mu_m' does not apply to the coulomb law".
std::string AxisError(const ParameterAxis& axis, LawKind law, bool forced = false);

}  // namespace stickslip
