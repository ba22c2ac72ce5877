// Internal to the seed's estimates (estimates.cpp, bound_fit.cpp): the
// checks and sampling helpers both use.
#pragma once

#include <algorithm>
#include <string>
#include <vector>

#include "numerics/numbers.hpp"
#include "stickslip/errors.hpp"
#include "stickslip/systems/belt/params.hpp"

namespace stickslip {
namespace seed_detail {

// Messages give 6 digits (%.6g).
inline std::string Num6(double x) { return Num(x, 6); }

// Validates p and insists on the cubic law: (3.9)-(3.30) are for it alone.
inline void RequireCubic(const Params& p) {
  Validate(p);
  if (p.law != LawKind::kCubic)
    throw InvalidArgument(std::string("estimates: law '") + Name(p.law) +
                          "' is not cubic; the seed's estimates (3.9-3.30) need the cubic law");
  if (p.k5 != 0)
    throw InvalidArgument("estimates: k5 = " + std::to_string(p.k5) +
                          ": the seed's estimates (3.9-3.30) are for the cubic law without k5");
}

// Linear coefficient of h (3.10): 2 beta - k1 + 3 k3 v^2 (the equilibrium's damping).
inline double LinearCoefficient(const Params& p) {
  return 2.0 * p.beta - p.k1() + 3.0 * p.k3() * p.v * p.v;
}

// n equally spaced points on [lo, hi], both ends included.
inline std::vector<double> Grid(double lo, double hi, int n) {
  std::vector<double> x(n);
  for (int i = 0; i < n; ++i) x[i] = lo + (hi - lo) * i / (n - 1);
  x[n - 1] = hi;
  return x;
}

template <class F>
std::vector<double> Map(const std::vector<double>& x, F f) {
  std::vector<double> y(x.size());
  std::transform(x.begin(), x.end(), y.begin(), f);
  return y;
}

}  // namespace seed_detail
}  // namespace stickslip
