// Private to src/: the first sign change of a polynomial on (0, 1], never
// missing one, after heyoka's event detection (Biscani & Izzo 2021, MNRAS 504,
// section 4): Bernstein coefficients bound the polynomial on an interval
// (convex hull property), so an interval whose coefficients all share one sign
// with a margin for rounding holds no root; otherwise it is halved (de
// Casteljau) until a single sign variation isolates one root (Descartes' rule
// for the Bernstein basis), which Brent's method then locates.
#pragma once

namespace stickslip {

struct PolyRoot {
  bool found = false;
  double u = 0;  // the first u in (0, 1] where the sign differs from `sign`
};

// c[0..n], n <= 40: power coefficients in u. sign (+1 or -1) is the sign of
// g just after u = 0; zero_sign is the sign an exact 0 counts as.
PolyRoot FirstSignChange(const double* c, int n, int sign, int zero_sign);

// The coefficients in w of c(u + (1 - u) w), w in [0, 1]: c on [u, 1]
// (Taylor shift by repeated synthetic division, then scaling).
void RestrictToTail(const double* c, int n, double u, double* out);

// Horner's rule at u.
inline double Horner(const double* c, int n, double u) {
  double s = c[n];
  for (int k = n - 1; k >= 0; --k) s = s * u + c[k];
  return s;
}

}  // namespace stickslip
