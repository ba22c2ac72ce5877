// The one place where the library's numerical thresholds are defined. Every
// threshold a computation uses is a field here, derived from the user's rtol
// and atol (or a documented absolute floor); no other file holds a bare
// threshold literal (issue 19). docs/theory.md lists them.
#pragma once

#include <algorithm>

namespace stickslip {

struct Tolerances {
  double rtol = 1e-10;
  double atol = 1e-13;

  static Tolerances From(double rtol, double atol) {
    Tolerances t;
    t.rtol = rtol;
    t.atol = atol;
    return t;
  }

  // --- Integration, events and orbits (flow, steppers, shooting) ---
  /// Forced flow, slip leaving x' = v at a stick exit: x'' there below this
  /// times the state's scale is rounding (64 machine epsilons; rtol-free).
  static constexpr double SurfaceRounding() { return 64 * 2.220446049250313e-16; }

  // --- Continuation, charts and basins ---
  /// PALC corrector stopping tolerance: max(1e-13, 10 rtol) (issue 23).
  double Corrector() const { return std::max(1e-13, 10 * rtol); }
  /// Forced branches: a slip phase shorter than this fraction of the orbit's
  /// period at a located sliding point is the one adding-sliding creates
  /// (its length grows like sqrt(|p - p*|) <= 1e-5 within 1e-10; issue 20).
  double VanishingPhase() const { return 1e-4; }
  /// Forced branches: a crossing of x' = v this close to the stick band's edge
  /// (times 1 + the orbit's width) is on it at a located sliding point.
  double BandEdge() const { return std::max(1e-8, 1e3 * rtol); }
  /// Forced basins (chaos/forced_basin.hpp): stroboscopic points of one
  /// periodic cycle agree to this, relative to 1 + |z|: max(1e-6, 1e3 rtol).
  double SectionCycle() const { return std::max(1e-6, 1e3 * rtol); }
  /// ... and two periodic attractors are one if their points agree to max(1e-4, 1e5 rtol).
  double SameAttractor() const { return std::max(1e-4, 1e5 * rtol); }
  /// A start is chaotic if its largest exponent exceeds max(3 err, this floor) (1 / time).
  double ChaoticExponentFloor() const { return 1e-3; }
};

}  // namespace stickslip
