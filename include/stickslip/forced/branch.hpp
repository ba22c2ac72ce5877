// Continuation of the forced oscillator's periodic orbits in one parameter
// (issue 20, items 3-4): pseudo-arclength (palc.hpp) on the stroboscopic
// residual P^m(z; p) - z = 0 in (x, x', p), rows with the orbit's data; folds
// (LP), period doublings (PD) and Neimark-Sacker points (NS) where multipliers
// cross +1, -1 or the unit circle, and the sliding bifurcations where the
// orbit's stick structure changes (GR, SW, AD, CR: di Bernardo, Kowalczyk &
// Nordmark, Physica D 170, 2002; Kowalczyk & Piiroinen, Physica D 237, 2008),
// located by bisection. Where the stroboscopic map jumps (a stick phase of
// finite length born, mu_s > mu_k) the branch goes on from the orbit beyond.
#pragma once

#include <complex>
#include <string>
#include <vector>

#include "stickslip/continuation/branch_status.hpp"
#include "stickslip/continuation/palc.hpp"
#include "stickslip/forced/orbit.hpp"
#include "stickslip/model/forced_axis.hpp"
#include "stickslip/names.hpp"

namespace stickslip {

/// Special points. The sliding ones (docs/theory.md, forced section), by the
/// change of (sticks, crossings) per orbit period across the point:
///   GR grazing-sliding: a slip phase touches x' = v tangentially (x'' = 0)
///      inside the stick band, a stick phase is born (sticks +-1);
///   SW switching-sliding: the slip leaving a stick phase reaches x' = v and
///      crosses it (crossings +-1, sticks unchanged);
///   AD adding-sliding: the stick force touches the band's edge tangentially,
///      a stick phase splits in two around a short slip (sticks +-1);
///   CR crossing-sliding: a crossing of x' = v reaches the band's edge and
///      becomes a stick phase (sticks +-1, crossings -+1);
///   SL any other change of the stick structure (several at once).
enum class ForcedLabel { kNone, kLP, kPD, kNS, kGR, kSW, kAD, kCR, kSL };
template <>
struct EnumNames<ForcedLabel> {
  static constexpr NamedValue<ForcedLabel> kTable[] = {
      {ForcedLabel::kNone, ""}, {ForcedLabel::kLP, "LP"}, {ForcedLabel::kPD, "PD"},
      {ForcedLabel::kNS, "NS"}, {ForcedLabel::kGR, "GR"}, {ForcedLabel::kSW, "SW"},
      {ForcedLabel::kAD, "AD"}, {ForcedLabel::kCR, "CR"}, {ForcedLabel::kSL, "SL"},
  };
};

struct ForcedBranchRow {
  double p = 0;
  double x0 = 0, xdot0 = 0;  ///< the stroboscopic point at theta = 0
  int m = 1, sticks = 0, crossings = 0;
  Extrema extrema = Extrema::Empty();  ///< running extremes of x and x'
  std::complex<double> multipliers[2];
  bool stable = false;
  ForcedLabel label = ForcedLabel::kNone;  ///< special points only
  std::string description;                 ///< special points only: one line
};

struct ForcedBranchOptions {
  /// m's upper bound (1000 forcing periods, as a restart file's).
  static constexpr int kMaxM = 1000;
  ForcedOptions flow;
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

struct ForcedBranch {
  BranchStatus status = BranchStatus::kStartFailed;
  std::string message;
  std::vector<ForcedBranchRow> rows;
  std::vector<ForcedBranchRow> special;  ///< LP, PD, NS and sliding points, located
  int jumps = 0;                         ///< restarts across jumps of the map
  int evaluations = 0;
  double seconds = 0;
};

/// Traces the branch through the orbit near (x_guess, xdot_guess) at p = from
/// toward p = to. Throws InvalidArgument on invalid parameters, options or a
/// non-finite guess.
/// options.palc.cancelled (if set) is polled before every correction.
ForcedBranch ContinueForced(const ForcedParams& base, ForcedAxis axis, double from, double to,
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
ForcedBranch ContinueDoubled(const ForcedParams& at_pd, ForcedAxis axis, double x0, double xdot0,
                             double lo, double hi, const ForcedBranchOptions& options);

}  // namespace stickslip
