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
  ModeSet mode;        ///< the slip mode it rests in
  Eigen::VectorXd z;
  /// The Jacobian's eigenvalues, the largest real part first.
  std::vector<std::complex<double>> eigenvalues;
  double max_real = 0;  ///< the largest real part (found only)
  bool stable() const { return found && max_real < 0; }
};

/// Steady sliding of mode m.
SteadyState SteadySliding(const System& s, const ModeSet& m);

/// Steady sliding of the first pure-slip mode that has a rest point on its
/// side of every contact: every contact slipping below (the belt's x' < v)
/// first, then the other 2^k - 1 in the order of their bits (above = 1),
/// for k <= kSteadyModeContacts; beyond, below only. A drill bit turning
/// forward slips above its contact velocity 0.
SteadyState SteadySliding(const System& s);
inline constexpr int kSteadyModeContacts = 6;

/// Steady sliding in near's mode, sought from near's state (System::Rest's
/// guess): along a branch, the rest point that continues the last one where
/// several exist (a drill's fast and slow steady rotations).
SteadyState SteadySliding(const System& s, const SteadyState& near);

/// Steady sliding (or 0 where there is none) with its first component moved
/// by d: where a settling run starts.
Eigen::VectorXd NearSteadySliding(const System& s, double d);

}  // namespace stickslip
