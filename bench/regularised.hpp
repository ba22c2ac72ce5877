// The tanh-regularised smooth belt model, for the work-precision benchmark:
// seed eq. (3.5) with the friction sign replaced by a smooth step,
//   x'' + 2 beta x' + x = F_eps(x' - v),  F_eps(u) = -tanh(u / eps) mu(|u|),
// and no stick mode: the smoothing approach (Leine et al. 1998 smooth with atan).
// Its periodic orbit is found as a smooth-continuation user would: a short
// transient from rest, then shooting (Newton on the return map of the section
// x' = 0, x' decreasing), integrated with CVODE BDF (stiff for small eps).
#pragma once

#include <string>

#include "stickslip/systems/belt/params.hpp"

namespace bench {

struct SmoothOptions {
  double eps = 1e-3;   // regularisation width in u = x' - v
  double rtol = 1e-8;  // CVODE BDF tolerances
  double atol = 1e-10;
  int transient_maxima = 3;  // x maxima to pass from rest before shooting
  double max_time = 4000;    // per integration (transient or one return)
  int max_newton = 30;
  long max_steps = 2000000;  // CVODE steps per Advance call
};

struct SmoothCycle {
  bool ok = false;
  std::string message;  // why not ok
  double period = 0;    // return time of the section at the fixed point
  double x_max = 0, x_min = 0;
  // x' came within 10 eps of v: creep at the belt speed, what sticking
  // becomes in the smooth model.
  bool touches = false;
  long steps = 0;  // CVODE steps, transient and shooting together
  int newton = 0;  // Newton iterations
};

// The periodic orbit of the regularised model at p (cubic or any other law).
// Not ok if the transient or a return fails, Newton does not converge, or the
// orbit collapses onto steady sliding (no cycle for this eps).
SmoothCycle RegularisedCycle(const stickslip::Params& p, const SmoothOptions& o);

}  // namespace bench
