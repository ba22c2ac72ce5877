// The forced oscillator's branches on the one branch driver (orbit_branch.hpp):
// the stroboscopic residual P^m(z; p) - z = 0 in (x, x', p) of ForcedModel,
// started from its parameters and a guess (x, x') at theta = 0. The rows,
// special points (LP, PD, NS, GR, AD, CR, SL: special_kind.hpp) and statuses
// are the driver's; a row's start is (x, x', theta).
#pragma once

#include <complex>
#include <string>
#include <vector>

#include "stickslip/continuation/branch_status.hpp"
#include "stickslip/continuation/orbit_branch.hpp"
#include "stickslip/continuation/palc.hpp"
#include "stickslip/forced/orbit.hpp"
#include "stickslip/model/forced_axis.hpp"
#include "stickslip/names.hpp"

namespace stickslip {

/// The extremes of x and x' of a row (OrbitRow::lo, hi); Extrema::Empty()
/// where the shooting did not record them.
inline Extrema RowExtrema(const OrbitRow& r) { return ExtremaOf(r.lo, r.hi); }

/// The period multiple m of a branch: its section's clock turns.
inline int PeriodMultiple(const OrbitBranch& b) { return b.section.turns; }

struct ForcedBranchOptions {
  /// m's upper bound (1000 forcing periods, as a restart file's).
  static constexpr int kMaxM = 1000;
  FlowOptions flow = ForcedModel::FlowDefaults();
  int m = 1;                   ///< period multiple, in [1, kMaxM]
  PalcOptions palc;            ///< on (x, x', p)
  double max_amplitude = 1e3;  ///< rows stop beyond |x| = max_amplitude
  double locate_tol = 1e-12;   ///< special points: the bracket on the chord, relative
  /// Where the corrector fails at a jump of the stroboscopic map: at most this
  /// many restarts from the orbit beyond the located sliding point.
  int max_jumps = 50;
  /// Empty if valid, else one line naming the offending value (m, max_amplitude,
  /// locate_tol, max_jumps, flow).
  std::string ValidationError() const;
  /// ContinueForced's checks: the model at from, the range (to finite and !=
  /// from), the options, then a start guess that is not finite.
  std::string ValidationError(const ForcedParams& base, ForcedAxis axis, double from, double to,
                              double x_guess, double xdot_guess) const;
};

/// Traces the branch through the orbit near (x_guess, xdot_guess) at p = from
/// toward p = to. Throws InvalidArgument on invalid parameters, options or a
/// non-finite guess.
/// options.palc.cancelled (if set) is polled before every correction.
OrbitBranch ContinueForced(const ForcedParams& base, ForcedAxis axis, double from, double to,
                           double x_guess, double xdot_guess, const ForcedBranchOptions& options);

/// Branch switching at a period doubling (AUTO-07p's ISW = -1 at a PD label).
/// at_pd holds the PD point's parameters (GetAxis(at_pd, axis) = p_PD),
/// (x0, xdot0) its stroboscopic point and options.m its period multiple. The
/// 2m-periodic branch starts at z + h e (e the eigenvector of the multiplier
/// -1 of DP^m, h = options.palc.ds, scaled), corrected with its projection on
/// e held (p free: the 2m orbits form a pitchfork of P^2m, p - p_PD ~ h^2),
/// and is traced away from the m orbit to whichever bound, lo or hi, it opens
/// toward. Rows have m = 2 options.m. Status kStartFailed with a message if
/// the point has no multiplier near -1 or the start falls back onto the m
/// orbit. Throws InvalidArgument on invalid parameters, options or bounds
/// (lo < p_PD < hi).
OrbitBranch ContinueDoubled(const ForcedParams& at_pd, ForcedAxis axis, double x0, double xdot0,
                            double lo, double hi, const ForcedBranchOptions& options);

}  // namespace stickslip
