// Steady sliding of any system along one parameter (docs/theory.md, "Steady
// sliding of any system"): the rest point of the slip mode (SteadySliding)
// on an even grid of the parameter, with the points where its largest real
// part crosses 0 located by bisection (Kuznetsov 2004, ch. 3):
//   HB  a complex pair crosses the imaginary axis (Hopf; for the brake model
//       the flutter threshold mu_k*, mode_coupling.hpp);
//   LP  a real eigenvalue crosses 0 (a fold or branch point of the rest
//       points).
// The rest point is explicit, so no corrector is needed. It ends where the
// system has no rest point, or where a contact's normal force there is not
// positive (the contact would be open: no sliding state).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "stickslip/continuation/branch_status.hpp"
#include "stickslip/continuation/special_kind.hpp"
#include "stickslip/equilibria/steady_sliding.hpp"

namespace stickslip {

/// Settings of ContinueSteadySliding, validated once.
struct SteadyBranchOptions {
  static constexpr int kMaxPoints = 1000000;  ///< the rows' memory bound
  int points = 101;  ///< grid rows from `from` to `to`, both ends included, in [2, kMaxPoints]
  double locate_tol = 1e-14;        ///< special points: the bracket, relative to 1 + |p|
  std::function<bool()> cancelled;  ///< polled between rows and bisection steps
  /// Empty if valid, else one line naming the offending value.
  std::string ValidationError() const;
};

struct SteadyRow {
  double p = 0;
  SteadyState state;
  SpecialKind label = SpecialKind::kNone;  ///< HB or LP on special points
  std::string description;                 ///< special points only: one line
};

struct SteadyBranch {
  BranchStatus status = BranchStatus::kStartFailed;
  std::string message;
  std::vector<SteadyRow> rows;     ///< the special points among them, in order of p
  std::vector<SteadyRow> special;  ///< HB and LP, located
};

/// Steady sliding of `system` (every contact slipping below) for its
/// parameter `parameter` from its value in `system` to `to`. kStartFailed
/// where there is none at the start; kContactLost where a normal force at the
/// rest point falls to 0 or below (the rows end before); kStepTooSmall where
/// the rest point ceases to exist. Throws InvalidArgument on an invalid
/// system, options, parameter index or range, or a parameter the system
/// does not depend on (System::ParameterError).
SteadyBranch ContinueSteadySliding(const System& system, int parameter, double to,
                                   const SteadyBranchOptions& options);

}  // namespace stickslip
