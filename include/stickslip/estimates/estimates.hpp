// The seed's analytic estimates for the cubic law (section 3, eqs. 3.9-3.30),
// the bounds a1, a2 of (3.18)-(3.20) fitted with NLopt, and the first-harmonic
// averaging of Thomsen & Fidlin (2003).
//
// Every function validates p (InvalidArgument naming the value) and throws
// InvalidArgument naming the law unless p.law is cubic. Numerical outcomes
// (an estimate that does not apply) are reported in the result, never thrown.
#pragma once

#include <limits>
#include <string>

#include "stickslip/names.hpp"
#include "stickslip/systems/belt/params.hpp"

namespace stickslip {

/// h(z) of seed eq. (3.10), z = x1 = y' = x' (absolute velocity):
/// h(z) = (2 beta - k1 + 3 k3 v^2) z - 3 k3 v z^2 + k3 z^3, and h'(z).
double SeedH(const Params& p, double z);
double SeedHPrime(const Params& p, double z);

/// Steady sliding x_bar = mu_s - k1 v + k3 v^3 (seed, before 3.9).
double SeedEquilibrium(const Params& p);
/// v_max = sqrt((k1 - 2 beta) / (3 k3)) of (3.16); NaN when k1 <= 2 beta.
double SeedVMax(const Params& p);

/// Which D of (3.17) to use.
enum class SeedDForm {
  kCorrected,  // D = (3v/2)^2 - (2 beta - k1 + 3 k3 v^2) / k3: r1, r2 are roots of h
  kAsPrinted,  // the seed's misprint, 3 k3 v^3: r1, r2 are NOT roots of h
};

/// Roots r0 = 0, r1 = 3v/2 - sqrt(D), r2 = 3v/2 + sqrt(D) of h (3.17).
struct SeedRoots {
  bool applies = false;  // D > 0 and r1 < 0 < r2 (for kCorrected: v < v_max)
  std::string reason;    // empty when applies
  double d = std::numeric_limits<double>::quiet_NaN();
  double r0 = 0.0;
  double r1 = std::numeric_limits<double>::quiet_NaN();  // the seed's x'_min estimate
  double r2 = std::numeric_limits<double>::quiet_NaN();
  double v_max = std::numeric_limits<double>::quiet_NaN();  // (3.16)
};
/// The roots r0, r1, r2 of h (3.10) and v_max (3.16) for the model p.
SeedRoots ComputeSeedRoots(const Params& p, SeedDForm form = SeedDForm::kCorrected);

/// Fitting a1 of h1^(x1) = -a1 x1 on D1 = [r1, v] (3.18) and a2 of
/// h2^(x1) = -a2 (x1^2 - r1^2) on D2 = [x1_low, r1) (3.20).
struct BoundFitOptions {
  int fit_points = 401;       // >= 3: grid on which NLopt imposes the constraint
  int check_points = 200001;  // >= fit_points: grid on which the result is verified
  /// Lower end of D2, the orbit's minimum of x' = x1. NaN: the fallback 2 r1.
  double x1_low = std::numeric_limits<double>::quiet_NaN();
  double check_tolerance = 1e-10;  // > 0: allowed violation, in units of a
  double xtol_abs = 1e-14;         // > 0: NLopt stopping test on a
  int max_evaluations = 1000;      // > 0
};

/// How the fit of a linear bound (3.18), (3.23) ended.
enum class BoundStatus {
  kFitted,           // NLopt stopped with a > 0 satisfying every sampled constraint
  kNoPositiveBound,  // the optimal a is <= 0: no positive a satisfies the inequality
  kNotApplicable,    // no roots r1 < 0 < r2 (v >= v_max), so D1, D2 are undefined
  kOptimizerFailed,  // NLopt returned an error code or an infeasible point
};
template <>
struct EnumNames<BoundStatus> {
  static constexpr NamedValue<BoundStatus> kTable[] = {
      {BoundStatus::kFitted, "fitted"},
      {BoundStatus::kNoPositiveBound, "no-positive-bound"},
      {BoundStatus::kNotApplicable, "not-applicable"},
      {BoundStatus::kOptimizerFailed, "optimizer-failed"},
  };
};

/// One fitted bound: its slope a, whether it holds on its domain, and why not.
struct BoundFit {
  BoundStatus status = BoundStatus::kNotApplicable;
  std::string reason;  // why not kFitted / not holds; or a note (a2: orbit never enters D2)
  double a = std::numeric_limits<double>::quiet_NaN();
  double lo = std::numeric_limits<double>::quiet_NaN();  // interval fitted on
  double hi = std::numeric_limits<double>::quiet_NaN();
  /// Max over the check grid of the constraint in units of a (a1: -h/x1 - a1;
  /// a2: a2 - (-h / (x1^2 - r1^2))); <= 0 where the seed's inequality holds.
  double worst_violation = std::numeric_limits<double>::quiet_NaN();
  bool holds = false;  // worst_violation <= check_tolerance
  int evaluations = 0;
  int nlopt_code = 0;  // nlopt_result of the last optimize call
};

/// The bounds a1 (on D1) and a2 (on D2) of the seed's section 3.
struct SeedBounds {
  SeedRoots roots;
  BoundFit a1, a2;
};
/// Throws InvalidArgument if options are invalid.
SeedBounds FitSeedBounds(const Params& p, const BoundFitOptions& options = {});

/// How y1 (where the D1 comparison trajectory (3.22) first reaches y' = r1) is taken.
enum class SeedY1Rule {
  kSmallA1,  // the seed's text after (3.22): sqrt(y0^2 + (v - a1 y0)^2 - r1^2), a1 << 1
  /// y(t1) of (3.22) at the first t1 > 0 with y'(t1) = r1; not applicable if
  /// y' climbs back above v first (the comparison returns to the belt).
  kExactCrossing,
};

/// Choices where the seed's text is ambiguous (which y1 rule, which form of d).
struct SeedEstimateOptions {
  BoundFitOptions bounds;
  SeedY1Rule y1_rule = SeedY1Rule::kSmallA1;
};

/// The chain (3.21)-(3.30), in y = x - x_bar. Fields are filled up to the first
/// stage that fails; the rest stay NaN.
struct SeedEstimate {
  bool applies = false;  // every stage up to y3 computed
  std::string reason;    // the first stage that failed
  SeedBounds bounds;
  double x_bar = std::numeric_limits<double>::quiet_NaN();
  double x0 = std::numeric_limits<double>::quiet_NaN();  // stick exit mu_s - 2 beta v
  double y0 = std::numeric_limits<double>::quiet_NaN();  // x0 - x_bar
  double velocity_amplitude = std::numeric_limits<double>::quiet_NaN();  // r1 (x'_min claim)
  /// sqrt(y0^2 + (v - a1 y0)^2) (after 3.30) and x_bar -+ it.
  double displacement_bound = std::numeric_limits<double>::quiet_NaN();
  double x_min_bound = std::numeric_limits<double>::quiet_NaN();
  double x_max_bound = std::numeric_limits<double>::quiet_NaN();
  double y1 = std::numeric_limits<double>::quiet_NaN();        // per SeedY1Rule
  double c = std::numeric_limits<double>::quiet_NaN();         // (3.26)
  double y2 = std::numeric_limits<double>::quiet_NaN();        // (3.27) as printed
  double y2_pade = std::numeric_limits<double>::quiet_NaN();   // Pade redone: -y1/(1+2 a2 y1)
  double y2_exact = std::numeric_limits<double>::quiet_NaN();  // root of (3.26)
  double ydot_m = std::numeric_limits<double>::quiet_NaN();    // (3.28), < 0
  double min_velocity_bound = std::numeric_limits<double>::quiet_NaN();  // r1 + ydot_m
  double y3 = std::numeric_limits<double>::quiet_NaN();                  // (3.30) from y2
  /// Omega in y: [-mu_s - 2 beta v - x_bar, y0]; whether y3 lies in it.
  double y_stick_low = std::numeric_limits<double>::quiet_NaN();
  bool y3_in_stick = false;
};
/// Throws InvalidArgument if options are invalid.
SeedEstimate EstimateSeed(const Params& p, const SeedEstimateOptions& options = {});

/// First-harmonic averaging, Thomsen & Fidlin (2003): x' ~ -a_ps sin t about 0.
struct AveragingEstimate {
  bool applies = false;  // pure slip: k1 - 2 beta - 3 k3 v^2 > 0 and a_ps < v
  std::string reason;
  /// a_ps = 2 sqrt((k1 - 2 beta - 3 k3 v^2) / (3 k3)); computed whenever the
  /// radicand is >= 0, also when the orbit sticks (a_ps >= v).
  double amplitude = std::numeric_limits<double>::quiet_NaN();
  /// a_ps = v: v_g = 2 sqrt((k1 - 2 beta) / (15 k3)); NaN when k1 <= 2 beta.
  double grazing_speed = std::numeric_limits<double>::quiet_NaN();
  double hopf_speed = std::numeric_limits<double>::quiet_NaN();  // a_ps = 0: v_max
  double hopf_beta = std::numeric_limits<double>::quiet_NaN();   // (k1 - 3 k3 v^2) / 2
};
/// First-harmonic averaging of the pure-slip orbit (cubic law only).
AveragingEstimate EstimateAveraging(const Params& p);

}  // namespace stickslip
