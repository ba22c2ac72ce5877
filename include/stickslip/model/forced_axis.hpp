// The forced model's lens: the parameter of ForcedParams a run continues or
// sweeps (the belt's is ParameterAxis, parameter_axis.hpp).
#pragma once

#include "stickslip/model/forced.hpp"
#include "stickslip/names.hpp"

namespace stickslip {

/// The continued parameter of the forced model.
enum class ForcedAxis { kOmega, kForce, kV, kBeta };
template <>
struct EnumNames<ForcedAxis> {
  static constexpr NamedValue<ForcedAxis> kTable[] = {
      {ForcedAxis::kOmega, "omega"},
      {ForcedAxis::kForce, "force"},
      {ForcedAxis::kV, "v"},
      {ForcedAxis::kBeta, "beta"},
  };
};
double GetAxis(const ForcedParams& p, ForcedAxis a);
void SetAxis(ForcedParams& p, ForcedAxis a, double value);

}  // namespace stickslip
