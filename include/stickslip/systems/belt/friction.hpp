// Friction laws mu(s), s = |x' - v| > 0, and the slip force F(u) = -sgn(u) mu(|u|)
// of seed eq. (3.5). A small value type: no virtual calls on the hot path.
#pragma once

#include "stickslip/systems/belt/params.hpp"

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

}  // namespace stickslip
