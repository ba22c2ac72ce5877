// Periodic orbits of the forced friction oscillator (issue 20, item 2):
// fixed points of the stroboscopic map P^m: (x, x') at t = 0 -> (x, x') at
// t = m 2 pi / Omega, by Newton with the map's Jacobian from the variational
// equations and saltation (forced/flow.hpp); Floquet multipliers are the
// eigenvalues of that Jacobian at the fixed point.
#pragma once

#include <complex>
#include <string>

#include "stickslip/forced/flow.hpp"

namespace stickslip {

struct ForcedOrbitOptions {
  ForcedOptions flow;
  int max_newton = 40;
  /// Converged when the Newton update is below tol (1 + |z|) (max norm).
  double tol = 1e-12;
};

enum class ForcedOrbitStatus {
  kConverged,
  kNoConvergence,  ///< max_newton iterations without the update falling below tol
  kSingular,       ///< DP^m - I singular (a multiplier at 1)
  kFlowFailed,     ///< the flow failed (message says where)
};
const char* ForcedOrbitStatusName(ForcedOrbitStatus s);

struct ForcedOrbit {
  ForcedOrbitStatus status = ForcedOrbitStatus::kNoConvergence;
  std::string message;
  int m = 1;                      ///< period multiple: the orbit closes after m forcing periods
  ForcedPoint start;              ///< at t = 0 (theta = 0)
  double period = 0;              ///< m 2 pi / Omega
  Mat2 monodromy = Mat2::Zero();  ///< DP^m at the fixed point
  std::complex<double> multipliers[2];  ///< |first| >= |second|
  bool stable = false;                  ///< every |multiplier| < 1
  int sticks = 0, crossings = 0;        ///< per period of the orbit
  ForcedExtremes extremes;
  int iterations = 0;
  double update = 0;  ///< the last Newton update (max norm)
  long steps = 0;     ///< flow steps of the last evaluation
};

/// Newton on P^m(z) - z = 0 from (x0, xdot0) at t = 0.
ForcedOrbit ShootStroboscopic(const ForcedModel& model, double x0, double xdot0, int m,
                              const ForcedOrbitOptions& options);

/// Multipliers of a 2 x 2 monodromy, the larger modulus first.
void Multipliers(const Mat2& M, std::complex<double> out[2]);

}  // namespace stickslip
