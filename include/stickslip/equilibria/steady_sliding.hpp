// Steady sliding of any system (system.hpp): the rest point of a slip mode
// (System::Rest) and the eigenvalues of its smooth field's Jacobian there
// (System::Jacobian on the tangent block). Stable when every eigenvalue has
// a negative real part; a Hopf point where the largest real part crosses 0
// (for any n: Kuznetsov, "Elements of Applied Bifurcation Theory", ch. 3).
#pragma once

#include <Eigen/Dense>
#include <complex>
#include <vector>

#include "stickslip/system/system.hpp"

namespace stickslip {

struct SteadyState {
  bool found = false;  ///< the mode has a rest point (System::Rest)
  Eigen::VectorXd z;
  /// The Jacobian's eigenvalues, the largest real part first.
  std::vector<std::complex<double>> eigenvalues;
  double max_real = 0;  ///< the largest real part (found only)
  bool stable() const { return found && max_real < 0; }
};

/// Steady sliding of mode m (default: every contact slips below).
SteadyState SteadySliding(const System& s, const ModeSet& m = ModeSet());

/// Steady sliding (or 0 where there is none) with its first component moved
/// by d: where a settling run starts.
Eigen::VectorXd NearSteadySliding(const System& s, double d);

}  // namespace stickslip
