// Closed form of the coulomb law with damping (beta > 0), where slip below the
// belt is the damped linear oscillator u'' + 2 beta u' + u = 0, u = x - mu_k.
// From the exit point x0 = mu_s - 2 beta v, x' = v (seed, case 1), with
// Delta = mu_s - mu_k and w = sqrt(1 - beta^2):
//   x'(t) = e^{-beta t} (v cos wt + D sin wt),  D = (beta v - Delta) / w,
// so x' = R e^{-beta t} cos(wt - phi), R = sqrt(v^2 + D^2), phi = atan2(D, v).
// Its maxima lie at wt - phi = -psi + 2 pi k, psi = asin(beta), with value
// w R e^{-beta t}, and w R = sqrt(v^2 - 2 beta Delta v + Delta^2). The start
// is no maximum (x'' = -Delta < 0 there), so the first return's maximum is at
// t1 = (2 pi + phi - psi) / w. There x'' = 0: on x' = v that is the fold of the
// slip field, x = mu_k - 2 beta v, inside the stick band. The stick-slip orbit
// exists while that maximum reaches v and disappears where it equals v.
#pragma once

#include <cmath>

namespace stickslip::coulomb_damped {

// Time of the first return's maximum of x' after leaving the exit point.
inline long double FirstMaxTime(long double mu_s, long double mu_k, long double beta,
                                long double v) {
  const long double pi = std::acos(-1.0L), w = std::sqrt(1 - beta * beta);
  const long double d = (beta * v - (mu_s - mu_k)) / w;
  return (2 * pi + std::atan2(d, v) - std::asin(beta)) / w;
}

// (largest x' on the first return) - v: > 0 where the orbit sticks again.
inline long double Gap(long double mu_s, long double mu_k, long double beta, long double v) {
  const long double delta = mu_s - mu_k;
  const long double wr = std::sqrt(v * v - 2 * beta * delta * v + delta * delta);
  return wr * std::exp(-beta * FirstMaxTime(mu_s, mu_k, beta, v)) - v;
}

// The belt speed where the stick-slip orbit disappears: Gap = 0, by bisection
// on [lo, hi] (Gap(lo) > 0 > Gap(hi)).
inline long double EndSpeed(long double mu_s, long double mu_k, long double beta,
                            long double lo = 1e-6L, long double hi = 10.0L) {
  for (int i = 0; i < 200; ++i) {
    const long double mid = (lo + hi) / 2;
    (Gap(mu_s, mu_k, beta, mid) > 0 ? lo : hi) = mid;
  }
  return (lo + hi) / 2;
}

// The orbit at the end point: slip for FirstMaxTime, then stick from
// x = mu_k - 2 beta v to the exit point x0 = mu_s - 2 beta v, for Delta / v.
inline long double EndPeriod(long double mu_s, long double mu_k, long double beta) {
  const long double v = EndSpeed(mu_s, mu_k, beta);
  return FirstMaxTime(mu_s, mu_k, beta, v) + (mu_s - mu_k) / v;
}

}  // namespace stickslip::coulomb_damped
