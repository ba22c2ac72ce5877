// The Newton stall test, one for every Newton loop (the PALC corrector,
// pure-slip shooting): a step that is near the tolerance but no longer
// shrinks is at the noise floor of the residual (Tolerances::kStallBand).
#pragma once

#include <cmath>

#include "numerics/tolerances.hpp"

namespace stickslip {

// step, last_step: |Newton step| now and one iteration before; iteration
// counts from 1; tol: the convergence tolerance on the step.
inline bool NewtonStalled(double step, double last_step, int iteration, double tol) {
  return iteration >= Tolerances::kStallFirstIteration && step < Tolerances::kStallBand * tol &&
         step > Tolerances::kStallRatio * last_step;
}

// The stop of every corrector (PALC's, Newton2): converged below tol, or
// stalled (NewtonStalled, then *stalled is set).
inline bool NewtonConverged(double step, double last_step, int iteration, double tol,
                            bool* stalled) {
  *stalled = NewtonStalled(step, last_step, iteration, tol) && !(step < tol);
  return step < tol || *stalled;
}

// The one stall guard of the flow: events (roots in a segment, switches in a
// run) that keep coming at one t, to rounding, would loop for ever, so more
// than `limit` in a row are a failure that says where.
struct RootRepeats {
  explicit RootRepeats(int max_in_a_row) : limit(max_in_a_row) {}
  double t = NAN;  // where the run of repeats began
  int count = 0;
  int limit;
  // Out of line: one copy for the segment loop and the run loop, not one
  // inlined into each (the hot code's footprint, docs/benchmarks.md).
  [[gnu::noinline]] bool Stuck(double t_event) {
    const bool same = std::abs(t_event - t) <= Tolerances::RootRepeat(t);
    count = same ? count + 1 : 0;
    if (!same) t = t_event;
    return count > limit;
  }
};

}  // namespace stickslip
