// Periodic orbits of the forced friction oscillator (issue 20, item 2):
// fixed points of the stroboscopic map P^m: (x, x') at t = 0 -> (x, x') at
// t = m 2 pi / Omega, by Newton with the map's Jacobian from the variational
// equations and saltation (forced/flow.hpp); Floquet multipliers are the
// eigenvalues of that Jacobian at the fixed point.
#pragma once

#include <complex>
#include <string>

#include "stickslip/forced/flow.hpp"
#include "stickslip/names.hpp"

namespace stickslip {

struct ForcedOrbitOptions {
  FlowOptions flow = ForcedModel::FlowDefaults();
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
template <>
struct EnumNames<ForcedOrbitStatus> {
  static constexpr NamedValue<ForcedOrbitStatus> kTable[] = {
      {ForcedOrbitStatus::kConverged, "converged"},
      {ForcedOrbitStatus::kNoConvergence, "no-convergence"},
      {ForcedOrbitStatus::kSingular, "singular"},
      {ForcedOrbitStatus::kFlowFailed, "flow-failed"},
  };
};

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
  Extrema extrema = Extrema::Empty();   ///< running extremes of x and x'
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

namespace stickslip {

/// A stick-slip orbit as a fixed point of the exit-phase map (docs/theory.md,
/// "One shooting"): from a stick exit at t_e, on the band's edge
/// x_e = +-mu_s - 2 beta v + A cos(Omega t_e), x' = v, to the `sticks`-th
/// next exit t'; the orbit closes when t' = t_e + m 2 pi / Omega.
struct ForcedExitOrbit {
  ForcedOrbitStatus status = ForcedOrbitStatus::kNoConvergence;
  std::string message;
  int m = 1, sticks = 1;  ///< forcing periods and stick phases per period of the orbit
  double t_exit = 0;      ///< in [0, 2 pi / Omega)
  double x_exit = 0;
  Mode exit_mode = Mode::kSlipBelow;  ///< the slip mode it leaves into
  /// dt'/dt_e = -(Phi w)_x / phi'(t'), w = (-phi'(t_e), -x''(t_e+)): the exit
  /// map's derivative, the orbit's nontrivial multiplier (the other is 0).
  double multiplier = 0;
  bool stable = false;
  int crossings = 0;
  Extrema extrema = Extrema::Empty();  ///< running extremes of x and x'
  int iterations = 0;
  double update = 0;
};

/// Newton on t' - t_e - m T = 0 from the exit time t_guess into exit_mode.
ForcedExitOrbit ExitPhaseOrbit(const ForcedModel& model, double t_guess, Mode exit_mode, int sticks,
                               int m, const ForcedOrbitOptions& options);

}  // namespace stickslip
