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

  // --- Continuation, charts and basins ---
  /// PALC corrector stopping tolerance: max(1e-13, 10 rtol) (issue 23).
  double Corrector() const { return std::max(1e-13, 10 * rtol); }
  /// A branch is on a range end when within on_end * scale of it (a floor
  /// near the double precision of p, not a tolerance).
  double on_end = 1e-13;
};

}  // namespace stickslip
