// A user's own friction system, written against the installed headers only
// (stickslip/system/system.hpp, taylor_field.hpp, mode.hpp): one block on a
// belt with its own friction law,
//   x'' + 2 beta x' + x = F(x' - v),   F(u) = -sgn(u) mu(|u|),
//   mu(s) = mu_k + (mu_s - mu_k) exp(-s / v_s) + eta s   (s > 0),
// an exponential Stribeck curve plus viscous friction. It sticks (x' = v)
// while |x + 2 beta v| <= mu_s. State z = (x, x'), one contact with relative
// velocity h = x' - v (docs/theory.md, "One core": the system describes its
// fields, contacts and parameters; the library does the rest). The program
// that runs it is own_system.cpp.
#pragma once

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>

#include "stickslip/system/taylor_field.hpp"

namespace own {

using stickslip::ConstState;
using stickslip::Mode;
using stickslip::ModeSet;

struct BeltParams {
  double beta = 0.05, v = 0.3, mu_s = 0.4, mu_k = 0.25, v_s = 0.5, eta = 0.02;
};

class StribeckBelt final : public stickslip::System {
 public:
  explicit StribeckBelt(const BeltParams& p) : p_(p) {}
  const BeltParams& params() const { return p_; }

  // --- Copies (the library clones the system into its flows) ---
  std::unique_ptr<System> Clone() const override { return std::make_unique<StribeckBelt>(*this); }
  bool Assign(const System& s) override {
    const auto* o = dynamic_cast<const StribeckBelt*>(&s);
    if (o) *this = *o;
    return o != nullptr;
  }
  std::string ValidationError() const override {
    for (int j = 0; j < parameters(); ++j)
      if (!std::isfinite(ParameterValue(j))) return ParameterName(j) + " must be finite";
    if (!(p_.beta >= 0)) return "beta must be >= 0";
    if (!(p_.v > 0)) return "v must be > 0";
    if (!(p_.mu_s >= p_.mu_k && p_.mu_k > 0)) return "need mu_s >= mu_k > 0";
    if (!(p_.v_s > 0 && p_.eta >= 0)) return "need v_s > 0 and eta >= 0";
    return "";
  }

  // --- Sizes and names ---
  int dimension() const override { return 2; }
  int contacts() const override { return 1; }
  std::string StateName(int i) const override { return i == 0 ? "x" : "x'"; }
  int DerivativeOf(int i) const override { return i == 0 ? 1 : -1; }  // x' = dx/dt

  // --- The contact: h = x' - v; stick force lambda = x + 2 beta v (x'' = 0
  // in stick needs F = lambda; lambda > 0 pulls the block back, below the belt).
  stickslip::ContactVelocity Contact(int) const override {
    stickslip::ContactVelocity c;
    c.terms[0] = {1, 1.0};  // weight 1 on z[1] = x'
    c.size = 1;
    c.speed = p_.v;
    return c;
  }
  double StickForce(const ModeSet&, int, ConstState z) const override {
    return z[0] + 2 * p_.beta * p_.v;
  }
  void StickForceGradient(const ModeSet&, int, ConstState, stickslip::StateOut g) const override {
    g << 1, 0;
  }
  double StaticLimit(int, ConstState) const override { return p_.mu_s; }
  /// lambda is linear in x: the exit point is x = bound - 2 beta v exactly.
  void ProjectOnExit(const ModeSet&, int, double bound, stickslip::StateOut z) const override {
    z[0] = bound - 2 * p_.beta * p_.v;
  }

  // --- The law: sigma = +1 slipping below (s = v - x'), -1 above (s = x' - v).
  static double Sigma(Mode m) { return m == Mode::kSlipBelow ? 1.0 : -1.0; }
  double Mu(double s) const {
    return p_.mu_k + (p_.mu_s - p_.mu_k) * std::exp(-s / p_.v_s) + p_.eta * s;
  }
  /// dF/dx' = -mu'(s) on either branch (extended across s = 0).
  double ForceSlope(double s) const {
    return (p_.mu_s - p_.mu_k) / p_.v_s * std::exp(-s / p_.v_s) - p_.eta;
  }

  // --- Fields (the Jacobian on the tangent block, here all of z) ---
  void Field(const ModeSet& m, ConstState z, stickslip::StateOut f) const override {
    if (m.sticks(0)) {
      f << p_.v, 0;
      return;
    }
    const double sigma = Sigma(m[0]), s = sigma * (p_.v - z[1]);
    f << z[1], -2 * p_.beta * z[1] - z[0] + sigma * Mu(s);
  }
  void Jacobian(const ModeSet& m, ConstState z, stickslip::MatrixOut J) const override {
    J.setZero();
    if (m.sticks(0)) return;
    const double s = Sigma(m[0]) * (p_.v - z[1]);
    J << 0, 1, -1, -2 * p_.beta + ForceSlope(s);
  }
  std::unique_ptr<stickslip::TaylorField> MakeTaylorField(
      const stickslip::TaylorRequest& request) const override;
  /// Steady sliding: x = mu(v), x' = 0, stable while 2 beta > dF/dx'.
  bool Rest(const ModeSet& m, stickslip::StateOut z, bool* stable) const override {
    if (m[0] != Mode::kSlipBelow) return false;
    z << Mu(p_.v), 0;
    *stable = 2 * p_.beta > ForceSlope(p_.v);
    return true;
  }

  // --- Parameters by name: ParameterIndex("v") is the continued lens ---
  int parameters() const override { return 6; }
  std::string ParameterName(int j) const override {
    static const char* names[] = {"beta", "v", "mu_s", "mu_k", "v_s", "eta"};
    return names[j];
  }
  double ParameterValue(int j) const override {
    return *const_cast<StribeckBelt*>(this)->Member(j);
  }
  void SetParameterValue(int j, double value) override { *Member(j) = value; }

 private:
  double* Member(int j) {
    double* m[] = {&p_.beta, &p_.v, &p_.mu_s, &p_.mu_k, &p_.v_s, &p_.eta};
    return m[j];
  }
  BeltParams p_;
};

// The Taylor recurrences (taylor_field.hpp; Jorba & Zou 2005). Given
// coefficients 0..k of every row, coefficient k+1 of the state is
//   x_{k+1} = x'_k / (k+1),  x'_{k+1} = (-2 beta x'_k - x_k + sigma mu_k) / (k+1),
// with mu_k the k-th coefficient of mu(s(t)): s_k = sigma ([k = 0] v - x'_k),
// and e = exp(a), a = -s / v_s, from e' = a' e:
//   e_0 = exp(a_0),  e_k = (1/k) sum_{j=1..k} j a_j e_{k-j}.
// Phi' = J Phi: q0' = q1, q1' = -q0 - 2 beta q1 + (g q1) with the series of
// g = dF/dx' = (mu_s - mu_k)/v_s e - eta (a Cauchy product). In stick x = x0
// + v t, x' = v, J = 0; the auxiliary rows are lambda = x + 2 beta v and mu_s.
class StribeckField final : public stickslip::TaylorField {
 public:
  bool Bind(const stickslip::System& s, const ModeSet& m) override {
    const auto* o = dynamic_cast<const StribeckBelt*>(&s);
    if (!o) return false;  // another system: the stepper asks it for its own field
    p_ = o->params();
    stick_ = m.sticks(0);
    sigma_ = StribeckBelt::Sigma(m[0]);
    return true;
  }
  int AuxRows() const override { return stick_ ? 2 : 0; }
  void Coefficients(int order, const stickslip::TaylorLayout& l, stickslip::TaylorRow* c) override {
    double *x = c[0], *xd = c[1];
    for (int k = 0; k < order; ++k) {
      const double inv = 1.0 / (k + 1);
      if (stick_) {
        x[k + 1] = k == 0 ? p_.v : 0.0;
        xd[k + 1] = 0;
      } else {
        Law(k, xd);
        x[k + 1] = xd[k] * inv;
        xd[k + 1] = (-2 * p_.beta * xd[k] - x[k] + sigma_ * mu_[k]) * inv;
      }
      if (l.variational) Phi(k, l, c);
    }
    if (stick_) StickRows(order, l, c);
  }

 private:
  static constexpr int kN = stickslip::kTaylorRowSize;

  // Coefficient k of s, a, e = exp(a), mu and g from x'_0..x'_k.
  void Law(int k, const double* xd) {
    s_[k] = sigma_ * ((k == 0 ? p_.v : 0.0) - xd[k]);
    a_[k] = -s_[k] / p_.v_s;
    if (k == 0) {
      e_[0] = std::exp(a_[0]);
    } else {
      double sum = 0;
      for (int j = 1; j <= k; ++j) sum += j * a_[j] * e_[k - j];
      e_[k] = sum / k;
    }
    const double dmu = p_.mu_s - p_.mu_k;
    mu_[k] = dmu * e_[k] + p_.eta * s_[k] + (k == 0 ? p_.mu_k : 0.0);
    g_[k] = dmu / p_.v_s * e_[k] - (k == 0 ? p_.eta : 0.0);
  }

  // Coefficient k+1 of Phi's columns (column-major, tangent entries each).
  void Phi(int k, const stickslip::TaylorLayout& l, stickslip::TaylorRow* c) const {
    const double inv = 1.0 / (k + 1);
    for (int col = 0; col < l.tangent; ++col) {
      double* q0 = c[l.phi() + col * l.tangent];
      double* q1 = c[l.phi() + col * l.tangent + 1];
      if (stick_) {
        q0[k + 1] = q1[k + 1] = 0;
        continue;
      }
      double gq = 0;  // (g q1)_k
      for (int j = 0; j <= k; ++j) gq += g_[j] * q1[k - j];
      q0[k + 1] = q1[k] * inv;
      q1[k + 1] = (-q0[k] - 2 * p_.beta * q1[k] + gq) * inv;
    }
  }

  // The events' rows of a sticking contact: lambda_i, then its static limit.
  void StickRows(int order, const stickslip::TaylorLayout& l, stickslip::TaylorRow* c) const {
    double* lam = c[l.aux_first()];
    double* lim = c[l.aux_first() + 1];
    std::fill(lam, lam + kN, 0.0);  // entries past order stay finite
    std::fill(lim, lim + kN, 0.0);
    for (int k = 0; k <= order; ++k) lam[k] = c[0][k];
    lam[0] += 2 * p_.beta * p_.v;
    lim[0] = p_.mu_s;
  }

  BeltParams p_;
  bool stick_ = false;
  double sigma_ = 1;
  double s_[kN] = {}, a_[kN] = {}, e_[kN] = {}, mu_[kN] = {}, g_[kN] = {};
};

inline std::unique_ptr<stickslip::TaylorField> StribeckBelt::MakeTaylorField(
    const stickslip::TaylorRequest&) const {
  // No parameter column (SupportsParameterColumn stays false): the branch
  // driver takes dF/dp by differences.
  return std::make_unique<StribeckField>();
}

}  // namespace own
