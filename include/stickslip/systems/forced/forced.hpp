// The harmonically forced friction oscillator (docs/theory.md, "One core"):
//   x'' + 2 beta x' + x = F(x' - v) + A cos(Omega t),   F(s) = -sgn(s) mu(|s|),
// the belt model (seed eq. 3.5) plus a harmonic force. v = 0 is Den Hartog's
// (1931) block on a fixed floor. Stick (x' = v) holds while
// |x + 2 beta v - A cos(Omega t)| <= mu_s.
#pragma once

#include <array>
#include <cmath>
#include <string>

#include "stickslip/flow/flow_options.hpp"
#include "stickslip/system/system.hpp"
#include "stickslip/systems/belt/friction.hpp"
#include "stickslip/systems/belt/model.hpp"
#include "stickslip/systems/belt/params.hpp"

namespace stickslip {

/// The forced oscillator on the one system interface: the belt plus a phase
/// theta' = Omega (a clock, COCO's way of making forcing autonomous), state
/// (x, x', theta); its parameters are the belt's (Parameter's order), then
/// force and omega.
class ForcedBelt final : public System {
 public:
  static constexpr int kStateSize = 2;
  /// The parameter indexes of A and Omega (after the belt's).
  static constexpr int kForceIndex = static_cast<int>(Parameter::kForce),
                       kOmegaIndex = static_cast<int>(Parameter::kOmega);
  /// Throws InvalidArgument naming the offending value.
  explicit ForcedBelt(const ForcedBeltParams& p);
  /// The tolerance its tools default to (rtol = atol): at the belt's 1e-11
  /// the branch corrector, tol 1e-11, stalls on the flow's noise.
  static constexpr double kFlowTol = 1e-12;
  /// Their flow settings: kFlowTol, 1e6 steps and 1e5 switches per run.
  static FlowOptions FlowDefaults() {
    FlowOptions o;
    o.rtol = o.atol = kFlowTol;
    o.max_steps = 1000000;
    o.max_switches = 100000;
    return o;
  }

  // --- The system interface (theta = Omega t) ---
  std::unique_ptr<System> Clone() const override { return std::make_unique<ForcedBelt>(*this); }
  bool Assign(const System& s) override;
  std::string ValidationError() const override { return stickslip::ValidationError(p_); }
  int dimension() const override { return 3; }
  int contacts() const override { return 1; }
  int clocks() const override { return 1; }
  std::string StateName(int i) const override;
  int DerivativeOf(int i) const override { return i == 0 ? 1 : -1; }
  ContactVelocity Contact(int i) const override;
  double StickForce(const ModeSet& m, int i, ConstState z) const override;
  void StickForceGradient(const ModeSet& m, int i, ConstState z, StateOut g) const override;
  double StaticLimit(int, ConstState) const override { return p_.base.mu_s; }
  /// x on the band's edge exactly: x = bound - 2 beta v + A cos(theta).
  void ProjectOnExit(const ModeSet& m, int i, double bound, StateOut z) const override;
  void Field(const ModeSet& m, ConstState z, StateOut f) const override;
  void Jacobian(const ModeSet& m, ConstState z, MatrixOut J) const override;
  std::unique_ptr<TaylorField> MakeTaylorField(const TaylorRequest& request) const override;
  /// The belt's columns (ParameterColumnSupported), force and omega.
  bool SupportsParameterColumn(int j) const override;
  /// The belt's, and d lambda / dA = -cos(theta).
  ContactSensitivity ContactParameterDerivative(const ModeSet& m, int i, int j,
                                                ConstState z) const override;
  double ClockRateDerivative(int, int j) const override { return j == kOmegaIndex ? 1 : 0; }
  /// Steady sliding only without forcing (A = 0).
  bool Rest(const ModeSet& m, StateOut z, bool* stable) const override;
  int parameters() const override;
  std::string ParameterName(int j) const override;
  /// AxisError: a parameter of another friction law.
  std::string ParameterError(int j) const override;
  double ParameterValue(int j) const override;
  void SetParameterValue(int j, double value) override;

  const ForcedBeltParams& params() const { return p_; }
  const Friction& friction() const { return friction_; }
  double v() const { return p_.base.v; }
  double beta() const { return p_.base.beta; }
  double force() const { return p_.force; }
  double omega() const { return p_.omega; }
  double period() const { return 2 * M_PI / p_.omega; }
  double static_limit() const { return p_.base.mu_s; }
  /// The half-widths in (x, x') of the box of stroboscopic starts an orbit
  /// search scans (OrbitSearchOptions::half_width): x within r = A /
  /// max(|1 - Omega^2|, 2 beta Omega, 0.2) + mu_s + v (the linear response's
  /// amplitude, bounded at resonance), x' within r max(1, Omega).
  std::array<double, 2> SearchBox() const;

  /// The slip force on the mode's branch, extended smoothly across x' = v.
  double SlipForce(Mode m, double xdot) const {
    return m == Mode::kSlipBelow ? friction_.Mu(v() - xdot) : -friction_.Mu(xdot - v());
  }
  double Acceleration(Mode m, double t, double x, double xdot) const {
    if (m == Mode::kStick) return 0;
    return -x - two_beta_ * xdot + SlipForce(m, xdot) + p_.force * std::cos(p_.omega * t);
  }
  Vec2 Field(Mode m, double t, const Vec2& z) const {
    if (m == Mode::kStick) return Vec2(v(), 0.0);
    return Vec2(z[1], Acceleration(m, t, z[0], z[1]));
  }
  Mat2 Jacobian(Mode m, double t, const Vec2& z) const;
  double RelativeVelocity(const Vec2& z) const { return z[1] - v(); }

  /// The friction force that holds x' = v: x + 2 beta v - A cos(Omega t).
  double StickForce(double t, double x) const {
    return x + two_beta_ * v() - p_.force * std::cos(p_.omega * t);
  }
  /// d/dt of StickForce along the stick motion x' = v.
  double StickForceRate(double t) const {
    return v() + p_.force * p_.omega * std::sin(p_.omega * t);
  }
  bool InStickBand(double t, double x) const { return std::abs(StickForce(t, x)) <= p_.base.mu_s; }
  /// Filippov on x' = v, arriving from slip mode `from`: stick inside the band,
  /// else the side the one-sided accelerations point to (== from: a touch).
  Mode ModeAfterArrival(Mode from, double t, double x) const;
  /// The slip mode a stick phase leaves into (the sign of the force needed).
  Mode ExitMode(double t, double x) const {
    return StickForce(t, x) > 0 ? Mode::kSlipBelow : Mode::kSlipAbove;
  }

  /// Saltation matrices (di Bernardo et al. 2008, section 2.5) on the state
  /// (x, x'), for a switching surface h(t, z) = 0:
  ///   S = I + (f_after - f_before) grad h^T / (grad h . f_before + dh/dt).
  /// Entering stick (h = x' - v): diag(1, 0). Crossing x' = v: diag(1, a+/a-).
  /// Leaving stick (h = StickForce -+ mu_s, dh/dt = StickForceRate).
  Mat2 SaltationCrossing(Mode before, Mode after, double t, double x) const;
  Mat2 SaltationStickOut(Mode after, double t, double x) const;

 private:
  ForcedBeltParams p_;
  Friction friction_;
  double two_beta_;
};

}  // namespace stickslip
