#include "stickslip/roots.hpp"

#include <algorithm>
#include <boost/math/tools/minima.hpp>
#include <boost/math/tools/toms748_solve.hpp>
#include <cmath>
#include <cstdint>
#include <limits>

namespace stickslip {

namespace {
// Thrown out of Boost's solver when f is not finite: the bracket is lost.
struct NotFinite {};
}  // namespace

RootResult FindRoot(const std::function<double(double)>& f, double a, double b, double xtol,
                    int max_evaluations) {
  return FindRoot(f, a, b, f(a), f(b), xtol, max_evaluations - 2);
}

// Alefeld, Potra & Shi (1995), TOMS 748 (boost::math::tools::toms748_solve):
// inverse cubic and quadratic steps in a bracket that shrinks every step.
RootResult FindRoot(const std::function<double(double)>& f, double a, double b, double fa,
                    double fb, double xtol, int max_evaluations) {
  RootResult r;
  if (!std::isfinite(fa) || !std::isfinite(fb) || fa * fb > 0) return r;
  if (fa == 0) return {true, a, fa, 0};
  if (fb == 0) return {true, b, fb, 0};
  if (a > b) std::swap(a, b), std::swap(fa, fb);
  // The best point seen, as Brent's zeroin returns it: smallest |f|.
  double best_x = std::abs(fa) < std::abs(fb) ? a : b;
  double best_f = std::abs(fa) < std::abs(fb) ? fa : fb;
  auto g = [&](double x) {
    const double fx = f(x);
    ++r.evaluations;
    if (!std::isfinite(fx)) throw NotFinite{};
    if (std::abs(fx) <= std::abs(best_f)) best_x = x, best_f = fx;
    return fx;
  };
  // Stop when the bracket is below xtol (plus a few ulps, as zeroin's 2 eps |b|).
  const double eps = std::numeric_limits<double>::epsilon();
  auto small = [&](double lo, double hi) {
    return std::abs(hi - lo) <= xtol + 4 * eps * std::max(std::abs(lo), std::abs(hi));
  };
  std::uintmax_t iterations = static_cast<std::uintmax_t>(std::max(max_evaluations, 1));
  try {
    const auto bracket = boost::math::tools::toms748_solve(g, a, b, fa, fb, small, iterations);
    r.ok = best_f == 0 || small(bracket.first, bracket.second);
  } catch (const NotFinite&) {
    return {false, best_x, best_f, r.evaluations};
  }
  r.x = best_x;
  r.fx = best_f;
  return r;
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
