// Private to src/: the first sign change of a polynomial on (0, 1], never
// missing one, after heyoka's event detection (Biscani & Izzo 2021, MNRAS 504,
// section 4): Bernstein coefficients bound the polynomial on an interval
// (convex hull property), so an interval whose coefficients all share one sign
// with a margin for rounding holds no root; otherwise it is halved (de
// Casteljau) until a single sign variation isolates one root (Descartes' rule
// for the Bernstein basis), which Brent's method then locates.
#pragma once

#include <algorithm>
#include <cmath>

#include "numerics/tolerances.hpp"

namespace stickslip {

struct PolyRoot {
  bool found = false;
  double u = 0;           // the first u in (0, 1] where the sign differs from `sign`
  bool monotone = false;  // the search found c monotone on [0, 1] (Monotone)
};

// c[0..n], n <= 40: power coefficients in u. sign (+1 or -1) is the sign of
// g just after u = 0; zero_sign is the sign an exact 0 counts as.
PolyRoot FirstSignChange(const double* c, int n, int sign, int zero_sign);
// The same, past the quadratic bound (QuadraticBoundExcludes(c, n, sign,
// tail) is false): tail = sum_{k>=3} |c_k|.
PolyRoot FirstSignChangePast(const double* c, int n, int sign, int zero_sign, double tail);

// The coefficients in w of c(u + (1 - u) w), w in [0, 1]: c on [u, 1]
// (Taylor shift by repeated synthetic division, then scaling).
void RestrictToTail(const double* c, int n, double u, double* out);

// Whether sign * c has no root on [0, 1], by its quadratic part: sign * (c0 +
// c1 u + c2 u^2) stays above tail = sum_{k>=3} |c_k| by more than rounding (its
// minimum on [0, 1] is at an end or at the vertex).
inline bool QuadraticBoundExcludes(const double* c, int n, int sign, double tail) {
  const double q0 = sign * c[0], q1 = n >= 1 ? sign * c[1] : 0.0, q2 = n >= 2 ? sign * c[2] : 0.0;
  const double scale = std::abs(q0) + std::abs(q1) + std::abs(q2) + tail;
  if (!Tolerances::PolyBoundsApply(scale)) return false;  // q1^2 would underflow or overflow
  const double margin = Tolerances::PolyMargin(n, scale);
  double q_min = std::min(q0, q0 + q1 + q2);
  if (q2 > 0 && -q1 > 0 && -q1 < 2 * q2) q_min = std::min(q_min, q0 - q1 * q1 / (4 * q2));
  return q_min - tail > margin;
}

// The same by the cubic part, for the search past the quadratic bound: sign *
// (c0 + ... + c3 u^3) stays above tail4 = sum_{k>=4} |c_k| by more than
// rounding; its minimum on [0, 1] is at an end or where its derivative
// vanishes (a root of 3 c3 u^2 + 2 c2 u + c1, by the stable formula).
// Twice PolyMargin exceeds the rounding of Horner's rule on the even and odd
// parts (Higham 2002, eq. 5.3, for 1.5 n + 3 operations) with the tail's own:
// where this excludes, no evaluation of the polynomial changes sign, so the
// search past it finds no root either.
[[gnu::noinline]] inline bool CubicBoundExcludes(const double* c, int n, int sign, double tail4,
                                                 double scale) {
  const double q0 = sign * c[0], q1 = n >= 1 ? sign * c[1] : 0.0, q2 = n >= 2 ? sign * c[2] : 0.0,
               q3 = n >= 3 ? sign * c[3] : 0.0;
  if (!Tolerances::PolyBoundsApply(scale)) return false;  // b^2 - 4 a q1 would not be finite
  const double margin = 2 * Tolerances::PolyMargin(n, scale) + tail4;
  auto q = [&](double u) { return q0 + u * (q1 + u * (q2 + u * q3)); };
  if (!(q0 > margin) || !(q0 + q1 + q2 + q3 > margin)) return false;
  const double a = 3 * q3, b = 2 * q2;
  auto inside_above = [&](double u) { return !(u > 0 && u < 1) || q(u) > margin; };
  if (a == 0) return b == 0 || inside_above(-q1 / b);
  const double d = b * b - 4 * a * q1;
  if (d < 0) return true;  // q monotone: the ends decide
  const double s = -0.5 * (b + std::copysign(std::sqrt(d), b));
  return inside_above(s / a) && (s == 0 || inside_above(q1 / s));
}

// Whether c (degree n) is strictly monotone on [0, 1]: its derivative's
// quadratic bound excludes a root there. Then c has at most one root on [0, 1].
inline bool Monotone(const double* c, int n) {
  if (n < 1 || c[1] == 0) return false;
  double d[3] = {c[1], n >= 2 ? 2 * c[2] : 0.0, n >= 3 ? 3 * c[3] : 0.0}, tail = 0;
  for (int k = 4; k <= n; ++k) tail += k * std::abs(c[k]);  // sum_{k>=3} |c'_k|
  return QuadraticBoundExcludes(d, n - 1, c[1] > 0 ? 1 : -1, tail);
}

// The polynomial at u by Horner's rule in u^2 on its even and odd parts: two
// independent chains of half the length (the latency of one chain bounds
// plain Horner).
// Out of line (one copy for every caller: the hot code's footprint,
// docs/benchmarks.md).
[[gnu::noinline]] inline double Horner(const double* c, int n, double u) {
  const double u2 = u * u;
  int k = n % 2 == 0 ? n : n - 1;  // highest even index
  double even = c[k], odd = n % 2 == 1 ? c[n] : 0.0;
  for (k -= 2; k >= 0; k -= 2) {
    even = even * u2 + c[k];
    odd = odd * u2 + c[k + 1];
  }
  return even + u * odd;
}

}  // namespace stickslip
