// The model seam (issue 19, design.md section 2): what the flow, its events
// and the orbit search need of an autonomous friction system with state
// z = (x, x') and a contact of speed v (switching surface x' = v, normal
// n = (0, 1)). The belt oscillator (model.hpp) is one implementation; a test
// drives a second one (tests/orbits/seam_test.cpp) through the same code.
// A small virtual interface: the flow calls it per segment, per switch and,
// for the Taylor recurrences, once per step (TaylorField), never per
// coefficient, so a virtual call costs nothing measurable (docs/theory.md).
#pragma once

#include <Eigen/Dense>
#include <algorithm>
#include <complex>
#include <memory>
#include <optional>
#include <string>

#include "stickslip/model/parameter_axis.hpp"
#include "stickslip/names.hpp"

namespace stickslip {

using Vec2 = Eigen::Vector2d;
using Mat2 = Eigen::Matrix2d;

/// The three modes of the Filippov system (seed regions Omega_-, Omega, Omega_+).
enum class Mode {
  kSlipBelow,  // x' < v: region Omega_- of the seed, eq. (3.7)
  kStick,      // x' = v, |stick force| <= static limit: region Omega, eq. (3.6)
  kSlipAbove,  // x' > v: region Omega_+, eq. (3.8)
};
const char* ModeName(Mode m);  // "slip-below", "stick", "slip-above"
template <>
struct EnumNames<Mode> {
  static constexpr NamedValue<Mode> kTable[] = {
      {Mode::kSlipBelow, "slip-below"},
      {Mode::kStick, "stick"},
      {Mode::kSlipAbove, "slip-above"},
  };
};

/// Steady sliding x = xbar, x' = 0, with eigenvalues of
/// lambda^2 + damping lambda + stiffness = 0 (the belt: stiffness 1).
struct Equilibrium {
  double x = 0;
  double damping = 0;  // stable when > 0, Hopf where it vanishes
  std::complex<double> lambda1, lambda2;
  double max_real() const { return std::max(lambda1.real(), lambda2.real()); }
  bool stable() const { return damping > 0; }
};

class TaylorField;  // src/integrate/taylor_field.hpp: a slip mode's recurrences

/// The seam. Every function is a property of the system, not of the flow.
class FrictionSystem {
 public:
  static constexpr int kStateSize = 2;  // z = (x, x')
  virtual ~FrictionSystem() = default;
  virtual std::unique_ptr<FrictionSystem> Clone() const = 0;
  /// Becomes a copy of s if s is of this type (no allocation); else false.
  virtual bool Assign(const FrictionSystem& s) = 0;

  /// The contact speed v: the relative velocity is x' - v (0 on the surface).
  virtual double v() const = 0;
  double RelativeVelocity(const Vec2& z) const { return z[1] - v(); }

  /// x'' in a slip mode, the mode's branch extended smoothly across x' = v.
  virtual double Acceleration(Mode m, double x, double xdot) const = 0;
  /// Each mode's vector field; stick moves with the contact: (v, 0).
  Vec2 Field(Mode m, const Vec2& z) const {
    if (m == Mode::kStick) return Vec2(v(), 0.0);
    return Vec2(z[1], Acceleration(m, z[0], z[1]));
  }
  /// df/dz of a mode (zero in stick).
  virtual Mat2 Jacobian(Mode m, const Vec2& z) const = 0;
  /// The Taylor recurrences of the slip modes (with Phi, and with dz/dp for
  /// `parameter` when given), for the Taylor stepper. Throws
  /// InvalidArgument for a parameter the system has no column for.
  virtual std::unique_ptr<TaylorField> MakeTaylorField(
      const std::optional<ParameterAxis>& parameter) const = 0;
  /// Whether MakeTaylorField accepts this parameter.
  virtual bool SupportsParameterColumn(const ParameterAxis& parameter) const = 0;

  /// The force the contact must transmit to hold stick at x; stick holds
  /// while |StickForce(x)| <= static_limit().
  virtual double StickForce(double x) const = 0;
  virtual double static_limit() const = 0;
  bool InStickInterval(double x) const { return std::abs(StickForce(x)) <= static_limit(); }
  /// Where every stick phase ends, into slip below (v > 0).
  virtual Vec2 ExitPoint() const = 0;

  /// The switching rules (Filippov): the mode of a state, and the mode after
  /// reaching x' = v at x from `from` (stick, or a crossing).
  Mode ModeAt(const Vec2& z) const {
    if (z[1] < v()) return Mode::kSlipBelow;
    if (z[1] > v()) return Mode::kSlipAbove;
    if (InStickInterval(z[0])) return Mode::kStick;
    return StickForce(z[0]) > 0 ? Mode::kSlipBelow : Mode::kSlipAbove;
  }
  Mode ModeAfterArrival(Mode from, double x) const {
    if (InStickInterval(x)) return Mode::kStick;
    return from == Mode::kSlipBelow ? Mode::kSlipAbove : Mode::kSlipBelow;
  }

  /// Saltation matrices (Leine et al. 1998; di Bernardo et al. 2008): entering
  /// stick diag(1, 0); leaving stick I + (f_slip - f_stick) g^T / (g^T f_stick)
  /// with g = (dF/dx, 0) the gradient of the stick force F(x) (g cancels:
  /// S = I + (f_slip - f_stick) (1, 0) / v); crossing x' = v
  /// I + (f_after - f_before) n^T / (n^T f_before).
  static Mat2 SaltationStickIn() {
    Mat2 S;
    S << 1.0, 0.0, 0.0, 0.0;
    return S;
  }
  virtual Mat2 SaltationStickOut() const {
    const Vec2 z = ExitPoint();
    const Vec2 df = Field(Mode::kSlipBelow, z) - Field(Mode::kStick, z);
    Mat2 S = Mat2::Identity();
    S.col(0) += df / v();
    return S;
  }
  Mat2 SaltationCrossing(Mode before, Mode after, const Vec2& z) const {
    const Vec2 fb = Field(before, z);
    const Vec2 fa = Field(after, z);
    Mat2 S = Mat2::Identity();
    S.col(1) += (fa - fb) / fb[1];
    return S;
  }

  /// Steady sliding in slip below: the flow's rest test and the Taylor
  /// stepper's scale of x use it.
  virtual Equilibrium SteadySliding() const = 0;
};

}  // namespace stickslip
