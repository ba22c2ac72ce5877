// Friction laws mu(s), s = |x' - v| > 0, and the slip force F(u) = -sgn(u) mu(|u|)
// of seed eq. (3.5). A small value type: no virtual calls on the hot path.
#pragma once

#include "stickslip/params.hpp"

namespace stickslip {

/// The friction law mu(s) of a model and its derivatives in s >= 0.
class Friction {
 public:
  explicit Friction(const Params& p);

  LawKind law() const { return law_; }
  /// The static limit: stick holds while |x + 2 beta v| <= mu_s.
  double static_limit() const { return mu_s_; }
  /// mu(0+): equals mu_s for cubic, stribeck, leine; mu_k for coulomb.
  double mu0() const { return Mu(0.0); }

  /// mu(s) and its first three derivatives in s, for s >= 0 (one-sided at 0).
  double Mu(double s) const;
  double DMu(double s) const;
  double D2Mu(double s) const;
  double D3Mu(double s) const;
  /// Whether mu <= 0 somewhere on [0, s_max]: only the cubic law with k5 > 0 can
  /// (mu is then checked at s_max and at the roots of mu' = 0, a quadratic in s^2).
  bool NonPositiveUpTo(double s_max) const;
  /// Cubic law's quintic coefficient k5 (0 for the seed's law and the others).
  double k5() const { return c_; }

  /// Slip force F(u) = -sgn(u) mu(|u|) for u != 0, and F'(u) = -mu'(|u|).
  double Force(double u) const { return u < 0 ? Mu(-u) : -Mu(u); }
  double DForce(double u) const { return -DMu(u < 0 ? -u : u); }

 private:
  friend class MuSeries;
  LawKind law_;
  double mu_s_;
  double a_;  // cubic: k1; coulomb, stribeck: mu_k; leine: delta
  double b_;  // cubic: k3; stribeck: v_s
  double c_;  // cubic: k5 (the law stays an odd polynomial mu_s - k1 s + k3 s^3 - k5 s^5)
};

// Taylor coefficients of mu(s(t)) and mu'(s(t)) from those of s(t), order by
// order (automatic differentiation; Jorba & Zou 2005, section 2):
//   cubic:    an odd polynomial mu_s + sum_j c_j s^j by Cauchy products;
//   coulomb:  a constant;
//   stribeck: E = exp(u), u = -s / v_s: k E_k = sum_{j=1..k} j u_j E_{k-j};
//   leine:    Q = mu_s / D, D = 1 + delta s: Q_k = -sum_{j=1..k} D_j Q_{k-j} / D_0,
//             and mu' = -(delta / mu_s) Q^2.
class MuSeries {
 public:
  static constexpr int kMaxOrder = 40;
  explicit MuSeries(const Friction& f);
  // With s[0..k] given and orders 0..k-1 done before: mu_k, and mu'_k in *dmu
  // unless dmu is null (then later calls must pass null too).
  double Next(int k, const double* s, double* dmu);

 private:
  LawKind law_;
  double mu_s_ = 0, a_ = 0, b_ = 0;
  double c_[6] = {0, 0, 0, 0, 0, 0};  // cubic: odd coefficients c_1, c_3, c_5
  int degree_ = 1;                    // cubic: highest odd degree with c_j != 0
  double w_[5][kMaxOrder + 1];  // cubic: s^2..s^5 (rows 0..3); stribeck: u, E; leine: D, Q, Q^2
};

}  // namespace stickslip
