// The Newton stall test, one for every Newton loop (the PALC corrector,
// pure-slip shooting): a step that is near the tolerance but no longer
// shrinks is at the noise floor of the residual (Tolerances::kStallBand).
#pragma once

#include "numerics/tolerances.hpp"

namespace stickslip {

// step, last_step: |Newton step| now and one iteration before; iteration
// counts from 1; tol: the convergence tolerance on the step.
inline bool NewtonStalled(double step, double last_step, int iteration, double tol) {
  return iteration >= Tolerances::kStallFirstIteration && step < Tolerances::kStallBand * tol &&
         step > Tolerances::kStallRatio * last_step;
}

}  // namespace stickslip
