// Independent references for the forced friction oscillator (issue 20):
//   x'' + 2 beta x' + x = F(x' - v) + A cos(Omega t).
// Shares no code with the library: long double throughout, fields and stick
// condition re-derived here, every switch located by scanning and bisection.
//  - PieceSim<CoulombPiece>: the coulomb law, every slip piece in closed form
//    (a linear oscillator with constant force and harmonic forcing).
//  - PieceSim<OdeintPiece>: any law, Boost.Odeint's RKF78 in long double.
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

#include "reference/reference_orbit.hpp"
#include "stickslip/systems/forced/forced.hpp"

namespace stickslip::forced_reference {

/// The library's parameters of a coulomb scene (the tests' shorthand).
inline ForcedBeltParams Coulomb(double mu_s, double mu_k, double beta, double v, double a,
                                double w) {
  ForcedBeltParams p;
  p.base.law = LawKind::kCoulomb;
  p.base.mu_s = mu_s, p.base.mu_k = mu_k, p.base.beta = beta, p.base.v = v;
  p.force = a, p.omega = w;
  return p;
}

// A law at mu_s 0.4, mu_k 0.25 (the seed's pair) under A cos(w t).
inline ForcedBeltParams Belt(LawKind law, double beta, double v, double a, double w) {
  ForcedBeltParams p = Coulomb(0.4, 0.25, beta, v, a, w);
  p.base.law = law;
  return p;
}

// The seed's cubic law (its mu_m 0.25, v_m 0.5) at beta 0.05 and belt speed v under
// A cos(w t): studies/seed_forced.ini (v 0.25) and forced_ns_seed.ini (v 0.42).
inline ForcedBeltParams SeedBelt(double v, double a, double w) {
  return Belt(LawKind::kCubic, 0.05, v, a, w);
}

// studies/stribeck_forced.ini's law (v_s 0.2) at beta 0.05 and belt speed v.
inline ForcedBeltParams StribeckBelt(double v, double a, double w) {
  ForcedBeltParams p = Belt(LawKind::kStribeck, 0.05, v, a, w);
  p.base.v_s = 0.2;
  return p;
}

/// Den Hartog (1931), the non-stop amplitude of the undamped Coulomb belt at
/// rest: X = sqrt(V^2 - (mu U)^2), V = A / (1 - W^2),
/// U = sin(pi / W) / (W (1 + cos(pi / W))).
inline double DenHartogX(double mu, double a, double w) {
  const double V = a / (1 - w * w), U = std::sin(M_PI / w) / (w * (1 + std::cos(M_PI / w)));
  return std::sqrt(V * V - mu * mu * U * U);
}

using reference::Real;

struct Setup {
  reference::Law law;
  Real beta, v, a, w;                    // A, Omega
  Real Force(int sigma, Real y) const {  // sigma = +1 below the contact, -1 above
    return sigma * law.Mu(sigma * (v - y));
  }
  Real StickForce(Real t, Real x) const { return x + 2 * beta * v - a * std::cos(w * t); }
};

// x'' + 2 beta x' + x = c + A cos(Omega t), beta < 1, Omega != 1 (or beta > 0):
// x = c + e^{-beta t} (C1 cos wd t + C2 sin wd t) + Re(P e^{i Omega t}),
// P = A / (1 - Omega^2 + 2 i beta Omega).
struct CoulombPiece {
  Real c, beta, wd, pr, pi, w, t0, c1, c2;
  CoulombPiece(const Setup& s, int sigma, Real t0_, Real x0, Real y0)
      : c(sigma * s.law.mu_k), beta(s.beta), wd(std::sqrt(1 - s.beta * s.beta)), w(s.w), t0(t0_) {
    const Real re = 1 - s.w * s.w, im = 2 * s.beta * s.w, den = re * re + im * im;
    pr = s.a * re / den, pi = -s.a * im / den;
    Real xp, yp;
    Particular(t0, xp, yp);
    c1 = x0 - c - xp;                 // tau = 0: x = c + C1 + xp
    c2 = (y0 - yp + beta * c1) / wd;  // x' = -beta C1 + wd C2 + yp
  }
  void Particular(Real t, Real& x, Real& y) const {
    x = pr * std::cos(w * t) - pi * std::sin(w * t);
    y = -w * (pr * std::sin(w * t) + pi * std::cos(w * t));
  }
  void At(Real t, Real& x, Real& y) const {
    const Real tau = t - t0, e = std::exp(-beta * tau), co = std::cos(wd * tau),
               si = std::sin(wd * tau);
    Real xp, yp;
    Particular(t, xp, yp);
    x = c + e * (c1 * co + c2 * si) + xp;
    y = e * (-beta * (c1 * co + c2 * si) + wd * (-c1 * si + c2 * co)) + yp;
  }
};

// The same interface by Boost.Odeint's RKF78 in long double: dense enough by
// re-stepping from the nearest stored step (steps of at most hmax).
struct OdeintPiece {
  struct Field {
    const Setup* s;
    int sigma;
    void operator()(const reference::State<2>& z, reference::State<2>& dz, Real t) const {
      dz[0] = z[1];
      dz[1] = -z[0] - 2 * s->beta * z[1] + s->Force(sigma, z[1]) + s->a * std::cos(s->w * t);
    }
  };
  using Rk = boost::numeric::odeint::runge_kutta_fehlberg78<reference::State<2>, Real,
                                                            reference::State<2>, Real>;
  Field f;
  std::vector<Real> ts;
  std::vector<reference::State<2>> zs;
  Real tol;
  OdeintPiece(const Setup& s, int sigma, Real t0, Real x0, Real y0, Real tol_ = 1e-18L)
      : f{&s, sigma}, ts{t0}, zs{{x0, y0}}, tol(tol_) {}
  void Extend(Real t) {
    auto ctrl = boost::numeric::odeint::make_controlled<Rk>(tol, tol);
    Real dt = 1e-3L;
    while (ts.back() < t) {
      reference::State<2> z = zs.back(), out;
      Real tt = ts.back();
      dt = std::min(dt, Real(0.02));
      for (int tries = 0; tries < 500; ++tries)
        if (ctrl.try_step(f, z, tt, out, dt) == boost::numeric::odeint::success) break;
      ts.push_back(tt);
      zs.push_back(out);
    }
  }
  void At(Real t, Real& x, Real& y) {
    Extend(t);
    size_t i = std::upper_bound(ts.begin(), ts.end(), t) - ts.begin();
    i = i == 0 ? 0 : i - 1;
    reference::State<2> out = zs[i];
    if (t > ts[i]) Rk().do_step(f, zs[i], ts[i], out, t - ts[i]);
    x = out[0], y = out[1];
  }
};

struct Event {
  int kind;  // 0 stick in, 1 stick out, 2 crossing
  Real t, x;
};

// Bisection for the first t in (a, b] where pred turns true (pred(a) false).
template <class Pred>
Real Bisect(Pred pred, Real a, Real b) {
  for (int i = 0; i < 200 && b - a > 1e-30L; ++i) {
    const Real m = (a + b) / 2;
    if (m <= a || m >= b) break;
    (pred(m) ? b : a) = m;
  }
  return b;
}

// Event-driven simulation from (t, x, y) (y = v with |phi| <= mu_s: stick) to
// t_end, scanning each phase's switching function on a grid of dt (and at the
// extrema of y - v and phi between grid points) and bisecting the first change.
template <class Piece>
struct PieceSim {
  explicit PieceSim(const Setup& setup) : s(setup) {}
  Setup s;
  Real dt = 1e-3L;
  // x_max, x_min exact: the roots of x' inside slip phases bisected (else the
  // slip phases' extremes are sampled on the grid of dt).
  bool exact_extremes = false;
  std::vector<Event> events;
  Real x_max = -1e300L, x_min = 1e300L;
  int sticks = 0, crossings = 0;

  // Runs to t_end; returns the state there.
  // start_sigma (+1 below, -1 above, 0 stick) overrides the start's mode.
  void Run(Real& t, Real& x, Real& y, Real t_end, int start_sigma = 2) {
    int sigma = y < s.v ? 1 : (y > s.v ? -1 : 0);
    if (sigma == 0 && std::abs(s.StickForce(t, x)) > s.law.mu_s)  // not held: slips at once
      sigma = s.StickForce(t, x) > 0 ? 1 : -1;
    if (start_sigma != 2) sigma = start_sigma;
    while (t < t_end) {
      x_max = std::max(x_max, x), x_min = std::min(x_min, x);
      if (sigma == 0) {
        Stick(t, x, y, t_end, sigma);
      } else {
        SlipPhase(t, x, y, t_end, sigma);
      }
    }
    x_max = std::max(x_max, x), x_min = std::min(x_min, x);
  }
  void Stick(Real& t, Real& x, Real& y, Real t_end, int& sigma) {
    const Real t_a = t, x_a = x, mu_s = s.law.mu_s;
    auto out = [&](Real tt) { return std::abs(s.StickForce(tt, x_a + s.v * (tt - t_a))) > mu_s; };
    // phi' = v + A Omega sin(Omega t): phi's extrema between grid points are checked too.
    auto rate = [&](Real tt) { return s.v + s.a * s.w * std::sin(s.w * tt) > 0; };
    for (Real t0 = t; t0 < t_end; t0 += dt) {
      const Real t1 = std::min(t0 + dt, t_end);
      Real hit = -1;
      if (out(t1)) hit = Bisect(out, t0, t1);
      if (hit < 0 && rate(t0) != rate(t1)) {
        const Real te = Bisect([&](Real tt) { return rate(tt) != rate(t0); }, t0, t1);
        if (out(te)) hit = Bisect(out, t0, te);
      }
      if (hit >= 0) {
        t = hit, x = x_a + s.v * (hit - t_a), y = s.v;
        sigma = s.StickForce(t, x) > 0 ? 1 : -1;
        events.push_back({1, t, x});
        return;
      }
    }
    t = t_end, x = x_a + s.v * (t_end - t_a), y = s.v;
  }
  void SlipPhase(Real& t, Real& x, Real& y, Real t_end, int& sigma) {
    Piece p(s, sigma, t, x, y);
    // d = sigma (v - y) > 0 in this mode; the phase ends where it falls to 0.
    auto gone = [&](Real tt) {
      Real xx, yy;
      p.At(tt, xx, yy);
      return sigma * (s.v - yy) <= 0;
    };
    auto ydot_sign = [&](Real tt) {
      Real xx, yy;
      p.At(tt, xx, yy);
      return -xx - 2 * s.beta * yy + s.Force(sigma, yy) + s.a * std::cos(s.w * tt) > 0;
    };
    const Real start = t;
    for (Real t0 = t; t0 < t_end; t0 += dt) {
      const Real t1 = std::min(t0 + dt, t_end);
      Real hit = -1;
      // The start on the surface is no event (x' - v may grow like tau^3 there).
      const Real lo = t0 == start ? t0 + 1e-5L : t0;
      if (gone(t1)) hit = Bisect(gone, lo, t1);
      if (hit < 0 && ydot_sign(lo) != ydot_sign(t1)) {
        const bool s0 = ydot_sign(lo);
        const Real te = Bisect([&](Real tt) { return ydot_sign(tt) != s0; }, lo, t1);
        if (gone(te)) hit = Bisect(gone, lo, te);
      }
      Real xx, yy;
      if (exact_extremes) SlipExtremes(p, lo, hit >= 0 ? hit : t1, ydot_sign);
      if (hit >= 0) {
        p.At(hit, xx, yy);
        t = hit, x = xx, y = s.v;
        const Real f = s.StickForce(t, x);
        if (std::abs(f) <= s.law.mu_s) {
          sigma = 0, ++sticks;
          events.push_back({0, t, x});
        } else {
          sigma = f > 0 ? 1 : -1, ++crossings;
          events.push_back({2, t, x});
        }
        return;
      }
      p.At(t1, xx, yy);
      x_max = std::max(x_max, xx), x_min = std::min(x_min, xx);
      if (t1 == t_end) {
        t = t_end, x = xx, y = yy;
        return;
      }
    }
  }
  // The roots of x' in [a, b] of slip piece p: at most one each side of an
  // extremum of x' (a sign change of x''), each bisected; x there extends
  // x_max, x_min.
  template <class P, class Sign>
  void SlipExtremes(P& p, Real a, Real b, const Sign& ydot_sign) {
    auto y = [&](Real tt) {
      Real xx, yy;
      p.At(tt, xx, yy);
      return yy;
    };
    Real cuts[3] = {a, b, b};
    const bool s0 = ydot_sign(a);
    if (s0 != ydot_sign(b)) cuts[1] = Bisect([&](Real tt) { return ydot_sign(tt) != s0; }, a, b);
    for (int i = 0; i < 2; ++i) {
      const Real c0 = cuts[i], c1 = cuts[i + 1];
      const bool up = y(c0) > 0;
      if (c1 <= c0 || (y(c1) > 0) == up) continue;
      Real xx, yy;
      p.At(Bisect([&](Real tt) { return (y(tt) > 0) != up; }, c0, c1), xx, yy);
      x_max = std::max(x_max, xx), x_min = std::min(x_min, xx);
    }
  }
};

}  // namespace stickslip::forced_reference
