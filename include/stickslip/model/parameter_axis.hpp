// A parameter of the belt model as a type: the continued parameter, a chart's
// axes, the parameter column. Resolved once to the member of Params it stands
// for, so that a point on the axis is one assignment. Names are read and
// written at the edges only (options, files: EnumNames<Parameter>).
#pragma once

#include <ostream>
#include <string>

#include "stickslip/model/params.hpp"

namespace stickslip {

/// One parameter of Params.
class ParameterAxis {
 public:
  ParameterAxis(Parameter id) : id_(id), member_(ParameterMember(id)) {}  // NOLINT: implicit
  /// By name (an option or a file); throws InvalidArgument naming the string if it is no parameter.
  explicit ParameterAxis(const std::string& name) : member_(ParameterMember(name)) {
    FromName(name, &id_);
  }

  Parameter id() const { return id_; }
  /// The printed name (EnumNames<Parameter>).
  std::string name() const { return Name(id_); }
  bool operator==(const ParameterAxis& o) const { return id_ == o.id_; }
  bool operator!=(const ParameterAxis& o) const { return !(*this == o); }
  double Get(const Params& p) const { return p.*member_; }
  void Set(Params& p, double value) const { p.*member_ = value; }
  /// base with this parameter set to value.
  Params At(const Params& base, double value) const {
    Params q = base;
    Set(q, value);
    return q;
  }

 private:
  Parameter id_ = Parameter::kV;
  double Params::*member_;
};

/// Writes the printed name.
inline std::ostream& operator<<(std::ostream& os, const ParameterAxis& a) { return os << a.name(); }

/// The parameters that apply to a law, in ParameterNames(law)'s order.
std::vector<ParameterAxis> ParameterAxes(LawKind law);

}  // namespace stickslip
