#include "stickslip/friction.hpp"

#include <algorithm>
#include <cmath>

namespace stickslip {

Friction::Friction(const Params& p) : law_(p.law), mu_s_(p.mu_s), a_(0), b_(0), c_(0) {
  switch (law_) {
    case LawKind::kCubic:
      a_ = p.k1();
      b_ = p.k3();
      c_ = p.k5;
      break;
    case LawKind::kCoulomb:
      a_ = p.mu_k;
      break;
    case LawKind::kStribeck:
      a_ = p.mu_k;
      b_ = p.v_s;
      break;
    case LawKind::kLeine:
      a_ = p.delta;
      break;
  }
}

double Friction::Mu(double s) const {
  switch (law_) {
    case LawKind::kCubic: {  // seed (3.3): mu_s - k1 s + k3 s^3, with the quintic - k5 s^5
      // The cubic terms in the seed's order, so that k5 = 0 rounds as before.
      const double cubic = mu_s_ - a_ * s + b_ * s * s * s;
      return c_ == 0 ? cubic : cubic - c_ * s * s * s * s * s;
    }
    case LawKind::kCoulomb:
      return a_;
    case LawKind::kStribeck:
      return a_ + (mu_s_ - a_) * std::exp(-s / b_);
    case LawKind::kLeine:  // Leine et al. (1998): mu_s / (1 + delta s)
      return mu_s_ / (1.0 + a_ * s);
  }
  return 0;
}

double Friction::DMu(double s) const {
  switch (law_) {
    case LawKind::kCubic: {
      const double cubic = -a_ + 3.0 * b_ * s * s;
      return c_ == 0 ? cubic : cubic - 5.0 * c_ * s * s * s * s;
    }
    case LawKind::kCoulomb:
      return 0.0;
    case LawKind::kStribeck:
      return -(mu_s_ - a_) / b_ * std::exp(-s / b_);
    case LawKind::kLeine: {
      const double d = 1.0 + a_ * s;
      return -mu_s_ * a_ / (d * d);
    }
  }
  return 0;
}

double Friction::D2Mu(double s) const {
  switch (law_) {
    case LawKind::kCubic:
      return s * (6.0 * b_ - 20.0 * c_ * s * s);
    case LawKind::kCoulomb:
      return 0.0;
    case LawKind::kStribeck:
      return (mu_s_ - a_) / (b_ * b_) * std::exp(-s / b_);
    case LawKind::kLeine: {
      const double d = 1.0 + a_ * s;
      return 2.0 * mu_s_ * a_ * a_ / (d * d * d);
    }
  }
  return 0;
}

double Friction::D3Mu(double s) const {
  switch (law_) {
    case LawKind::kCubic:
      return 6.0 * b_ - 60.0 * c_ * s * s;
    case LawKind::kCoulomb:
      return 0.0;
    case LawKind::kStribeck:
      return -(mu_s_ - a_) / (b_ * b_ * b_) * std::exp(-s / b_);
    case LawKind::kLeine: {
      const double d = 1.0 + a_ * s;
      return -6.0 * mu_s_ * a_ * a_ * a_ / (d * d * d * d);
    }
  }
  return 0;
}

bool Friction::NonPositiveUpTo(double s_max) const {
  if (law_ != LawKind::kCubic || c_ == 0) return false;  // the laws' mu > 0 on s >= 0
  if (!(Mu(std::max(s_max, 0.0)) > 0)) return true;
  // mu' = -k1 + 3 k3 s^2 - 5 k5 s^4 = 0: s^2 = (3 k3 -+ sqrt(9 k3^2 - 20 k1 k5)) / (10 k5).
  const double disc = 9.0 * b_ * b_ - 20.0 * a_ * c_;
  if (disc < 0) return false;
  for (double sign : {-1.0, 1.0}) {
    const double s2 = (3.0 * b_ + sign * std::sqrt(disc)) / (10.0 * c_);
    if (s2 > 0 && std::sqrt(s2) < s_max && !(Mu(std::sqrt(s2)) > 0)) return true;
  }
  return false;
}

MuSeries::MuSeries(const Friction& f) : law_(f.law_), mu_s_(f.mu_s_), a_(f.a_), b_(f.b_) {
  if (law_ == LawKind::kCubic) {  // seed (3.3): mu_s - k1 s + k3 s^3, and - k5 s^5
    c_[1] = -a_;
    c_[3] = b_;
    c_[5] = -f.c_;
    for (int j = 1; j <= 5; j += 2)
      if (c_[j] != 0) degree_ = j;
  }
}

namespace {
// Coefficient k of the Cauchy product of p and q.
inline double Cauchy(const double* p, const double* q, int k) {
  double sum = 0;
  for (int j = 0; j <= k; ++j) sum += p[j] * q[k - j];
  return sum;
}
}  // namespace

double MuSeries::Next(int k, const double* s, double* dmu) {
  const double c0 = k == 0 ? 1.0 : 0.0;
  switch (law_) {
    case LawKind::kCubic: {
      // w_[d - 2] holds s^d: s^2 = s s, s^3 = s^2 s, s^4 = s^2 s^2, s^5 = s^4 s.
      if (degree_ >= 3 || dmu) w_[0][k] = Cauchy(s, s, k);
      if (degree_ >= 3) w_[1][k] = Cauchy(w_[0], s, k);
      if (degree_ >= 5) {
        w_[2][k] = Cauchy(w_[0], w_[0], k);
        w_[3][k] = Cauchy(w_[2], s, k);
      }
      double mu = c0 * mu_s_ + c_[1] * s[k];
      if (degree_ >= 3) mu += c_[3] * w_[1][k];
      if (degree_ >= 5) mu += c_[5] * w_[3][k];
      if (dmu) {
        *dmu = c0 * c_[1] + 3 * c_[3] * w_[0][k];
        if (degree_ >= 5) *dmu += 5 * c_[5] * w_[2][k];
      }
      return mu;
    }
    case LawKind::kCoulomb:
      if (dmu) *dmu = 0;
      return c0 * a_;
    case LawKind::kStribeck: {
      double* u = w_[0];
      double* e = w_[1];
      u[k] = -s[k] / b_;
      if (k == 0) {
        e[0] = std::exp(u[0]);
      } else {
        double sum = 0;
        for (int j = 1; j <= k; ++j) sum += j * u[j] * e[k - j];
        e[k] = sum / k;
      }
      if (dmu) *dmu = -(mu_s_ - a_) / b_ * e[k];
      return c0 * a_ + (mu_s_ - a_) * e[k];
    }
    case LawKind::kLeine: {
      double* d = w_[0];
      double* q = w_[1];
      d[k] = c0 + a_ * s[k];
      double sum = c0 * mu_s_;
      for (int j = 1; j <= k; ++j) sum -= d[j] * q[k - j];
      q[k] = sum / d[0];
      if (dmu) {
        w_[2][k] = Cauchy(q, q, k);
        *dmu = -(a_ / mu_s_) * w_[2][k];
      }
      return q[k];
    }
  }
  return 0;
}

}  // namespace stickslip
