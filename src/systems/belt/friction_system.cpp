// The one-contact systems' projection onto a stick exit (friction_system.hpp).
#include "stickslip/systems/belt/friction_system.hpp"

namespace stickslip {

// The exit point's x exactly into slip below (seed case 1: x0 = mu_s - 2
// beta v for the belt); else the root of the affine stick force.
void FrictionSystem::ProjectOnExit(const ModeSet&, int, double bound, StateOut z) const {
  if (bound == static_limit()) {
    z[0] = ExitPoint()[0];
    return;
  }
  const double slope = StickForce(z[0] + 1) - StickForce(z[0]);
  z[0] += (bound - StickForce(z[0])) / slope;
}

}  // namespace stickslip
