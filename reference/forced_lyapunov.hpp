// Independent reference for the forced oscillator's stroboscopic map and its
// largest Lyapunov exponent (issue 21 item 2: "the Taylor and the independent
// path agree within the estimate's own error"). Shares no code with the
// library's flow: the slip fields, their variational equations and the
// saltation matrices are re-derived here from
//   x'' + 2 beta x' + x = F(x' - v) + A cos(Omega t),  F(s) = -sgn(s) mu(|s|),
// (design.md section 5; di Bernardo et al. 2008, section 2.5 for saltation),
// integrated by Boost.Odeint's Runge-Kutta-Fehlberg 7(8) in long double with
// step control. Arrivals on x' = v and stick exits (|x + 2 beta v - A cos
// Omega t| = mu_s) are located by bisection on the step length. Coulomb,
// Stribeck and the seed's cubic law only. The exponent is accumulated the same way (Frobenius norm
// of the renormalised tangent matrix, batch means), so the two estimates
// differ only by the integration of the flow.
#pragma once

#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "stickslip/systems/forced/forced.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wuninitialized"
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#include <boost/numeric/odeint.hpp>

namespace stickslip::reference {

using LReal = long double;
using FState = std::array<LReal, 6>;  // x, x', Phi00, Phi10, Phi01, Phi11

struct ForcedRef {
  LReal beta, v, mu_s, mu_k, v_s, a, w;
  bool stribeck, cubic;
  LReal k1,
      k3;  // cubic (seed eq. 3.5): K1 = 3 (mu_s - mu_m) / (2 v_m), K3 = (mu_s - mu_m) / (2 v_m^3)
  explicit ForcedRef(const ForcedBeltParams& p)
      : beta(p.base.beta),
        v(p.base.v),
        mu_s(p.base.mu_s),
        mu_k(p.base.mu_k),
        v_s(p.base.v_s),
        a(p.force),
        w(p.omega),
        stribeck(p.base.law == LawKind::kStribeck),
        cubic(p.base.law == LawKind::kCubic),
        k1(LReal(3) * (p.base.mu_s - p.base.mu_m) / (2 * LReal(p.base.v_m))),
        k3((p.base.mu_s - p.base.mu_m) / (2 * LReal(p.base.v_m) * p.base.v_m * p.base.v_m)) {}
  // mu(s) and mu'(s), s = |x' - v| (Stribeck: mu_k + (mu_s - mu_k) exp(-s / v_s)).
  // Cubic: mu_s - K1 s + K3 s^3.
  LReal Mu(LReal s) const {
    if (cubic) return mu_s - k1 * s + k3 * s * s * s;
    return stribeck ? mu_k + (mu_s - mu_k) * std::exp(-s / v_s) : mu_k;
  }
  LReal DMu(LReal s) const {
    if (cubic) return -k1 + 3 * k3 * s * s;
    return stribeck ? -(mu_s - mu_k) / v_s * std::exp(-s / v_s) : LReal(0);
  }
  // Slip below (sigma = +1, x' < v) or above (sigma = -1): F = sigma mu(sigma (v - x')).
  LReal Accel(int sigma, LReal t, LReal x, LReal y) const {
    return -x - 2 * beta * y + sigma * Mu(sigma * (v - y)) + a * std::cos(w * t);
  }
  LReal StickForce(LReal t, LReal x) const { return x + 2 * beta * v - a * std::cos(w * t); }
};

struct ForcedRefField {
  const ForcedRef* m;
  int sigma;
  void operator()(const FState& s, FState& d, LReal t) const {
    d[0] = s[1];
    d[1] = m->Accel(sigma, t, s[0], s[1]);
    // dF/dx' = -mu'(sigma (v - x')) on both sides.
    const LReal c = -2 * m->beta - m->DMu(sigma * (m->v - s[1]));
    d[2] = s[3], d[3] = -s[2] + c * s[3];
    d[4] = s[5], d[5] = -s[4] + c * s[5];
  }
};

// One forcing period [0, T] from (x, x', stuck) with the state transition matrix.
struct RefPeriod {
  LReal x, y;
  bool stuck;
  LReal phi[2][2];
  int sticks = 0;
  bool ok = true;
};

inline RefPeriod RefOnePeriod(const ForcedRef& m, LReal x, LReal y, bool stuck, LReal tol) {
  namespace ode = boost::numeric::odeint;
  using Rk = ode::runge_kutta_fehlberg78<FState, LReal>;
  const LReal T = 2 * std::acos(LReal(-1)) / m.w;
  RefPeriod out{};
  FState s{x, y, 1, 0, 0, 1};
  LReal t = 0, dt = 1e-2L;
  int sigma = y < m.v ? 1 : -1;
  if (stuck) s[1] = m.v, s[3] = 0, s[5] = 0;
  auto edge_gap = [&](LReal tt, LReal xx) { return m.mu_s - std::abs(m.StickForce(tt, xx)); };
  while (t < T && out.ok) {
    if (stuck) {  // x = x_a + v (t - t_a); exit where the gap changes sign
      const LReal h = std::min(T / 400, T - t);
      const LReal xa = s[0];
      if (edge_gap(t + h, xa + m.v * h) >= 0) {
        s[0] = xa + m.v * h, t = (t + h >= T) ? T : t + h;
        continue;
      }
      LReal lo = 0, hi = h;
      for (int i = 0; i < 200 && hi - lo > 1e-19L * (1 + t); ++i) {
        const LReal mid = (lo + hi) / 2;
        (edge_gap(t + mid, xa + m.v * mid) >= 0 ? lo : hi) = mid;
      }
      t += hi, s[0] = xa + m.v * hi;
      const LReal f = m.StickForce(t, s[0]);
      sigma = f > 0 ? 1 : -1;
      const LReal ap = m.Accel(sigma, t, s[0], m.v);
      const LReal rate = m.v + m.a * m.w * std::sin(m.w * t);
      // S_out = [[1, 0], [a+ / rate, 1]]: the x' row gains (a+/rate) times the x row.
      s[3] += ap / rate * s[2], s[5] += ap / rate * s[4];
      stuck = false;
      continue;
    }
    ForcedRefField f{&m, sigma};
    auto ctrl = ode::make_controlled<Rk>(tol, tol);
    FState next;
    LReal t1 = t, h = std::min(dt, T - t);
    int tries = 0;
    while (ctrl.try_step(f, s, t1, next, h) != ode::success && ++tries < 200) {
    }
    if (tries >= 200) return out.ok = false, out;
    dt = h;
    const LReal hs = t1 - t;
    if (sigma * (m.v - next[1]) > 0) {  // still on this side
      s = next, t = t1 >= T ? T : t1;
      continue;
    }
    Rk rk;
    LReal lo = 0, hi = hs;
    FState mid_s;
    for (int i = 0; i < 200 && hi - lo > 1e-19L * (1 + t); ++i) {
      const LReal mid = (lo + hi) / 2;
      rk.do_step(f, s, t, mid_s, mid);
      (sigma * (m.v - mid_s[1]) > 0 ? lo : hi) = mid;
    }
    rk.do_step(f, s, t, next, hi);
    s = next, t += hi, s[1] = m.v;
    const LReal fs = m.StickForce(t, s[0]);
    if (std::abs(fs) <= m.mu_s) {  // S_in = diag(1, 0)
      stuck = true, s[3] = 0, s[5] = 0, ++out.sticks;
      continue;
    }
    const int after = fs > 0 ? 1 : -1;
    if (after != sigma) {  // a crossing: S = diag(1, a+ / a-)
      const LReal r = m.Accel(after, t, s[0], m.v) / m.Accel(sigma, t, s[0], m.v);
      s[3] *= r, s[5] *= r;
      sigma = after;
    }
  }
  out.x = s[0], out.y = stuck ? m.v : s[1], out.stuck = stuck;
  out.phi[0][0] = s[2], out.phi[1][0] = s[3], out.phi[0][1] = s[4], out.phi[1][1] = s[5];
  return out;
}

struct RefLyapunov {
  LReal lambda = 0, err = 0;
  bool ok = true;
};

// Transient, alignment and kept periods as in chaos/lyapunov.hpp.
inline RefLyapunov RefLargestExponent(const ForcedBeltParams& p, LReal x0, LReal y0, int transient,
                                      int align, int keep, int batches, LReal tol = 1e-16L) {
  const ForcedRef m(p);
  const LReal T = 2 * std::acos(LReal(-1)) / m.w;
  LReal M[2][2] = {{1, 0}, {0, 1}};
  std::vector<LReal> sums(batches, 0);
  LReal x = x0, y = y0;
  bool stuck = false;
  RefLyapunov r;
  for (int k = 0; k < transient + keep; ++k) {
    const RefPeriod per = RefOnePeriod(m, x, y, stuck, tol);
    if (!per.ok) return r.ok = false, r;
    x = per.x, y = per.y, stuck = per.stuck;
    if (k < transient - align) continue;
    LReal N[2][2], norm = 0;
    for (int i = 0; i < 2; ++i)
      for (int j = 0; j < 2; ++j) {
        N[i][j] = per.phi[i][0] * M[0][j] + per.phi[i][1] * M[1][j];
        norm += N[i][j] * N[i][j];
      }
    norm = std::sqrt(norm);
    for (int i = 0; i < 2; ++i)
      for (int j = 0; j < 2; ++j) M[i][j] = N[i][j] / norm;
    if (k >= transient) sums[static_cast<size_t>(k - transient) * batches / keep] += std::log(norm);
  }
  LReal total = 0;
  for (LReal s : sums) total += s;
  r.lambda = total / (keep * T);
  LReal var = 0;
  for (int i = 0; i < batches; ++i) {
    const int n = (i + 1) * keep / batches - i * keep / batches;
    var += (sums[i] / (n * T) - r.lambda) * (sums[i] / (n * T) - r.lambda);
  }
  r.err = batches > 1 ? std::sqrt(var / (batches - 1) / batches) : 0;
  return r;
}

}  // namespace stickslip::reference

#pragma GCC diagnostic pop
