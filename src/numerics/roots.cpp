#include "numerics/roots.hpp"

#include <algorithm>
#include <boost/math/tools/minima.hpp>
#include <cmath>
#include <cstdint>
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

// Brent (1973), ch. 5 (boost::math::tools::brent_find_minima): golden section
// with parabolic steps, to about xtol.
RootResult FindMinimum(const std::function<double(double)>& f, double a, double b, double xtol,
                       int max_evaluations) {
  // Boost's tolerance is 2^(1 - bits) (|x| + 1/4): bits for xtol at |x| ~ 1.
  const int bits =
      std::clamp(static_cast<int>(1 - std::log2(xtol)), 1, std::numeric_limits<double>::digits / 2);
  std::uintmax_t iterations = static_cast<std::uintmax_t>(std::max(max_evaluations - 1, 1));
  RootResult r;
  const auto [x, fx] = boost::math::tools::brent_find_minima(
      [&](double u) { return f(u); }, std::min(a, b), std::max(a, b), bits, iterations);
  r.ok = iterations < static_cast<std::uintmax_t>(std::max(max_evaluations - 1, 1));
  r.x = x;
  r.fx = fx;
  r.evaluations = static_cast<int>(iterations) + 1;
  return r;
}

}  // namespace stickslip
