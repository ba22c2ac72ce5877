#include "stickslip/systems/belt/friction.hpp"

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

}  // namespace stickslip
