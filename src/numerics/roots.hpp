// Scalar root finding and minimisation on a bracket, after Brent (1973),
// "Algorithms for Minimization without Derivatives": zeroin (ch. 4) here, fmin
// (ch. 5) through Boost.Math. Boost's toms748_solve in place of zeroin put a
// spurious fold on the seed branch at BDF rtol 1e-3
// (Continuation.SameStructureAtEveryTolerance), so zeroin stays.
#pragma once

#include <functional>

namespace stickslip {

/// A root or a minimum: the point, f there, and the evaluations spent.
struct RootResult {
  bool ok = false;  // false: no sign change on the bracket, or a non-finite value
  double x = 0;
  double fx = 0;
  int evaluations = 0;
};

/// Root of f on [a, b] with f(a) f(b) <= 0, to |dx| <= xtol (Brent's zeroin).
/// fa, fb are f(a), f(b) if already known.
RootResult FindRoot(const std::function<double(double)>& f, double a, double b, double fa,
                    double fb, double xtol, int max_evaluations = 200);
RootResult FindRoot(const std::function<double(double)>& f, double a, double b, double xtol,
                    int max_evaluations = 200);

/// Minimum of f on [a, b] to about xtol (boost::math::tools::brent_find_minima:
/// golden section with parabolic steps).
RootResult FindMinimum(const std::function<double(double)>& f, double a, double b, double xtol,
                       int max_evaluations = 200);

}  // namespace stickslip
