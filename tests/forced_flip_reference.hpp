// det(Phi + I) of the forced oscillator's m = 1 orbit on the independent
// long-double stroboscopic map (reference/forced_lyapunov.hpp, RKF78): the
// reference for period doublings (tests/forced/forced_flip_test.cpp,
// tests/continuation/orbit_branch_test.cpp).
#pragma once

#include <cmath>

#include "reference/forced_lyapunov.hpp"
#include "stickslip/systems/forced/forced.hpp"

namespace stickslip::forced_reference {

using reference::LReal;

// det(Phi + I) at the reference map's fixed point near (x, y), which it
// updates; ok false if Newton fails or the orbit has no single stick.
inline LReal RefFlip(const ForcedBeltParams& p, LReal* x, LReal* y, bool* ok) {
  const reference::ForcedRef m(p);
  for (int it = 0; it < 30; ++it) {
    const reference::RefPeriod r = reference::RefOnePeriod(m, *x, *y, false, 1e-17L);
    *ok = r.ok && r.sticks == 1 && !r.stuck;
    if (!*ok) return 0;
    const LReal a = r.phi[0][0] - 1, b = r.phi[0][1], c = r.phi[1][0], d = r.phi[1][1] - 1;
    const LReal fx = r.x - *x, fy = r.y - *y, det = a * d - b * c;
    const LReal dx = -(d * fx - b * fy) / det, dy = -(-c * fx + a * fy) / det;
    *x += dx, *y += dy;
    if (std::abs(dx) + std::abs(dy) < 1e-16L)
      return (r.phi[0][0] + 1) * (r.phi[1][1] + 1) - r.phi[0][1] * r.phi[1][0];
  }
  *ok = false;
  return 0;
}

}  // namespace stickslip::forced_reference
