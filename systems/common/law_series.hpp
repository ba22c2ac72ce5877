// The Taylor series of a friction law along a solution (taylor_field.hpp;
// Jorba & Zou 2005): mu(s(t)) and mu'(s(t)) coefficient by coefficient from
// s(t)'s, by the usual rules (products; exp' = exp a'; (1/d)' = -d'/d^2).
// For the systems under systems/, written from the public headers: the
// library's own series (MuSeries) are private to it.
#pragma once

#include <cmath>

#include "stickslip/system/taylor_field.hpp"
#include "stickslip/systems/belt/params.hpp"

namespace stickslip::systems {

/// The Cauchy product's coefficient k of a and b, in four partial sums
/// (independent chains of additions, which the processor overlaps).
inline double Cauchy(const double* a, const double* b, int k) {
  double s0 = 0, s1 = 0, s2 = 0, s3 = 0;
  int j = 0;
  for (; j + 3 <= k; j += 4) {
    s0 += a[j] * b[k - j];
    s1 += a[j + 1] * b[k - j - 1];
    s2 += a[j + 2] * b[k - j - 2];
    s3 += a[j + 3] * b[k - j - 3];
  }
  for (; j <= k; ++j) s0 += a[j] * b[k - j];
  return (s0 + s1) + (s2 + s3);
}

/// 1 / (k + 1) for k < kTaylorRowSize, so that a recurrence multiplies
/// where it would divide (a division costs several multiplications).
struct Reciprocals {
  double r[kTaylorRowSize];
  constexpr Reciprocals() : r() {
    for (int k = 0; k < kTaylorRowSize; ++k) r[k] = 1.0 / (k + 1);
  }
};
inline constexpr Reciprocals kReciprocals{};

/// mu(s(t)) and mu'(s(t)) of one law: set s[0..k], then Next(k).
struct LawSeries {
  LawKind law = LawKind::kCoulomb;
  double mu_s = 0, a = 0, b = 0,
         c = 0;  // cubic k1, k3, k5; coulomb, stribeck mu_k, v_s; leine delta
  double s[kTaylorRowSize], p2[kTaylorRowSize], p3[kTaylorRowSize], p4[kTaylorRowSize],
      p5[kTaylorRowSize], e[kTaylorRowSize], d[kTaylorRowSize], r[kTaylorRowSize],
      r2[kTaylorRowSize];
  double mu[kTaylorRowSize], dmu[kTaylorRowSize];

  void Set(const Params& p) {
    law = p.law, mu_s = p.mu_s, a = b = c = 0;
    if (law == LawKind::kCubic) a = p.k1(), b = p.k3(), c = p.k5;
    if (law == LawKind::kCoulomb || law == LawKind::kStribeck) a = p.mu_k;
    if (law == LawKind::kStribeck) b = p.v_s;
    if (law == LawKind::kLeine) a = p.delta;
  }
  // Coefficient k of mu and mu', s[0..k] set.
  void Next(int k) {
    switch (law) {
      case LawKind::kCubic:
        p2[k] = Cauchy(s, s, k);
        p3[k] = Cauchy(p2, s, k);
        mu[k] = (k == 0 ? mu_s : 0.0) - a * s[k] + b * p3[k];
        dmu[k] = (k == 0 ? -a : 0.0) + 3 * b * p2[k];
        if (c != 0) {  // the quintic term (k5; the seed's law has none): two products more
          p4[k] = Cauchy(p2, p2, k);
          p5[k] = Cauchy(p4, s, k);
          mu[k] -= c * p5[k];
          dmu[k] -= 5 * c * p4[k];
        }
        return;
      case LawKind::kCoulomb:
        mu[k] = k == 0 ? a : 0.0;
        dmu[k] = 0;
        return;
      case LawKind::kStribeck: {  // e = exp(-s / v_s): e' = -e s' / v_s
        if (k == 0) {
          e[0] = std::exp(-s[0] / b);
        } else {
          double t = 0;
          for (int j = 1; j <= k; ++j) t += j * s[j] * e[k - j];
          e[k] = -t / (b * k);
        }
        mu[k] = (k == 0 ? a : 0.0) + (mu_s - a) * e[k];
        dmu[k] = -(mu_s - a) / b * e[k];
        return;
      }
      case LawKind::kLeine: {  // r = 1 / (1 + delta s)
        d[k] = (k == 0 ? 1.0 : 0.0) + a * s[k];
        double t = 0;
        for (int j = 1; j <= k; ++j) t += d[j] * r[k - j];
        r[k] = k == 0 ? 1.0 / d[0] : -t / d[0];
        r2[k] = Cauchy(r, r, k);
        mu[k] = mu_s * r[k];
        dmu[k] = -mu_s * a * r2[k];
        return;
      }
    }
  }
};

}  // namespace stickslip::systems
