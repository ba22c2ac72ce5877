// Private to src/: Taylor coefficients of mu(s(t)) and mu'(s(t)) from those of
// s(t), order by order (automatic differentiation; Jorba & Zou 2005, section 2):
//   cubic:    an odd polynomial mu_s + sum_j c_j s^j by Cauchy products;
//   coulomb:  a constant;
//   stribeck: E = exp(u), u = -s / v_s: k E_k = sum_{j=1..k} j u_j E_{k-j};
//   leine:    Q = mu_s / D, D = 1 + delta s: Q_k = -sum_{j=1..k} D_j Q_{k-j} / D_0,
//             and mu' = -(delta / mu_s) Q^2.
// Inline and a template in the law, so that the recurrences of the Taylor
// stepper compile to one loop per law.
#pragma once

#include <algorithm>
#include <cmath>

#include "integrate/series.hpp"
#include "stickslip/systems/belt/friction.hpp"

namespace stickslip {

class MuSeries {
 public:
  static constexpr int kMaxOrder = 40;
  explicit MuSeries(const Friction& f)
      : law_(f.law_), mu_s_(f.mu_s_), a_(f.a_), b_(f.b_), k5_(f.c_) {
    if (law_ == LawKind::kCubic) {  // seed (3.3): mu_s - k1 s + k3 s^3, and - k5 s^5
      c_[1] = -a_;
      c_[3] = b_;
      c_[5] = -f.c_;
      for (int j = 1; j <= 5; j += 2)
        if (c_[j] != 0) degree_ = j;
    }
    if (law_ == LawKind::kStribeck) inv_b_ = 1 / b_;
  }
  LawKind law() const { return law_; }
  // Whether this is f's series (Bind keeps it then: Begin readies it per step).
  bool Of(const Friction& f) const {
    return law_ == f.law_ && mu_s_ == f.mu_s_ && a_ == f.a_ && b_ == f.b_ && k5_ == f.c_;
  }
  double mu_s() const { return mu_s_; }
  // cubic: the odd coefficient c_j of mu_s + c_1 s + c_3 s^3 + c_5 s^5 (j = 1, 3, 5).
  double cubic(int j) const { return c_[j]; }

  // Each step: Begin(order) clears the rows the law's sums read past k; then
  // for k = 0, 1, ...: Old(k) before s_k is set (the sums of products of
  // earlier coefficients, off the critical path; the cubic's need s_k and
  // later 0), then New(k) once s_k is set: mu_k, and mu'_k in *dmu when D
  // (every call of this series passes the same D).
  template <LawKind L>
  void Begin(int order) {
    // The cubic's and Leine's sums read w_[.][k] (and padding) at Old(k): cleared.
    // Stribeck's read only coefficients below k (CauchyNewestLast), each written
    // by New before; Coulomb has no rows.
    const int rows = L == LawKind::kCubic ? (degree_ >= 5 ? 3 : 1) : L == LawKind::kLeine ? 3 : 0;
    for (int r = 0; r < rows; ++r)
      for (int k = 0; k < order + kPad; ++k) w_[r].c()[k] = 0;
  }
  template <LawKind L, bool D>
  void Old(int k, const double* s);
  template <LawKind L, bool D>
  double New(int k, const double* s, double* dmu);
  // mu_k = Alpha(k) + slope() s_k for k >= 1 (Alpha(k, sign) gives sign mu_k's part) (after Old(k),
  // and New(0) for the slope mu'(s_0)): mu_k is linear in s_k, so the recurrences need not wait for
  // New(k).
  template <LawKind L>
  double Alpha(int k, double sign = 1) const;
  double slope() const { return slope_; }

 private:
  LawKind law_;
  double mu_s_ = 0, a_ = 0, b_ = 0, k5_ = 0;
  double c_[6] = {0, 0, 0, 0, 0, 0};  // cubic: odd coefficients c_1, c_3, c_5
  int degree_ = 1;                    // cubic: highest odd degree with c_j != 0
  // cubic: s^2, -, s^4 (rows 0, 2); stribeck: u, E, j u_j; leine: D, Q, Q^2.
  Series<kMaxOrder> w_[4];
  double old_[4] = {0, 0, 0, 0};  // Old(k)'s sums, one per product
  double slope_ = 0;              // mu'(s_0)
  double inv_b_ = 0;              // stribeck: 1 / v_s
  double inv_d0_ = 0;             // leine: 1 / D_0, once per step
  // 1 / k at [k - 1]: the recurrences multiply, a division per coefficient
  // sat on their critical path.
  static constexpr Reciprocals<kMaxOrder> kInverse{};
  double s0_ = 0;  // cubic: s_0
};

template <LawKind L, bool D>
inline void MuSeries::Old(int k, const double* s) {
  if constexpr (L == LawKind::kCubic) {
    // Sums of the products s^2 = s s, s^3 = s^2 s, s^4 = s^2 s^2, s^5 = s^4 s.
    old_[0] = Cauchy(s, s, k);
    if (degree_ >= 3) old_[1] = Cauchy(w_[0].c(), s, k);
    if (degree_ >= 5) {
      old_[2] = Cauchy(w_[0].c(), w_[0].c(), k);
      old_[3] = Cauchy(w_[2].c(), s, k);
    }
  } else if constexpr (L == LawKind::kStribeck) {
    // sum_{1 <= j < k} j u_j E_{k-j}: the chain E_{k-1} -> old -> E_k is the
    // recurrence's latency, so E_{k-1} and u_{k-1} enter last.
    old_[0] = CauchyNewestLast(w_[2].c(), w_[1].c(), k);
  } else if constexpr (L == LawKind::kLeine) {
    if (k > 0) old_[0] = Cauchy(w_[0].c() + 1, w_[1].c(), k - 1);  // sum_{1 <= j < k} D_j Q_{k-j}
    if (D) old_[1] = Cauchy(w_[1].c(), w_[1].c(), k);
  }
}

// Coefficient k of a product p q from its old part and the two new terms
// (j = 0 and j = k; one term at k = 0).
inline double Product(double old, double p0, double pk, double q0, double qk, int k) {
  return k == 0 ? p0 * q0 : old + (p0 * qk + pk * q0);
}
// The same for p = q: 2 p0 pk is exact doubling, one operation shorter.
inline double SquareProduct(double old, double p0, double pk, int k) {
  return k == 0 ? p0 * p0 : old + (2 * p0) * pk;
}

template <LawKind L, bool D>
inline double MuSeries::New(int k, const double* s, double* dmu) {
  const double c0 = k == 0 ? 1.0 : 0.0;
  if constexpr (L == LawKind::kCubic) {
    // Only s^2 and s^4 (rows 0, 2) enter later products; s^3 and s^5 are
    // coefficient k of mu alone.
    double* w0 = w_[0].c();
    double* w2 = w_[2].c();
    w0[k] = SquareProduct(old_[0], s[0], s[k], k);
    if (k == 0) {
      s0_ = s[0];
      slope_ = c_[1] + w0[0] * (3 * c_[3] + 5 * c_[5] * w0[0]);
    }
    double mu = c0 * mu_s_ + c_[1] * s[k];
    if (degree_ >= 3) mu += c_[3] * Product(old_[1], w0[0], w0[k], s[0], s[k], k);
    if (degree_ >= 5) {
      w2[k] = SquareProduct(old_[2], w0[0], w0[k], k);
      mu += c_[5] * Product(old_[3], w2[0], w2[k], s[0], s[k], k);
    }
    if constexpr (D) {
      *dmu = c0 * c_[1] + 3 * c_[3] * w0[k];
      if (degree_ >= 5) *dmu += 5 * c_[5] * w2[k];
    }
    return mu;
  } else if constexpr (L == LawKind::kCoulomb) {
    if constexpr (D) *dmu = 0;
    return c0 * a_;
  } else if constexpr (L == LawKind::kStribeck) {
    double* u = w_[0].c();
    double* e = w_[1].c();
    double* ju = w_[2].c();  // j u_j
    u[k] = -s[k] * inv_b_;
    ju[k] = k * u[k];
    e[k] = k == 0 ? std::exp(u[0]) : (old_[0] + ju[k] * e[0]) * kInverse.r[k - 1];
    if (k == 0) slope_ = -(mu_s_ - a_) * inv_b_ * e[0];
    if constexpr (D) *dmu = -(mu_s_ - a_) * inv_b_ * e[k];
    return c0 * a_ + (mu_s_ - a_) * e[k];
  } else {  // leine
    double* d = w_[0].c();
    double* q = w_[1].c();
    d[k] = c0 + a_ * s[k];
    if (k == 0) inv_d0_ = 1 / d[0];
    q[k] = (k == 0 ? mu_s_ : -(old_[0] + d[k] * q[0])) * inv_d0_;
    if (k == 0) slope_ = -a_ * q[0] * inv_d0_;
    if constexpr (D) {
      w_[2].c()[k] = SquareProduct(old_[1], q[0], q[k], k);
      *dmu = -(a_ / mu_s_) * w_[2].c()[k];
    }
    return q[k];
  }
}

template <LawKind L>
inline double MuSeries::Alpha(int k, double sign) const {
  if constexpr (L == LawKind::kCubic) {
    // w1_k = old1 + s0 old0 + 3 s0^2 s_k, w3_k = old3 + s0 old2 + 2 s0^3 old0 + 5 s0^4 s_k.
    if (degree_ < 3) return 0.0;
    const double a = (sign * c_[3]) * (old_[1] + s0_ * old_[0]);
    if (degree_ < 5) return a;
    return a + (sign * c_[5]) * (old_[3] + s0_ * old_[2] + 2 * s0_ * w_[0].c()[0] * old_[0]);
  } else if constexpr (L == LawKind::kStribeck) {
    return (sign * (mu_s_ - a_)) * old_[0] * kInverse.r[k - 1];
  } else if constexpr (L == LawKind::kLeine) {
    return -(sign * old_[0]) * inv_d0_;
  } else {
    return 0.0;
  }
}

}  // namespace stickslip
