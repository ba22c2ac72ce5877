// Private to src/forced/: the Taylor expansion of one slip field of the forced
// oscillator and of its variational equations (Jorba & Zou 2005, section 2):
//   x_{k+1}  = x'_k / (k+1)
//   x'_{k+1} = (-x_k - 2 beta x'_k + sigma mu_k + A c_k) / (k+1)
//   c_{k+1}  = -Omega s_k / (k+1),  s_{k+1} = Omega c_k / (k+1)   (c = cos, s = sin Omega t)
//   Phi' = J Phi, J = [0 1; -1 cc], cc = -2 beta - mu'(s): each column (p, q) has
//   p_{k+1} = q_k / (k+1), q_{k+1} = (-p_k + sum_j cc_j q_{k-j}) / (k+1),
// with mu_k and mu'_k from MuSeries (s = sigma (v - x'), sigma = +1 below the
// contact, -1 above). Also the events' polynomials and their roots.
#pragma once

#include <algorithm>
#include <cmath>
#include <optional>

#include "integrate/mu_series.hpp"
#include "integrate/poly_roots.hpp"
#include "integrate/series.hpp"
#include "numerics/tolerances.hpp"
#include "stickslip/model/forced.hpp"

namespace stickslip::forced_detail {

constexpr int kMaxOrder = 36;
constexpr int kRow = kMaxOrder + 1 + kPad;

// The step of order p is h = rho exp(-(L + kStepMargin) / (p - 1)), L =
// -ln(eps) (StepSize; JZ section 3.2): the last terms at eps e^-2.1, heyoka's
// safety factor e^-0.7 (Biscani & Izzo 2021, eq. 10) and a quarter of eps,
// which keeps the section points of the Stribeck study's periodic orbits as
// close to an rtol 1e-14 run as JZ's order 15 was (4e-12; 1.3e-11 without it).
constexpr double kStepMargin = 0.7 + 1.4;
// A step costs about p^2 + kLinearWork p (the Cauchy sums of the law's series
// and of Phi, against sincos, exp, the event polynomials and root refinement):
// the order minimises the work per unit time, (p^2 + b p) exp((L +
// kStepMargin) / (p - 1)) (Jorba & Zou 2005, section 3.2: their cost p^2,
// here with a linear term). b = 0 gives about JZ (3.8), p = L / 2 + 1;
// b = 25 gives 22 at eps = 1e-12, where the measured time per forcing period
// is least over p = 15 .. 27 (docs/benchmarks.md).
constexpr double kLinearWork = 25;
inline int TaylorOrderByWork(double eps) {
  // A flow is made per forcing period (IterateStroboscopic): the last
  // answer is kept, per thread, instead of 35 logarithms each time.
  thread_local double last_eps = 0;
  thread_local int last_order = 0;
  if (eps == last_eps) return last_order;
  const double L = -std::log(eps) + kStepMargin;
  int best = 2;
  double best_work = INFINITY;
  for (int p = 2; p <= kMaxOrder; ++p) {
    const double work = std::log(p * (p + kLinearWork)) + L / (p - 1);
    if (work < best_work) best_work = work, best = p;
  }
  last_eps = eps, last_order = best;
  return best;
}

// JZ (3.8): p = ceil(-ln(eps) / 2 + 1), the step rho / e^2 exp(-0.7 / (p - 1)).
// Kept where the extrema inside steps are wanted: their root isolation
// (Bernstein form, O(p^2)) made the by-work order slower there (forced_bench's
// non-stop orbit 4.6 -> 7.9 us at rtol 1e-12).
inline int TaylorOrderJz(double eps) {
  return std::min(kMaxOrder, static_cast<int>(std::ceil(-0.5 * std::log(eps) + 1.0)));
}

class SlipSeries {
 public:
  // by_work: TaylorOrderByWork and its step, else Jorba & Zou's (3.8).
  SlipSeries(const ForcedModel& m, double rtol, double atol, bool by_work)
      : m_(m),
        mu_(m.friction()),
        rtol_(rtol),
        atol_(atol),
        by_work_(by_work),
        order_rel_(by_work ? TaylorOrderByWork(rtol) : TaylorOrderJz(rtol)),
        order_abs_(by_work ? TaylorOrderByWork(atol) : TaylorOrderJz(atol)),
        log_rel_(std::log(rtol)),
        log_abs_(std::log(atol)) {
    for (auto& row : c_) std::fill(row, row + kRow, 0.0);
  }
  // The coefficients at (t0, z): z = (x, x') and, with variational, the 2 x 2
  // Phi column by column (z[2..5] = Phi00, Phi10, Phi01, Phi11).
  void Expand(Mode mode, double t0, const double* z, bool variational);
  // JZ section 3.2 with heyoka's safety factor (Biscani & Izzo 2021, eq. 10),
  // for the order chosen (TaylorOrderByWork or TaylorOrderJz).
  double StepSize() const;
  int order() const { return order_; }
  int size() const { return n_; }
  const double* coeff(int i) const { return c_[i]; }
  void Evaluate(double tau, double* out) const {
    for (int i = 0; i < n_; ++i) out[i] = Horner(c_[i], order_, tau);
  }

 private:
  template <LawKind L, bool Var>
  void Recur();

  const ForcedModel& m_;
  MuSeries mu_;
  double rtol_, atol_;
  bool by_work_;
  int order_rel_, order_abs_, order_ = 0, n_ = 2, sigma_ = 1;
  double log_rel_, log_abs_, log_eps_ = 0;  // ln rtol, ln atol, the one of this step
  double t0_ = 0;
  double c_[6][kRow];  // x, x', Phi's columns; kPad finite entries past the order
  Series<kMaxOrder> s_, cc_, cos_, sin_;
};

// Roots of a polynomial g (power coefficients in u on [0, 1], degree n, n <=
// kMaxOrder) in order: the first sign change from `sign`, then the next ones
// (g restricted to [u, 1] and divided by (w - u): heyoka's event loop).
// visit(u, new_sign) returns false to stop. An exact 0 counts as zero_sign.
template <class Visit>
void EachRoot(const double* g, int n, int sign, int zero_sign, Visit visit) {
  const double* poly = g;
  int d = n;
  double rest[kMaxOrder + 1];
  double u0 = 0;
  for (int guard = 0; guard <= 2 * n + 2; ++guard) {
    const PolyRoot r = FirstSignChange(poly, d, sign, zero_sign);
    if (!r.found) return;
    const double u = r.u == 1 ? 1.0 : u0 + (1 - u0) * r.u;
    sign = -sign;
    if (!visit(u, sign) || u >= 1) return;
    RestrictToTail(g, n, u, rest);
    poly = rest;
    d = n;
    while (d > 0 && poly[1] == 0) ++poly, --d;
    if (d == 0) return;
    ++poly, --d;
    if ((poly[0] > 0 ? 1 : -1) != sign) return;  // a touch, not a crossing: rounding
    u0 = u;
  }
}

// g / u for a g with a root at u = 0 (a start on the surface), the leading
// coefficients below rounding dropped: returns the new degree (-1 if g
// vanishes), *g advanced.
inline int Deflate(const double*& g, int n) {
  double scale = 0;
  for (int k = 0; k <= n; ++k) scale = std::max(scale, std::abs(g[k]));
  const double noise = Tolerances::kDeflateUlps * (n + 1) * Tolerances::kDeflateEps * scale;
  ++g, --n;  // g_0 is the root
  while (n > 0 && std::abs(g[0]) <= noise) ++g, --n;
  if (n == 0 && std::abs(g[0]) <= noise) return -1;
  return n;
}

}  // namespace stickslip::forced_detail
