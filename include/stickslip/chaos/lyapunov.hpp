// Iterates of the stroboscopic map of the forced oscillator (issue 21, items
// 1-2): (x, x') at forcing phase 0 (cos Omega t = 1) -> one forcing period
// later, with the stick count and stick-exit phases of each period, and the
// largest Lyapunov exponent from the variational equations with saltation at
// every switch (forced/flow.hpp, docs/theory.md "Lyapunov exponents").
//
// The exponent: J_k = DP(z_k) is the flow's 2 x 2 state transition matrix
// over period k (saltation included: S_in = diag(1, 0) entering stick, so a
// period with a stick phase has rank(J_k) <= 1). A normalised tangent matrix
// M is carried, M <- J_k M / |J_k M|_F, and lambda = sum ln|J_k M|_F / (K T)
// over the K kept periods; M is first aligned over the last `align` transient
// periods, so on a periodic orbit the sum is ln|mu_max| per period from the
// first kept period on. A matrix rather than one vector: the rank-1 collapse
// at stick then loses no growing direction (a vector in the kernel of S_in
// would). If J_k M = 0 exactly (the tangent space collapsed onto zero, e.g. a
// superstable stick-slip orbit, exit map derivative 0) the true contribution
// is -infinity; it is counted as a factor DBL_EPSILON (the smallest
// contraction a double-precision product resolves), M is reseeded with J_k,
// and `collapses` counts it: the estimate is then an upper bound.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "stickslip/forced/flow.hpp"
#include "stickslip/names.hpp"

namespace stickslip {

struct LyapunovOptions {
  /// transient's and keep's upper bound (1e6 forcing periods each), as the apps'.
  static constexpr int kMaxPeriods = 1000000;
  FlowOptions flow = ForcedModel::FlowDefaults();
  int transient = 500;   ///< forcing periods discarded
  int keep = 200;        ///< forcing periods recorded (section points, exponent)
  int align = 50;        ///< last transient periods that align the tangent matrix
  int batches = 10;      ///< batch means for the exponent's standard error
  bool exponent = true;  ///< carry the variational equations
  /// Empty if valid, else one line naming the offending value.
  std::string ValidationError() const;
};

/// One point of the stroboscopic section, after period k of the kept ones.
struct SectionPoint {
  double x = 0, xdot = 0;
  Mode mode = Mode::kSlipBelow;  ///< kStick: stuck at the section
  int sticks = 0;                ///< stick phases begun during the period that ends here
  int exits = 0;                 ///< stick exits during that period
  float first_exit_phase = -1;   ///< Omega t of its first stick exit in [0, 2 pi), -1 if none
};

enum class LyapunovStatus {
  kDone,
  kFlowFailed,  ///< the flow failed or ran out of work (message says where)
  kDiverged,    ///< |x| or |x'| passed max_amplitude
  kCancelled,
};
template <>
struct EnumNames<LyapunovStatus> {
  static constexpr NamedValue<LyapunovStatus> kTable[] = {
      {LyapunovStatus::kDone, "done"},
      {LyapunovStatus::kFlowFailed, "flow-failed"},
      {LyapunovStatus::kDiverged, "diverged"},
      {LyapunovStatus::kCancelled, "cancelled"},
  };
};

struct StroboscopicRun {
  LyapunovStatus status = LyapunovStatus::kDone;
  std::string message;
  std::vector<SectionPoint> points;  ///< the kept periods' section points
  FlowPoint end;                     ///< the last state, at t = theta = 0
  double lyapunov = 0;               ///< largest exponent, per unit time
  double lyapunov_err = 0;           ///< standard error of the batch means
  int collapses = 0;                 ///< periods with J_k M = 0 (see above)
  long steps = 0;
};

/// IterateStroboscopic's default max_amplitude: far beyond any bounded orbit.
constexpr double kStroboscopicMaxAmplitude = 1e6;

/// Iterates the stroboscopic map from `start` (its t is taken as phase 0).
/// `cancelled` is polled once per period. |x| or |x'| above max_amplitude ends
/// the run as kDiverged.
StroboscopicRun IterateStroboscopic(const ForcedModel& model, const FlowPoint& start,
                                    const LyapunovOptions& options,
                                    const std::function<bool()>& cancelled = {},
                                    double max_amplitude = kStroboscopicMaxAmplitude);

}  // namespace stickslip
