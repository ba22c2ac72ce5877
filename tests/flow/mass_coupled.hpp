// A test system whose stick forces depend on the other contacts' modes (the
// modes-as-sets tests, switching.hpp): K blocks coupled by their masses alone,
// M x'' = g + r with M = mass (I + e (J - I)) (J all ones), g_i = -x_i - c x_i',
// r_i the friction force of contact i (slip below: +mu_k, above: -mu_k; stick:
// the force that holds x_i'' = 0). M^-1 = a I + b J keeps the arithmetic of
// alike blocks alike, and W_SS = a I + b J of the sticking ones is inverted by
// Sherman-Morrison.
#pragma once

#include <Eigen/Dense>
#include <memory>
#include <string>

#include "stickslip/errors.hpp"
#include "stickslip/system/system.hpp"
#include "stickslip/system/taylor_field.hpp"

namespace stickslip {

struct Coupling {
  int blocks = 2;
  double e = -0.5, mass = 1, c = 0, v = 0.2, mu_s = 0.4, mu_k = 0.3;
  int terms = 1;      // of each contact's velocity (a bad system: 0)
  double weight = 1;  // of its term (a bad system: 0)
};

class MassCoupled final : public System {
 public:
  explicit MassCoupled(const Coupling& p) : p_(p) {
    const int k = p.blocks;
    a_ = 1 / (p.mass * (1 - p.e));
    b_ = -p.e / (p.mass * (1 - p.e) * (1 + (k - 1) * p.e));
  }
  std::unique_ptr<System> Clone() const override { return std::make_unique<MassCoupled>(*this); }
  bool Assign(const System& s) override {
    const auto* o = dynamic_cast<const MassCoupled*>(&s);
    if (o) *this = *o;
    return o != nullptr;
  }
  std::string ValidationError() const override { return ""; }
  int dimension() const override { return 2 * p_.blocks; }
  int contacts() const override { return p_.blocks; }
  std::string StateName(int i) const override {
    return "x" + std::to_string(i / 2 + 1) + (i % 2 ? "'" : "");
  }
  int DerivativeOf(int i) const override { return i % 2 == 0 ? i + 1 : -1; }
  ContactVelocity Contact(int i) const override {
    ContactVelocity c;
    c.terms[0] = {2 * i + 1, p_.weight};
    c.size = p_.terms;
    c.speed = p_.v;
    return c;
  }
  // u = g + r with r_S = 0: slip forces, and the sticking contacts' r_S
  // from (M^-1 (u + r_S))_S = 0.
  Eigen::VectorXd Forces(const ModeSet& m, ConstState z) const {
    const int k = p_.blocks;
    Eigen::VectorXd u(k), r = Eigen::VectorXd::Zero(k);
    double total = 0;
    for (int i = 0; i < k; ++i) {
      if (!m.sticks(i)) r[i] = m[i] == Mode::kSlipBelow ? p_.mu_k : -p_.mu_k;
      total += u[i] = -z[2 * i] - p_.c * z[2 * i + 1] + r[i];
    }
    double free_sum = 0;
    int s = 0;
    for (int i = 0; i < k; ++i)
      if (m.sticks(i)) free_sum += a_ * u[i] + b_ * total, ++s;
    for (int i = 0; i < k; ++i)
      if (m.sticks(i)) r[i] = -(a_ * u[i] + b_ * total - b_ / (a_ + s * b_) * free_sum) / a_;
    return r;
  }
  double StickForce(const ModeSet& m, int i, ConstState z) const override {
    return Forces(m, z)[i];
  }
  void StickForceGradient(const ModeSet& m, int i, ConstState z, StateOut g) const override {
    Eigen::VectorXd y = z;
    const double f0 = StickForce(m, i, z);
    for (int j = 0; j < dimension(); ++j) {  // affine in z: exact differences of step 1
      y = z;
      y[j] += 1;
      g[j] = StickForce(m, i, y) - f0;
    }
  }
  double StaticLimit(int, ConstState) const override { return p_.mu_s; }
  void Field(const ModeSet& m, ConstState z, StateOut f) const override {
    const int k = p_.blocks;
    const Eigen::VectorXd r = Forces(m, z);
    Eigen::VectorXd u(k);
    double total = 0;
    for (int i = 0; i < k; ++i) total += u[i] = -z[2 * i] - p_.c * z[2 * i + 1] + r[i];
    for (int i = 0; i < k; ++i) {
      f[2 * i] = m.sticks(i) ? p_.v : z[2 * i + 1];
      f[2 * i + 1] = m.sticks(i) ? 0.0 : a_ * u[i] + b_ * total;
    }
  }
  void Jacobian(const ModeSet& m, ConstState z, MatrixOut J) const override {
    const int n = dimension();
    Eigen::VectorXd f0(n), f1(n), y(n);
    Field(m, z, f0);
    for (int j = 0; j < n; ++j) {
      y = z;
      y[j] += 1;
      Field(m, y, f1);
      J.col(j) = f1 - f0;
    }
  }
  std::unique_ptr<TaylorField> MakeTaylorField(const TaylorRequest&) const override {
    throw InvalidArgument("MassCoupled: CVODE only");
  }
  int parameters() const override { return 0; }
  std::string ParameterName(int) const override { return ""; }
  double ParameterValue(int) const override { return 0; }
  void SetParameterValue(int, double) override {}

 private:
  Coupling p_;
  double a_ = 1, b_ = 0;
};

}  // namespace stickslip
