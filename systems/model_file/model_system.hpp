// A model file's system on the one interface (system.hpp): state (x1, x1',
// x2, x2', ...) by coordinate, one contact per `contact` line, parameters by
// name; every mode's field, Jacobian, stick forces and Taylor recurrences
// from its compiled tapes (compiled.hpp).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "model_file/compiled.hpp"
#include "stickslip/system/taylor_field.hpp"

namespace stickslip::model_file {

class ModelSystem final : public System {
 public:
  explicit ModelSystem(std::shared_ptr<const Compiled> c);
  const Compiled& compiled() const { return *c_; }
  const std::vector<double>& values() const { return p_; }
  /// The mode's program; where its stick forces are not determined (a
  /// singular set: not consistent) every field and force is NaN, so that the
  /// mode is never chosen and a run that needs it fails saying where.
  const ModeProgram& Program(const ModeSet& m) const;

  std::unique_ptr<System> Clone() const override { return std::make_unique<ModelSystem>(*this); }
  bool Assign(const System& s) override;
  std::string ValidationError() const override;

  int dimension() const override { return c_->n; }
  int contacts() const override { return c_->k; }
  int clocks() const override { return c_->clocks; }
  std::string StateName(int i) const override { return c_->state_names[i]; }
  int DerivativeOf(int i) const override { return c_->derivative_of[i]; }

  ContactVelocity Contact(int i) const override { return velocity_[i]; }
  std::optional<ContactVelocity> NormalForce(int i) const override;
  double StickForce(const ModeSet& m, int i, ConstState z) const override;
  void StickForceGradient(const ModeSet& m, int i, ConstState z, StateOut g) const override;
  double StaticLimit(int i, ConstState z) const override;
  void StaticLimitGradient(int i, ConstState z, StateOut g) const override;

  void Field(const ModeSet& m, ConstState z, StateOut f) const override;
  void Jacobian(const ModeSet& m, ConstState z, MatrixOut J) const override;
  std::unique_ptr<TaylorField> MakeTaylorField(const TaylorRequest& request) const override;
  /// Every parameter: its column's field is derived from the file (compiled.hpp).
  bool SupportsParameterColumn(int j) const override { return j >= 0 && j < parameters(); }
  ContactSensitivity ContactParameterDerivative(const ModeSet& m, int i, int j,
                                                ConstState z) const override;
  double ClockRateDerivative(int c, int j) const override;
  /// Newton from the origin on the field of a mode without stick; the point
  /// must lie on that mode's side of every contact.
  bool Rest(const ModeSet& m, StateOut z, bool* stable) const override;

  int parameters() const override { return static_cast<int>(p_.size()); }
  std::string ParameterName(int j) const override { return c_->parameters[j]; }
  double ParameterValue(int j) const override { return p_[j]; }
  void SetParameterValue(int j, double value) override;
  /// A parameter no expression of the file reads (a branch in it is flat).
  std::string ParameterError(int j) const override;

 private:
  void Update();  // the contact forms at the parameters
  // The full tape's nodes at (m, z): every value.
  void Values(const Tape& t, ConstState z, std::vector<double>& out) const;

  std::shared_ptr<const Compiled> c_;
  std::vector<double> p_;
  bool Newton(const ModeSet& m, Eigen::VectorXd& x) const;
  double Sliding(const Eigen::VectorXd& x) const;
  std::vector<ContactVelocity> velocity_, normal_;
  std::vector<double> static_;  // the static coefficients
  std::vector<double> contact_values_;
};

}  // namespace stickslip::model_file
