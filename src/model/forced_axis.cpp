// The forced model's lens (stickslip/model/forced_axis.hpp).
#include "stickslip/model/forced_axis.hpp"

namespace stickslip {

double GetAxis(const ForcedParams& p, ForcedAxis a) {
  switch (a) {
    case ForcedAxis::kOmega:
      return p.omega;
    case ForcedAxis::kForce:
      return p.force;
    case ForcedAxis::kV:
      return p.base.v;
    case ForcedAxis::kBeta:
      return p.base.beta;
  }
  return 0;
}

void SetAxis(ForcedParams& p, ForcedAxis a, double value) {
  switch (a) {
    case ForcedAxis::kOmega:
      p.omega = value;
      return;
    case ForcedAxis::kForce:
      p.force = value;
      return;
    case ForcedAxis::kV:
      p.base.v = value;
      return;
    case ForcedAxis::kBeta:
      p.base.beta = value;
      return;
  }
}

}  // namespace stickslip
