// A one-contact system with state z = (x, x') and a contact of speed v
// (switching surface x' = v): the belt oscillator (model.hpp) and any
// spring-block like it, on the one system interface (system.hpp). Such a
// system gives its slip accelerations, stick force and exit point; this
// class derives the rest of the interface from them, and the 2-D helpers
// the belt's orbit search uses (ExitPoint, SteadySliding, saltations).
#pragma once

#include <Eigen/Dense>
#include <algorithm>
#include <complex>
#include <memory>
#include <optional>
#include <string>

#include "stickslip/system/system.hpp"

namespace stickslip {

using Vec2 = Eigen::Vector2d;
using Mat2 = Eigen::Matrix2d;

/// Steady sliding x = xbar, x' = 0, with eigenvalues of
/// lambda^2 + damping lambda + stiffness = 0 (the belt: stiffness 1).
struct Equilibrium {
  double x = 0;
  double damping = 0;  // stable when > 0, Hopf where it vanishes
  std::complex<double> lambda1, lambda2;
  double max_real() const { return std::max(lambda1.real(), lambda2.real()); }
  bool stable() const { return damping > 0; }
};

class FrictionSystem : public System {
 public:
  // --- What a one-contact system gives ---
  /// The contact speed v: the relative velocity is x' - v (0 on the surface).
  virtual double v() const = 0;
  /// x'' in a slip mode, the mode's branch extended smoothly across x' = v.
  virtual double Acceleration(Mode m, double x, double xdot) const = 0;
  /// df/dz of a mode (zero in stick).
  virtual Mat2 Jacobian(Mode m, const Vec2& z) const = 0;
  /// The force the contact must transmit to hold stick at x (affine in x);
  /// stick holds while |StickForce(x)| <= static_limit().
  virtual double StickForce(double x) const = 0;
  virtual double static_limit() const = 0;
  /// Where every stick phase ends, into slip below (v > 0).
  virtual Vec2 ExitPoint() const = 0;
  /// Steady sliding in slip below: the flow's rest test and the Taylor
  /// stepper's scale of x use it.
  virtual Equilibrium SteadySliding() const = 0;

  // --- Derived: the 2-D helpers ---
  double RelativeVelocity(const Vec2& z) const { return z[1] - v(); }
  bool InStickInterval(double x) const { return std::abs(StickForce(x)) <= static_limit(); }
  /// Each mode's vector field; stick moves with the contact: (v, 0).
  Vec2 Field(Mode m, const Vec2& z) const {
    if (m == Mode::kStick) return Vec2(v(), 0.0);
    return Vec2(z[1], Acceleration(m, z[0], z[1]));
  }
  /// The switching rules (Filippov): the mode of a state, and the mode after
  /// reaching x' = v at x from `from` (stick, or a crossing).
  Mode ModeAt(const Vec2& z) const {
    if (z[1] < v()) return Mode::kSlipBelow;
    if (z[1] > v()) return Mode::kSlipAbove;
    if (InStickInterval(z[0])) return Mode::kStick;
    return StickForce(z[0]) > 0 ? Mode::kSlipBelow : Mode::kSlipAbove;
  }
  /// Saltation matrices (Leine et al. 1998; di Bernardo et al. 2008): entering
  /// stick diag(1, 0); leaving stick I + (f_slip - f_stick) g^T / (g^T f_stick)
  /// with g = (dF/dx, 0) the gradient of the stick force F(x) (g cancels:
  /// S = I + (f_slip - f_stick) (1, 0) / v).
  static Mat2 SaltationStickIn() {
    Mat2 S;
    S << 1.0, 0.0, 0.0, 0.0;
    return S;
  }
  Mat2 SaltationStickOut() const {
    const Vec2 z = ExitPoint();
    const Vec2 df = Field(Mode::kSlipBelow, z) - Field(Mode::kStick, z);
    Mat2 S = Mat2::Identity();
    S.col(0) += df / v();
    return S;
  }

  // --- The system interface, from the above ---
  int dimension() const override { return 2; }
  int contacts() const override { return 1; }
  std::string StateName(int i) const override { return i == 0 ? "x" : "x'"; }
  int DerivativeOf(int i) const override { return i == 0 ? 1 : -1; }
  ContactVelocity Contact(int) const override {
    ContactVelocity c;
    c.terms[0] = {1, 1.0};
    c.size = 1;
    c.speed = v();
    return c;
  }
  double StickForce(const ModeSet&, int, ConstState z) const override { return StickForce(z[0]); }
  void StickForceGradient(const ModeSet&, int, ConstState z, StateOut g) const override {
    g << StickForce(z[0] + 1) - StickForce(z[0]), 0.0;  // affine in x
  }
  double StaticLimit(int, ConstState) const override { return static_limit(); }
  /// The exit point exactly (x0 of ExitPoint into slip below).
  void ProjectOnExit(const ModeSet& m, int i, double bound, StateOut z) const override;
  void Field(const ModeSet& m, ConstState z, StateOut f) const override {
    const Vec2 g = Field(m[0], Vec2(z[0], z[1]));
    f = g;
  }
  void Jacobian(const ModeSet& m, ConstState z, MatrixOut J) const override {
    J = Jacobian(m[0], Vec2(z[0], z[1]));
  }
  bool Rest(const ModeSet& m, StateOut z, bool* stable) const override {
    if (m[0] != Mode::kSlipBelow) return false;
    const Equilibrium e = SteadySliding();
    z << e.x, 0.0;
    *stable = e.stable();
    return true;
  }
  std::string ValidationError() const override { return ""; }
};

}  // namespace stickslip
