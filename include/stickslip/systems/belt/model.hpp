// The Filippov belt model, seed eq. (3.5): a one-contact system on the one
// system interface (friction_system.hpp, system.hpp). Fields, Jacobians,
// stick condition, steady sliding; its Taylor recurrences are
// src/systems/belt/belt_taylor.cpp (shared with the forced oscillator, forced.hpp).
#pragma once

#include <memory>
#include <string>

#include "stickslip/systems/belt/friction.hpp"
#include "stickslip/systems/belt/friction_system.hpp"
#include "stickslip/systems/belt/parameter_axis.hpp"
#include "stickslip/systems/belt/params.hpp"

namespace stickslip {

/// Whether the belt's parameter column (BeltFlow::set_parameter_column) supports
/// this parameter under this law: beta, v, and every law parameter mu(s)
/// depends on affinely (all but v_m, v_s and delta of their own laws).
bool ParameterColumnSupported(LawKind law, const ParameterAxis& axis);
/// The belt's contact events in parameter j (Parameter's order): the speed
/// v, the stick force x + 2 beta v and the static limit mu_s.
ContactSensitivity BeltContactDerivative(const Params& p, int j);

/// The belt model for one parameter set: fields, Jacobians, switching rules.
/// Its parameters (System's lenses) are the Parameter enum's, in its order.
class Model final : public FrictionSystem {
 public:
  /// Validates p (throws InvalidArgument naming the offending value).
  explicit Model(const Params& p);

  std::unique_ptr<System> Clone() const override { return std::make_unique<Model>(*this); }
  bool Assign(const System& s) override;
  std::string ValidationError() const override { return stickslip::ValidationError(p_); }

  const Params& params() const { return p_; }
  const Friction& friction() const { return friction_; }
  double v() const override { return p_.v; }
  double beta() const { return p_.beta; }

  /// x'' in a slip mode: the mode's branch of the friction law, extended
  /// smoothly across x' = v, so that event location sees a smooth function.
  double Acceleration(Mode m, double x, double xdot) const override {
    return -x - two_beta_ * xdot + SlipForce(m, xdot);
  }
  using FrictionSystem::Jacobian;
  Mat2 Jacobian(Mode m, const Vec2& z) const override;
  std::unique_ptr<TaylorField> MakeTaylorField(const TaylorRequest& request) const override;
  /// beta, v, and every law parameter mu(s) depends on affinely.
  bool SupportsParameterColumn(const ParameterAxis& parameter) const;
  bool SupportsParameterColumn(int j) const override;
  ContactSensitivity ContactParameterDerivative(const ModeSet&, int, int j,
                                                ConstState) const override {
    return BeltContactDerivative(p_, j);
  }
  /// dF/dx' on the mode's branch.
  double SlipForceSlope(Mode m, double xdot) const {
    return m == Mode::kSlipBelow ? -friction_.DMu(p_.v - xdot) : -friction_.DMu(xdot - p_.v);
  }
  double SlipForce(Mode m, double xdot) const {
    return m == Mode::kSlipBelow ? friction_.Mu(p_.v - xdot) : -friction_.Mu(xdot - p_.v);
  }

  /// Force needed to hold x' = v: x + 2 beta v. Stick holds while |.| <= mu_s.
  using FrictionSystem::StickForce;
  double StickForce(double x) const override { return x + two_beta_ * p_.v; }
  double static_limit() const override { return p_.mu_s; }
  /// Every stick segment leaves Omega at (x0, v), x0 = mu_s - 2 beta v (seed, case 1).
  Vec2 ExitPoint() const override { return Vec2(p_.mu_s - two_beta_ * p_.v, p_.v); }

  /// Steady sliding x = mu(v), x' = 0; eigenvalues solve
  /// lambda^2 + (2 beta + mu'(v)) lambda + 1 = 0 (linearised seed eq. 3.5).
  Equilibrium SteadySliding() const override;
  /// True where the energy E = ((x - mu(v))^2 + x'^2) / 2 provably decreases
  /// along every trajectory (proof in model.cpp): then no periodic orbit
  /// exists, of any kind, and steady sliding attracts every state.
  bool NoPeriodicOrbit() const;

  // The parameters by index (Parameter's order).
  int parameters() const override;
  std::string ParameterName(int j) const override;
  /// AxisError: a parameter of another friction law.
  std::string ParameterError(int j) const override;
  double ParameterValue(int j) const override;
  void SetParameterValue(int j, double value) override;

 private:
  Params p_;
  Friction friction_;
  double two_beta_;
};

}  // namespace stickslip
