// The continued parameter: a name resolved once to the member of Params it
// stands for, so that a point on the axis is one assignment.
#pragma once

#include <string>

#include "stickslip/model/params.hpp"

namespace stickslip {

/// The continued parameter by name, resolved once to its member of Params.
class ParameterAxis {
 public:
  /// Throws InvalidArgument naming the string if it is no parameter.
  explicit ParameterAxis(const std::string& name) : name_(name), member_(ParameterMember(name)) {}

  const std::string& name() const { return name_; }
  bool operator==(const ParameterAxis& o) const { return member_ == o.member_; }
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
  std::string name_;
  double Params::*member_;
};

}  // namespace stickslip
