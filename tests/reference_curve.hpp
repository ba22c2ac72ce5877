// The long-double reference orbit as a dense polygon, for tests that need an
// orbit's curve computed independently of the library: which side of it a
// point lies on, and its distances from steady sliding by brute force.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <tuple>
#include <vector>

#include "reference/reference_orbit.hpp"

namespace stickslip::testing_util {

using reference::Real;

// The reference pure-slip orbit through (x_guess, 0) as a polygon: every
// RKF78 step split into `sub` pieces by its own dense steps.
inline std::vector<std::array<Real, 2>> ReferenceCurve(const Params& p, double x_guess,
                                                       int sub = 40) {
  const reference::PureSlipOrbit o = reference::PureSlip(p, x_guess);
  if (!o.found) return {};
  const reference::Model m(p);
  reference::Stepper<2> st(reference::SlipField<2>{&m, -1}, 1e-16L);
  reference::State<2> s{o.x_section, 0};
  Real t = 0;
  std::vector<std::array<Real, 2>> pts{{s[0], s[1]}};
  while (t < o.period) {
    const reference::State<2> s0 = s;
    const Real t0 = t;
    Real h = st.Step(s, t);
    if (h <= 0) break;
    if (t > o.period) h = o.period - t0;
    for (int k = 1; k <= sub; ++k) {
      const reference::State<2> q = st.From(s0, t0, h * k / sub);
      pts.push_back({q[0], q[1]});
    }
  }
  return pts;
}

inline bool Inside(const std::vector<std::array<Real, 2>>& poly, double x, double y) {
  bool in = false;
  for (size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++) {
    const Real xi = poly[i][0], yi = poly[i][1], xj = poly[j][0], yj = poly[j][1];
    if ((yi > y) != (yj > y) && x < (xj - xi) * (y - yi) / (yj - yi) + xi) in = !in;
  }
  return in;
}

inline double Distance(const std::vector<std::array<Real, 2>>& poly, double x, double y) {
  Real d = 1e300;
  for (const auto& q : poly) d = std::min(d, std::hypot(q[0] - x, q[1] - y));
  return static_cast<double>(d);
}

// Distances of (xbar, 0) from the polygon: along x' = 0, along x = xbar
// (vertices next to a sign change) and the least energy ((x - xbar)^2 + x'^2) / 2.
inline std::tuple<Real, Real, Real> BruteDisturbance(const std::vector<std::array<Real, 2>>& curve,
                                                     Real xbar) {
  Real dx = 1e300, dy = 1e300, e = 1e300;
  for (size_t k = 0; k + 1 < curve.size(); ++k) {
    const auto &a = curve[k], &b = curve[k + 1];
    const Real ex = a[0] - xbar;
    e = std::min(e, (ex * ex + a[1] * a[1]) / 2);
    if ((a[1] > 0) != (b[1] > 0)) dx = std::min(dx, std::abs(ex));
    if ((a[0] > xbar) != (b[0] > xbar)) dy = std::min(dy, std::abs(a[1]));
  }
  return {dx, dy, e};
}

}  // namespace stickslip::testing_util
