// The coulomb chain's closed form (studies/chain2_coulomb.ini: mu_s 0.4,
// mu_k 0.3, beta 0, kc 0.5, v 0.2): in every mode each piece is affine,
// z' = A z + b, so z(t) = exp(t [[A, b], [0, 0]]) (z0, 1), here in long double
// (scaling and squaring of the Taylor series). Switch times are bracketed on
// a grid and bisected in long double; the rules at a switch are the chain's:
// arrive and stick while |c v + (1 + kc) x_i - kc x_j| <= mu_s, else cross;
// leave at the limit to the side the force points. Used by ChainCoulomb
// (the flow) and ChainStudyApp (ss_simulate --study chain2_coulomb).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace stickslip::chain::coulomb_reference {

using LD = long double;
constexpr int kA = 5;  // x1, x1', x2, x2', 1
using Mat = std::array<std::array<LD, kA>, kA>;
using Vec = std::array<LD, kA>;

struct Coulomb {
  LD mu_s = 0.4L, mu_k = 0.3L, c = 0, kc = 0.5L, v = 0.2L;
};

inline Mat Mul(const Mat& a, const Mat& b) {
  Mat r{};
  for (int i = 0; i < kA; ++i)
    for (int k = 0; k < kA; ++k)
      for (int j = 0; j < kA; ++j) r[i][j] += a[i][k] * b[k][j];
  return r;
}

// The augmented matrix of mode m (0 below, 1 stick, 2 above, per block).
inline Mat Augmented(const Coulomb& q, const int m[2]) {
  Mat a{};
  for (int i = 0; i < 2; ++i) {
    const int x = 2 * i, xd = x + 1, o = 2 * (1 - i);
    if (m[i] == 1) {
      a[x][4] = q.v;
      continue;
    }
    a[x][xd] = 1;
    a[xd][x] = -(1 + q.kc);
    a[xd][o] = q.kc;
    a[xd][xd] = -q.c;
    a[xd][4] = m[i] == 0 ? q.mu_k : -q.mu_k;
  }
  return a;
}

// exp(t a) (z, 1): Taylor to order 30 of a t / 2^s, squared s times.
inline Vec Advance(const Mat& a, LD t, const Vec& z) {
  LD norm = 0;
  for (auto& row : a)
    for (LD e : row) norm = std::max(norm, std::abs(e));
  int s = 0;
  while (norm * std::abs(t) / std::ldexp(1.0L, s) > 0.25L) ++s;
  const LD h = t / std::ldexp(1.0L, s);
  Mat e{}, term{};
  for (int i = 0; i < kA; ++i) e[i][i] = term[i][i] = 1;
  for (int k = 1; k <= 30; ++k) {
    term = Mul(term, a);
    for (auto& row : term)
      for (LD& x : row) x *= h / k;
    for (int i = 0; i < kA; ++i)
      for (int j = 0; j < kA; ++j) e[i][j] += term[i][j];
  }
  for (int i = 0; i < s; ++i) e = Mul(e, e);
  Vec r{};
  for (int i = 0; i < kA; ++i)
    for (int j = 0; j < kA; ++j) r[i] += e[i][j] * z[j];
  return r;
}

inline LD Holding(const Coulomb& q, const Vec& z, int i) {
  return q.c * q.v + (1 + q.kc) * z[2 * i] - q.kc * z[2 * (1 - i)];
}

struct Switch {
  LD t;
  int block;
};

// A piece of the walk: from t on, state z in modes m (0 below, 1 stick, 2 above).
struct Piece {
  LD t;
  Vec z;
  int m[2];
};

// The walk from z0 (modes m) to t_max; its switches and end state.
inline Vec Walk(const Coulomb& q, Vec z, int m[2], LD t_max, std::vector<Switch>* out,
                std::vector<Piece>* pieces = nullptr) {
  LD t = 0;
  if (pieces) pieces->push_back({t, z, {m[0], m[1]}});
  const LD dt = 0.004L;
  while (t < t_max) {
    const Mat a = Augmented(q, m);
    // g_i > 0 once block i's event has happened.
    auto g = [&](const Vec& y, int i) -> LD {
      if (m[i] == 1) return std::abs(Holding(q, y, i)) - q.mu_s;
      return m[i] == 0 ? y[2 * i + 1] - q.v : q.v - y[2 * i + 1];
    };
    LD lo = 0, hi = -1;
    int who = -1;
    for (LD tau = dt; t + lo < t_max; lo = tau, tau += dt) {
      const Vec y = Advance(a, tau, z);
      for (int i = 0; i < 2 && who < 0; ++i)
        if (g(y, i) > 0) who = i;
      if (who >= 0) {
        hi = tau;
        break;
      }
    }
    if (who < 0 || t + hi > t_max) return Advance(a, t_max - t, z);
    for (int it = 0; it < 100; ++it) {
      const LD mid = (lo + hi) / 2;
      (g(Advance(a, mid, z), who) > 0 ? hi : lo) = mid;
    }
    z = Advance(a, hi, z);
    t += hi;
    out->push_back({t, who});
    const int i = who;
    if (m[i] == 1) {  // exit: to the side the holding force points
      m[i] = Holding(q, z, i) > 0 ? 0 : 2;
    } else {
      z[2 * i + 1] = q.v;
      const LD f = Holding(q, z, i);
      m[i] = std::abs(f) <= q.mu_s ? 1 : (f > 0 ? 0 : 2);
    }
    if (pieces) pieces->push_back({t, z, {m[0], m[1]}});
  }
  return z;
}

// The state at time t of a walk's pieces (the last piece starting at or before t).
inline Vec At(const Coulomb& q, const std::vector<Piece>& pieces, LD t) {
  size_t k = 0;
  while (k + 1 < pieces.size() && pieces[k + 1].t <= t) ++k;
  const Piece& p = pieces[k];
  return Advance(Augmented(q, p.m), t - p.t, p.z);
}

}  // namespace stickslip::chain::coulomb_reference
