// Pseudo-arclength continuation (Keller 1977) of F(u) = 0, F: R^{n+1} -> R^n.
// Physics-free: a problem supplies F and its Jacobian; the algorithm supplies
// the tangent, the predictor, the bordered Newton corrector, step control and
// fold detection. Used for branches of pure-slip orbits in (a, p) and for
// curves of special points in (p1, p2) and (a, p1, p2).
#pragma once

#include <Eigen/Dense>
#include <functional>
#include <string>
#include <vector>

#include "stickslip/names.hpp"

namespace stickslip {

/// n equations in n + 1 unknowns.
class PalcProblem {
 public:
  virtual ~PalcProblem() = default;
  /// Number of unknowns, n + 1 (>= 2).
  virtual int unknowns() const = 0;
  /// F(u) (n entries) and dF/du (n x (n+1)). False if F cannot be evaluated at
  /// u; then *why says what failed.
  virtual bool Evaluate(const Eigen::VectorXd& u, Eigen::VectorXd* f, Eigen::MatrixXd* jac,
                        std::string* why) = 0;
  /// Called before each correction: a problem that keeps a derivative fixed
  /// over one correction (a chord) refreshes it here.
  virtual void BeginCorrection() {}
  /// Empty if u lies in the problem's domain, else why not. Checked after every
  /// Newton update, before the next evaluation.
  virtual std::string DomainError(const Eigen::VectorXd& /*u*/) const { return {}; }
};

/// Options in scaled coordinates u_s = u ./ scale: ds is arclength there.
struct PalcOptions {
  double ds = 0.01;      ///< first step
  double ds_min = 1e-7;  ///< below this a step failure ends the curve
  double ds_max = 0.02;  ///< largest step
  double grow = 1.5;     ///< step growth after a fast correction
  int fast_iterations = 3;
  int max_newton = 8;  ///< corrector iterations
  /// Converged when the L1 norm of the scaled Newton update is below tol.
  double tol = 1e-11;
  int max_points = 20000;
  /// End with kClosed when the curve comes back to its first point.
  bool closed_curves = true;
  Eigen::VectorXd scale;  ///< per unknown; empty means all 1
  /// Polled before every correction (rejected steps too); true ends the trace
  /// with kStopped and the message "cancelled". Empty: never.
  std::function<bool()> cancelled;
  /// Empty if valid for `unknowns`, else one line naming the offending value.
  std::string ValidationError(int unknowns) const;
};

/// Outcome of one bordered Newton correction.
struct PalcCorrection {
  bool ok = false;
  /// Accepted because the updates stopped shrinking at the noise floor of F
  /// (within 1e3 tol), not because they fell below tol.
  bool stalled = false;
  int iterations = 0;
  /// The last point F was evaluated at (so f, jac and whatever the problem
  /// cached belong to it), in unscaled coordinates.
  Eigen::VectorXd u, f;
  Eigen::MatrixXd jac;
  std::string why;  ///< when !ok
};

/// One accepted point of a curve.
struct PalcPoint {
  Eigen::VectorXd u;        ///< unscaled
  Eigen::VectorXd tangent;  ///< unit, scaled coordinates
  int iterations = 0;
  bool stalled = false;
  /// Components whose tangent changed sign since the previous point (folds
  /// with respect to that unknown, between the two points).
  std::vector<int> folds;
};

enum class PalcStatus {
  kStopped,       ///< the monitor returned false
  kClosed,        ///< the curve came back to its first point (a loop)
  kMaxPoints,     ///< max_points accepted points
  kStepTooSmall,  ///< correction failed with ds < ds_min; message says why
  kStartFailed,   ///< the start point could not be evaluated
};
template <>
struct EnumNames<PalcStatus> {
  static constexpr NamedValue<PalcStatus> kTable[] = {
      {PalcStatus::kStopped, "stopped"},          {PalcStatus::kClosed, "closed"},
      {PalcStatus::kMaxPoints, "max-points"},     {PalcStatus::kStepTooSmall, "step-too-small"},
      {PalcStatus::kStartFailed, "start-failed"},
  };
};

struct PalcResult {
  PalcStatus status = PalcStatus::kStopped;
  std::string message;
  std::vector<PalcPoint> points;
  int newton_iterations = 0, rejected_steps = 0, evaluations = 0;
};

/// Called for each accepted point, the previous one first in `curve`;
/// return false to stop.
using PalcMonitor = std::function<bool(const std::vector<PalcPoint>& curve)>;

/// What a hook tells the loop of Palc::Continue.
enum class PalcAction {
  kGoOn,   ///< correct this predictor, or accept this point
  kRetry,  ///< the hook changed the step: predict again
  kEnd,    ///< end the curve (status kStopped; the caller knows why)
};

/// Hooks into the one PALC loop (Palc::Continue), where a caller adds what
/// its problem needs to the plain loop: the pure-slip tracer lands on range
/// ends, ends at Hopf points, hands over at grazing points and polishes a
/// point at its own parameter. The defaults give the plain loop (Trace).
class PalcHooks {
 public:
  virtual ~PalcHooks() = default;
  /// The predictor from `last` (unscaled) with arclength step ds (scaled).
  virtual Eigen::VectorXd Predict(const PalcPoint& last, double ds, const Eigen::VectorXd& scale) {
    return last.u + ds * last.tangent.cwiseProduct(scale);
  }
  /// Before `pred` is corrected; may change *ds and retry, or end.
  virtual PalcAction Predicted(const PalcPoint& /*last*/, const Eigen::VectorXd& /*pred*/,
                               double* /*ds*/) {
    return PalcAction::kGoOn;
  }
  /// A correction that failed. kGoOn: the loop halves ds (kStepTooSmall
  /// below ds_min); kRetry: the hook changed ds itself; kEnd.
  virtual PalcAction Rejected(const PalcPoint& /*last*/, const PalcCorrection& /*c*/,
                              const Eigen::VectorXd& /*pred*/, double* /*ds*/) {
    return PalcAction::kGoOn;
  }
  /// A converged correction, before it is accepted as `next` (tangent and
  /// folds set); may move next->u (an extra corrector step), retry or end.
  virtual PalcAction Converged(const PalcPoint& /*last*/, const PalcCorrection& /*c*/,
                               PalcPoint* /*next*/, double* /*ds*/) {
    return PalcAction::kGoOn;
  }
  /// The accepted point, last in `curve`; false stops the curve.
  virtual bool Accepted(const std::vector<PalcPoint>& /*curve*/) { return true; }
};

class Palc {
 public:
  /// Throws InvalidArgument if the options do not fit the problem.
  Palc(PalcProblem& problem, const PalcOptions& options);

  const PalcOptions& options() const { return options_; }

  /// Unit null vector of jac (unscaled Jacobian) in scaled coordinates,
  /// oriented so that its dot product with `along` is >= 0 (if along != 0).
  Eigen::VectorXd Tangent(const Eigen::MatrixXd& jac, const Eigen::VectorXd& along) const;
  /// Bordered Newton on [F(u); t . (u_s - pred_s)] = 0 from pred (unscaled);
  /// tangent in scaled coordinates.
  PalcCorrection Correct(const Eigen::VectorXd& pred, const Eigen::VectorXd& tangent);
  /// Newton on F(u) = 0 with component k held at pred[k] (a start point).
  PalcCorrection CorrectFixed(const Eigen::VectorXd& pred, int k);

  /// Follows the curve from u0 (which need not be exact: corrected with
  /// component `fixed` held) in the direction of `direction` (scaled) until
  /// the monitor stops it, it closes, or it fails.
  PalcResult Trace(const Eigen::VectorXd& u0, int fixed, const Eigen::VectorXd& direction,
                   const PalcMonitor& monitor);
  /// The loop itself: from the accepted point `first` with step ds, under
  /// `hooks`, until a hook ends it, it closes (options().closed_curves), it
  /// fails or reaches max_points. Trace is this loop with default hooks.
  PalcResult Continue(const PalcPoint& first, double ds, PalcHooks& hooks);

  int evaluations() const { return evaluations_; }

 private:
  bool Eval(const Eigen::VectorXd& u, Eigen::VectorXd* f, Eigen::MatrixXd* jac, std::string* why);

  PalcProblem& problem_;
  PalcOptions options_;
  Eigen::VectorXd scale_;
  int evaluations_ = 0;
};

}  // namespace stickslip
