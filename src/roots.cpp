#include "stickslip/roots.hpp"

#include <cmath>
#include <limits>

namespace stickslip {

RootResult FindRoot(const std::function<double(double)>& f, double a, double b, double xtol,
                    int max_evaluations) {
  return FindRoot(f, a, b, f(a), f(b), xtol, max_evaluations - 2);
}

// Brent (1973), ch. 4: bisection safeguarding secant and inverse quadratic steps.
RootResult FindRoot(const std::function<double(double)>& f, double a, double b, double fa,
                    double fb, double xtol, int max_evaluations) {
  RootResult r;
  if (!std::isfinite(fa) || !std::isfinite(fb) || fa * fb > 0) return r;
  if (fa == 0) return {true, a, fa, 0};
  if (fb == 0) return {true, b, fb, 0};
  const double eps = std::numeric_limits<double>::epsilon();
  double c = a, fc = fa, d = b - a, e = d;
  for (int it = 0; it < max_evaluations; ++it) {
    if ((fb > 0) == (fc > 0)) {
      c = a;
      fc = fa;
      d = e = b - a;
    }
    if (std::abs(fc) < std::abs(fb)) {
      a = b;
      b = c;
      c = a;
      fa = fb;
      fb = fc;
      fc = fa;
    }
    const double tol = 2 * eps * std::abs(b) + 0.5 * xtol;
    const double m = 0.5 * (c - b);
    if (std::abs(m) <= tol || fb == 0) return {true, b, fb, r.evaluations};
    if (std::abs(e) >= tol && std::abs(fa) > std::abs(fb)) {
      double p, q, s = fb / fa;
      if (a == c) {  // secant
        p = 2 * m * s;
        q = 1 - s;
      } else {  // inverse quadratic interpolation
        const double qq = fa / fc, rr = fb / fc;
        p = s * (2 * m * qq * (qq - rr) - (b - a) * (rr - 1));
        q = (qq - 1) * (rr - 1) * (s - 1);
      }
      if (p > 0)
        q = -q;
      else
        p = -p;
      if (2 * p < std::min(3 * m * q - std::abs(tol * q), std::abs(e * q))) {
        e = d;
        d = p / q;
      } else {
        d = m;
        e = m;
      }
    } else {
      d = m;
      e = m;
    }
    a = b;
    fa = fb;
    b += std::abs(d) > tol ? d : (m > 0 ? tol : -tol);
    fb = f(b);
    ++r.evaluations;
    if (!std::isfinite(fb)) return r;
  }
  return {false, b, fb, r.evaluations};
}

// Brent (1973), ch. 5.
RootResult FindMinimum(const std::function<double(double)>& f, double a, double b, double xtol,
                       int max_evaluations) {
  const double golden = 0.5 * (3 - std::sqrt(5.0));
  double x = a + golden * (b - a), w = x, v = x;
  double fx = f(x), fw = fx, fv = fx;
  double d = 0, e = 0;
  RootResult r;
  r.evaluations = 1;
  while (r.evaluations < max_evaluations) {
    const double m = 0.5 * (a + b);
    const double tol =
        1e-3 * std::sqrt(std::numeric_limits<double>::epsilon()) * std::abs(x) + xtol / 3;
    if (std::abs(x - m) <= 2 * tol - 0.5 * (b - a)) return {true, x, fx, r.evaluations};
    bool golden_step = true;
    if (std::abs(e) > tol) {
      double rr = (x - w) * (fx - fv), q = (x - v) * (fx - fw), p = (x - v) * q - (x - w) * rr;
      q = 2 * (q - rr);
      if (q > 0)
        p = -p;
      else
        q = -q;
      if (std::abs(p) < std::abs(0.5 * q * e) && p > q * (a - x) && p < q * (b - x)) {
        e = d;
        d = p / q;
        const double u = x + d;
        if (u - a < 2 * tol || b - u < 2 * tol) d = x < m ? tol : -tol;
        golden_step = false;
      }
    }
    if (golden_step) {
      e = (x < m ? b : a) - x;
      d = golden * e;
    }
    const double u = x + (std::abs(d) >= tol ? d : (d > 0 ? tol : -tol));
    const double fu = f(u);
    ++r.evaluations;
    if (fu <= fx) {
      (u < x ? b : a) = x;
      v = w;
      fv = fw;
      w = x;
      fw = fx;
      x = u;
      fx = fu;
    } else {
      (u < x ? a : b) = u;
      if (fu <= fw || w == x) {
        v = w;
        fv = fw;
        w = u;
        fw = fu;
      } else if (fu <= fv || v == x || v == w) {
        v = u;
        fv = fu;
      }
    }
  }
  return {false, x, fx, r.evaluations};
}

}  // namespace stickslip
