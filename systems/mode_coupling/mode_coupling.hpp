// A 2-DOF mode-coupling model of brake squeal (Hoffmann, Fischer, Sepehri &
// Gaul, Mech. Res. Commun. 29, 2002), tangential x and normal y, one contact
// whose normal force follows y (docs/theory.md, "Mode coupling"):
//   x'' + 2 beta x' + k11 x + k12 y = (1 - gamma y) F(x' - v),
//   y'' + 2 beta y' + k12 x + k22 y = 0,
// stick (x' = v) while |2 beta v + k11 x + k12 y| <= mu_s (1 - gamma y). The
// contact stays closed while N = 1 - gamma y > 0 (System::NormalForce): the
// flow stops with FlowStatus::kContactOpen where N reaches 0. Written from
// the installed headers only. State z = (x, x', y, y').
#pragma once

#include <memory>
#include <string>

#include "stickslip/system/system.hpp"
#include "stickslip/systems/belt/friction.hpp"
#include "stickslip/systems/belt/params.hpp"

namespace stickslip::mode_coupling {

struct CouplingParams {
  double beta = 0.02, k11 = 1, k22 = 1.5, k12 = -0.3, gamma = 1, v = 0.5;
  Params law;  ///< the contact's law (its beta and v are not read)
};

/// The mu_k above which steady sliding under Coulomb friction flutters
/// (mode coupling; docs/theory.md): with D = (k11 - k22)^2 + 4 k12^2,
///   mu_k* = -(D + 8 beta^2 (k11 + k22)) / (4 gamma k12);
/// NaN where gamma k12 >= 0 (the follower term cannot merge the modes).
double FlutterMuK(const CouplingParams& p);

class ModeCoupling final : public System {
 public:
  /// Throws InvalidArgument naming the offending value.
  explicit ModeCoupling(const CouplingParams& p);
  const CouplingParams& params() const { return p_; }
  const Friction& friction() const { return friction_; }

  std::unique_ptr<System> Clone() const override { return std::make_unique<ModeCoupling>(*this); }
  bool Assign(const System& s) override;
  std::string ValidationError() const override;

  int dimension() const override { return 4; }
  int contacts() const override { return 1; }
  std::string StateName(int i) const override;
  int DerivativeOf(int i) const override { return i % 2 == 0 ? i + 1 : -1; }

  ContactVelocity Contact(int) const override;
  /// N = 1 - gamma y.
  std::optional<ContactVelocity> NormalForce(int) const override;
  double StickForce(const ModeSet&, int, ConstState z) const override {
    return 2 * p_.beta * p_.v + p_.k11 * z[0] + p_.k12 * z[2];
  }
  void StickForceGradient(const ModeSet&, int, ConstState, StateOut g) const override;
  double StaticLimit(int, ConstState z) const override {
    return p_.law.mu_s * (1 - p_.gamma * z[2]);
  }
  void StaticLimitGradient(int, ConstState, StateOut g) const override;
  /// Moves x alone onto the limit (y, and so the limit, stay).
  void ProjectOnExit(const ModeSet& m, int i, double bound, StateOut z) const override;

  void Field(const ModeSet& m, ConstState z, StateOut f) const override;
  void Jacobian(const ModeSet& m, ConstState z, MatrixOut J) const override;
  std::unique_ptr<TaylorField> MakeTaylorField(const TaylorRequest& request) const override;
  /// Steady sliding in slip below: [[k11, k12 + gamma mu(v)], [k12, k22]]
  /// (x, y) = (mu(v), 0), x' = y' = 0; stable when J's eigenvalues are.
  bool Rest(const ModeSet& m, StateOut z, bool* stable) const override;

  /// "beta", "k11", "k22", "k12", "gamma", "v", "mu_s", "mu_k".
  int parameters() const override { return 8; }
  std::string ParameterName(int j) const override;
  double ParameterValue(int j) const override;
  void SetParameterValue(int j, double value) override;

  /// F(x' - v) on the mode's branch (extended across x' = v) and dF/dx'.
  double SlipForce(Mode m, double xd) const;
  double SlipForceSlope(Mode m, double xd) const;

 private:
  double* Member(int j);
  CouplingParams p_;
  Friction friction_;
};

}  // namespace stickslip::mode_coupling
