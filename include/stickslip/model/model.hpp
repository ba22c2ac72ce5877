// The Filippov belt model, seed eq. (3.5): modes, vector fields, Jacobians,
// switching and stick conditions, saltation matrices, steady sliding.
// State z = (x, x'); switching surface x' = v with normal n = (0, 1).
#pragma once

#include <Eigen/Dense>
#include <complex>

#include "stickslip/model/friction.hpp"
#include "stickslip/model/params.hpp"

namespace stickslip {

using Vec2 = Eigen::Vector2d;
using Mat2 = Eigen::Matrix2d;

/// The three modes of the Filippov system (seed regions Omega_-, Omega, Omega_+).
enum class Mode {
  kSlipBelow,  // x' < v: region Omega_- of the seed, eq. (3.7)
  kStick,      // x' = v, |x + 2 beta v| <= mu_s: region Omega, eq. (3.6)
  kSlipAbove,  // x' > v: region Omega_+, eq. (3.8)
};
const char* ModeName(Mode m);  // "slip-below", "stick", "slip-above"

/// Steady sliding x = mu(v), x' = 0; eigenvalues solve
/// lambda^2 + (2 beta + mu'(v)) lambda + 1 = 0 (linearised seed eq. 3.5).
struct Equilibrium {
  double x = 0;
  double damping = 0;  // 2 beta + mu'(v): stable when > 0, Hopf where it vanishes
  std::complex<double> lambda1, lambda2;
  double max_real() const { return std::max(lambda1.real(), lambda2.real()); }
  bool stable() const { return damping > 0; }
};

/// The belt model for one parameter set: fields, Jacobians, switching rules.
class Model {
 public:
  /// Validates p (throws InvalidArgument naming the offending value).
  explicit Model(const Params& p);

  const Params& params() const { return p_; }
  const Friction& friction() const { return friction_; }
  double v() const { return p_.v; }
  double beta() const { return p_.beta; }

  /// Slip fields use the mode's branch of the friction law, extended smoothly
  /// across x' = v, so that event location sees a smooth function.
  Vec2 Field(Mode m, const Vec2& z) const {
    if (m == Mode::kStick) return Vec2(p_.v, 0.0);
    return Vec2(z[1], -z[0] - two_beta_ * z[1] + SlipForce(m, z[1]));
  }
  /// x'' in a slip mode (the second component of Field).
  double Acceleration(Mode m, double x, double xdot) const {
    return -x - two_beta_ * xdot + SlipForce(m, xdot);
  }
  Mat2 Jacobian(Mode m, const Vec2& z) const;
  /// dF/dx' on the mode's branch.
  double SlipForceSlope(Mode m, double xdot) const {
    return m == Mode::kSlipBelow ? -friction_.DMu(p_.v - xdot) : -friction_.DMu(xdot - p_.v);
  }
  double SlipForce(Mode m, double xdot) const {
    return m == Mode::kSlipBelow ? friction_.Mu(p_.v - xdot) : -friction_.Mu(xdot - p_.v);
  }

  /// Force needed to hold x' = v: x + 2 beta v. Stick holds while |.| <= mu_s.
  double StickForce(double x) const { return x + two_beta_ * p_.v; }
  bool InStickInterval(double x) const;
  /// Every stick segment leaves Omega at (x0, v), x0 = mu_s - 2 beta v (seed, case 1).
  Vec2 ExitPoint() const { return Vec2(p_.mu_s - two_beta_ * p_.v, p_.v); }
  /// The mode of a state; on x' = v the Filippov rule decides.
  Mode ModeAt(const Vec2& z) const;
  /// The mode a trajectory takes after reaching x' = v at x coming from `from`.
  Mode ModeAfterArrival(Mode from, double x) const;

  /// Saltation matrices (Leine et al. 1998; di Bernardo et al. 2008): entering stick diag(1, 0);
  /// leaving stick I + (f_slip - f_stick) g^T / (g^T f_stick) with g = (1, 0); crossing x' = v I +
  /// (f_after - f_before) n^T / (n^T f_before).
  static Mat2 SaltationStickIn();
  Mat2 SaltationStickOut() const;
  Mat2 SaltationCrossing(Mode before, Mode after, const Vec2& z) const;

  Equilibrium SteadySliding() const;
  /// True where the energy E = ((x - mu(v))^2 + x'^2) / 2 provably decreases
  /// along every trajectory (proof in model.cpp): then no periodic orbit
  /// exists, of any kind, and steady sliding attracts every state.
  bool NoPeriodicOrbit() const;

 private:
  Params p_;
  Friction friction_;
  double two_beta_;
};

}  // namespace stickslip
