// Branches of periodic orbits and of steady sliding in one parameter, with
// their special points located (not bracketed):
//   GR  grazing-sliding: the stick phase of the stick-slip orbit shrinks to
//       zero; the orbit touches x' = v at the exit point (x0, v);
//   HB  Hopf point of steady sliding, where 2 beta + mu'(v) = 0;
//   LP  fold: the branch turns back in the parameter (smooth, or at GR).
// Stick-slip orbits are unique for given parameters (constant return map on
// Omega), so that part of a branch is followed in the parameter itself.
// Pure-slip orbits are followed by pseudo-arclength continuation (Keller 1977)
// of G(a, p) = 0 in (a, p), a = x* - xbar the section amplitude, which starts
// at (0, p_HB) with tangent (1, 0) and ends there.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "stickslip/continuation/special_kind.hpp"
#include "stickslip/names.hpp"
#include "stickslip/orbits/orbit.hpp"
#include "stickslip/systems/belt/parameter_axis.hpp"

namespace stickslip {

/// What a branch point is: a stick-slip or pure-slip orbit, or steady sliding.
enum class PointKind { kStickSlip, kPureSlip, kEquilibrium };
template <>
struct EnumNames<PointKind> {
  static constexpr NamedValue<PointKind> kTable[] = {
      {PointKind::kStickSlip, "stick-slip"},
      {PointKind::kPureSlip, "pure-slip"},
      {PointKind::kEquilibrium, "equilibrium"},
  };
};

/// One point of a branch: the parameter, the orbit's measures and stability.
struct BranchPoint {
  double p = 0;  // the continued parameter
  PointKind kind = PointKind::kEquilibrium;
  int branch = 0;     // which curve: rows of one branch are consecutive
  double period = 0;  // nan for the equilibrium
  Extrema extrema;
  double t_stick = 0;
  /// Nontrivial Floquet multiplier; for the equilibrium the largest real part
  /// of its eigenvalues.
  double multiplier = 0;
  bool stable = false;
  double amplitude = 0;  // pure slip: section amplitude a; else (x_max - x_min) / 2
  // Pure slip: Newton was accepted where its steps stalled at the integration
  // noise floor (below 1000 x the tolerance, no longer shrinking) instead of
  // falling below the tolerance: the point is only as accurate as that step.
  bool newton_stalled = false;
  /// The state a restart starts from: stick-slip the exit point (x0, v),
  /// pure slip the section point (x*, 0), steady sliding (xbar, 0).
  double x_start = 0, xdot_start = 0;
};

/// A located special point with the orbit there and a one-line description.
struct SpecialPoint {
  SpecialKind kind = SpecialKind::kHopf;
  double p = 0;
  double period = 0;
  Extrema extrema;  // the table writes x_min, x_max, xdot_min; all four are set
  /// GR: the nontrivial multiplier on the stick-slip side and on the pure-slip side.
  double multiplier_before = 0, multiplier_after = 0;
  /// The point's state: HB (xbar, 0); GR the exit point (x0, v); LP the
  /// start of the fold orbit's run (on the section x' = 0 for a smooth fold).
  double x_start = 0, xdot_start = 0;
  std::string description;
};

/// The continued parameter, its range, steps and tolerances; validated once by Continue().
struct ContinuationOptions {
  ParameterAxis param{Parameter::kV};  // parsed from a name once, at the entry
  double from = 0.05;
  double to = 0.5;
  OrbitOptions orbit;
  /// Largest step, as a fraction of |to - from| (so at least 1/max_step points
  /// on a branch that spans the range), in (0, kMaxStepLimit].
  double max_step = 0.01;
  // max_step's upper bound (a branch across the range in at least 2 steps).
  static constexpr double kMaxStepLimit = 0.5;
  double min_step = 1e-7;     // fraction of |to - from| below which a branch fails
  double locate_tol = 1e-13;  // special points, in the parameter (Brent's interval)
  int max_points = 20000;     // per branch
  /// Stick-slip multipliers by the variational equations (otherwise 0, which
  /// S_in = diag(1, 0) makes exact).
  bool stick_slip_floquet = false;
  std::function<bool()> cancelled;                   // polled between points
  std::function<void(const BranchPoint&)> progress;  // called for every point
  /// Empty if valid, else one line naming the offending value. base: the model.
  std::string ValidationError(const Params& base) const;
};

/// How a continuation ended; kFailed and kCancelled keep the points so far.
enum class ContinuationStatus {
  kOk,
  kFailed,     // a numerical failure; message says where; points so far kept
  kCancelled,  // cancelled() returned true; points so far kept
};
template <>
struct EnumNames<ContinuationStatus> {
  static constexpr NamedValue<ContinuationStatus> kTable[] = {
      {ContinuationStatus::kOk, "ok"},
      {ContinuationStatus::kFailed, "failed"},
      {ContinuationStatus::kCancelled, "cancelled"},
  };
};

/// Work done, for the summary and branch.tsv's metadata.
struct ContinuationCounts {
  long orbit_solves = 0;       // stick-slip orbits and fixed-p pure-slip shootings
  long return_maps = 0;        // evaluations of G(a, p), the pure-slip return map
  long newton_iterations = 0;  // pure-slip corrector and shooting iterations
  long rejected_steps = 0;     // steps halved on any branch
  long integrator_steps = 0;   // BeltFlow::total_steps() over the whole run
};

/// Wall-clock seconds per phase; each second is counted in one phase only.
struct ContinuationTimes {
  double equilibrium = 0;  // steady sliding and its Hopf points
  double stick_slip = 0;   // stick-slip branches
  double pure_slip = 0;    // pure-slip branches (PALC), their folds and Hopf ends
  double switching = 0;    // grazing points: located, recorded, the next branch found
  double discovery = 0;    // the periodic orbit at `from` and the grid scan for more
  double total = 0;
};

/// Branches, special points, status, counts and timings of one Continue() call.
struct ContinuationResult {
  ContinuationStatus status = ContinuationStatus::kOk;
  std::string message;
  ParameterAxis param{Parameter::kV};  // the parameter axis the points are on
  // Conditions that make the result less trustworthy than its status says
  // (a tolerance looser than kLoosestTrustedRtol), one line each.
  std::vector<std::string> warnings;
  std::vector<BranchPoint> points;
  std::vector<SpecialPoint> special;
  ContinuationCounts counts;
  ContinuationTimes seconds;
  bool partial() const { return status != ContinuationStatus::kOk; }
};

/// Looser than this rtol a result carries a warning: docs/validation.md promises the
/// branch's structure (which special points, in which order) from here down.
constexpr double kLoosestTrustedRtol = 1e-4;

/// Throws InvalidArgument if the options or the model at either end are invalid.
ContinuationResult Continue(const Params& base, const ContinuationOptions& options);

}  // namespace stickslip
