// Continuation of the forced oscillator's periodic orbits in one parameter
// (issue 20, item 4): pseudo-arclength (palc.hpp) on the stroboscopic residual
// P^m(z; p) - z = 0 in (x, x', p), rows with the orbit's data, folds (LP) and
// period doublings (PD) where a multiplier crosses +1 or -1, located along
// the branch by bisection.
#pragma once

#include <complex>
#include <string>
#include <vector>

#include "stickslip/forced/orbit.hpp"
#include "stickslip/continuation/palc.hpp"

namespace stickslip {

/// The continued parameter of the forced model.
enum class ForcedAxis { kOmega, kForce, kV, kBeta };
const char* ForcedAxisName(ForcedAxis a);  // "omega", "force", "v", "beta"
double GetAxis(const ForcedParams& p, ForcedAxis a);
void SetAxis(ForcedParams& p, ForcedAxis a, double value);

enum class ForcedLabel { kNone, kLP, kPD };
const char* ForcedLabelName(ForcedLabel l);  // "", "LP", "PD"

struct ForcedBranchRow {
  double p = 0;
  double x0 = 0, xdot0 = 0;  ///< the stroboscopic point at theta = 0
  int m = 1, sticks = 0, crossings = 0;
  ForcedExtremes extremes;
  std::complex<double> multipliers[2];
  bool stable = false;
  ForcedLabel label = ForcedLabel::kNone;  ///< special points only
};

enum class ForcedBranchStatus {
  kReachedEnd,    ///< the last row is at p = to
  kUnbounded,     ///< |x| passed max_amplitude (a resonance without damping)
  kStepTooSmall,  ///< the corrector failed below ds_min (message says why)
  kStartFailed,   ///< no orbit at p = from near the guess
  kMaxPoints,
  kClosed,  ///< the branch came back to its start
};
const char* ForcedBranchStatusName(ForcedBranchStatus s);

struct ForcedBranchOptions {
  ForcedOptions flow;
  int m = 1;                   ///< period multiple
  PalcOptions palc;            ///< on (x, x', p)
  double max_amplitude = 1e3;  ///< rows stop beyond |x| = max_amplitude
  double locate_tol = 1e-12;   ///< special points: the bracket on the chord, relative
};

struct ForcedBranch {
  ForcedBranchStatus status = ForcedBranchStatus::kStartFailed;
  std::string message;
  std::vector<ForcedBranchRow> rows;
  std::vector<ForcedBranchRow> special;  ///< LP and PD, located
  int evaluations = 0;
  double seconds = 0;
};

/// Traces the branch through the orbit near (x_guess, xdot_guess) at p = from
/// toward p = to. Throws InvalidArgument on invalid parameters or options.
ForcedBranch ContinueForced(const ForcedParams& base, ForcedAxis axis, double from, double to,
                            double x_guess, double xdot_guess, const ForcedBranchOptions& options);

}  // namespace stickslip
