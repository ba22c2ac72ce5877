// The events of the Taylor stepper: the roots of the segment's event
// functions (events.hpp) on each step polynomial, none missed (poly_roots.hpp,
// after heyoka's event detection, Biscani & Izzo 2021, MNRAS 504, section 4).
#include <algorithm>
#include <cmath>

#include "integrate/poly_roots.hpp"
#include "integrate/taylor_stepper.hpp"

namespace stickslip {

namespace {
// g_k = coef(k) for k <= deg, returning sum_{k>=3} |g_k| summed as AbsSum
// sums it (two lanes, an odd last term after them): the same tail, from the
// values in registers, not reloaded from g (a load across two stores).
template <class Coef>
inline double FillWithTail(double* __restrict g, int deg, Coef coef) {
  for (int k = 0; k < 3 && k <= deg; ++k) g[k] = coef(k);
  double s0 = 0, s1 = 0;
  int k = 3;
  for (; k + 1 <= deg; k += 2) {
    const double a = coef(k), b = coef(k + 1);
    g[k] = a;
    g[k + 1] = b;
    s0 += std::abs(a);
    s1 += std::abs(b);
  }
  double tail = s0 + s1;
  if (k <= deg) tail += std::abs(g[k] = coef(k));
  return tail;
}
}  // namespace

// The step polynomial in u = tau / h of each function of its own shape
// (EventFunction::base); the others share it, with their own g_0 (g0_).
void TaylorStepper::EventPolynomials(int n) {
  const EventList& ev = p_->Events();
  const TaylorRow* r = c();
  const double* __restrict hp = hp_;
  const int nf = ev.functions();
  for (int i = 0; i < nf; ++i) {
    const EventFunction& f = ev.function(i);
    if (f.base != i) {
      g0_[i] = raw0_[f.base] - f.offset;
      tail_[i] = tail_[f.base];
      continue;
    }
    double* __restrict g = &poly_[static_cast<size_t>(i) * kTaylorRowSize];
    const double* __restrict r0 = r[f.terms[0].row];
    const bool single = f.size == 1 && f.terms[0].weight == 1;
    if (!f.derivative) {
      // tail_: sum_{k>=3} |g_k| for the quadratic bound.
      if (single) {
        tail_[i] = FillWithTail(g, n, [&](int k) { return r0[k] * hp[k]; });
      } else if (f.size == 2) {  // a stick exit, lambda -+ limit: the same sums
        const double* __restrict r1 = r[f.terms[1].row];
        const double w0 = f.terms[0].weight, w1 = f.terms[1].weight;
        tail_[i] =
            FillWithTail(g, n, [&](int k) { return (0.0 + w0 * r0[k] + w1 * r1[k]) * hp[k]; });
      } else {
        tail_[i] = FillWithTail(g, n, [&](int k) {
          double s = 0;
          for (int t = 0; t < f.size; ++t) s += f.terms[t].weight * r[f.terms[t].row][k];
          return s * hp[k];
        });
      }
      g[n + 1] = 0;
    } else {
      if (single) {
        tail_[i] =
            FillWithTail(g, n - 1, [&](int k) { return kOrdinals.k[k + 1] * r0[k + 1] * hp[k]; });
      } else {
        tail_[i] = FillWithTail(g, n - 1, [&](int k) {
          double s = 0;
          for (int t = 0; t < f.size; ++t) s += f.terms[t].weight * r[f.terms[t].row][k + 1];
          return kOrdinals.k[k + 1] * s * hp[k];
        });
      }
      g[n] = g[n + 1] = 0;  // the derivative has degree n - 1
    }
    raw0_[i] = g[0];
    g0_[i] = g[0] - f.offset;
  }
}

// The roots of every event function on this step, in u = tau / h. The first
// root that stops ends the step there; the roots before it that do not stop
// are passed to the problem's hook.
void TaylorStepper::Events(double h) {
  const int n = order_;
  const EventList& ev = p_->Events();
  const int nf = ev.functions();
  if (nf == 0) {
    passed_root_ = false;
    return;
  }
  EventPolynomials(n);
  const TaylorRow* r = c();
  // Noise on steady sliding: no events but the arrivals.
  bool at_rest = false;
  if (p_->has_rest)
    at_rest = p_->AtRestBy([r](int i) { return r[i][0]; }, [r](int i) { return r[i][1]; });
  passed_.clear();
  Roots roots;
  roots.rf = rf_.data();
  roots.nf = nf;
  roots.passed = &passed_;
  std::fill(rf_.begin(), rf_.begin() + nf, 0);
  for (int i = 0; i < nf; ++i) {
    const EventFunction& f = ev.function(i);
    if (!f.surface && at_rest) {
      state_[i] = kInactive;
      continue;
    }
    const double* g = &poly_[static_cast<size_t>(f.base) * kTaylorRowSize];
    EventRoots(i, g, f.derivative ? n - 1 : n, tail_[i], h, roots);
  }
  // The roots passed before the end of the step; each flips its sign, and
  // those of non-terminal events go to their hook.
  passed_root_ = false;
  for (const auto& pr : passed_) {
    if (pr.u >= roots.first) continue;
    passed_root_ = true;
    sign_[pr.i] = -sign_[pr.i];
    // A root passed at the step end, to rounding: the next step starts on it.
    if (roots.first > 1 && (1 - pr.u) * h <= Tolerances::StepEndRounding(tb_))
      state_[pr.i] = kDeflate;
    if (!p_->on_event.fn || !ev.Passes(pr.i, pr.direction)) continue;
    Evaluate(ta_ + pr.u * h, hook_y_.data(), layout_.n);  // the state: what hooks read
    p_->on_event(pr.i, hook_y_.data());
  }
  if (roots.first > 1) return;
  pending_ = true;
  for (int i = 0; i < nf; ++i)
    if (rf_[i] != 0) {
      state_[i] = kDeflate;
      sign_[i] = rf_[i];
    }
  tb_ = roots.first == 1 ? tb_ : ta_ + roots.first * h;
}

// The roots of g_i (degree deg) on (0, 1] in order, up to the first that
// stops or beyond roots.first: passed ones go to roots.passed.
void TaylorStepper::EventRoots(int i, const double* base, int deg, double tail, double h,
                               Roots& roots) {
  const EventList& ev = p_->Events();
  const EventFunction& f = ev.function(i);
  const int zero_sign = f.zero_sign;
  // g = base with g_0 = g0_[i]: the quick exclusion reads g_0..g_2, the rest
  // of the search a copy (gc) with this function's g_0.
  const double g0 = g0_[i];
  double gc[kTaylorRowSize], gd[kTaylorRowSize];
  const double* gi = nullptr;
  auto own = [&]() {
    if (gi) return;
    std::copy(base, base + deg + 1, gc);
    gc[0] = g0;
    gi = gc;
  };
  if (state_[i] == kInactive) state_[i] = kFresh;
  if (state_[i] == kFresh && g0 == 0 && f.deflate_at_start) state_[i] = kDeflate;
  int sign, start_sign;  // g's sign after u = 0; sign_[i] before the passed roots
  const bool deflated = state_[i] == kDeflate;
  if (deflated) {
    own();
    // A root at the step start (a start on the surface, or the root just
    // returned) is not an event: g / u from there on.
    while (deg > 0 && gi[1] == 0) ++gi, --deg;
    if (deg == 0) return;  // g vanishes identically
    ++gi, --deg;
    sign = start_sign = gi[0] > 0 ? 1 : (gi[0] < 0 ? -1 : zero_sign);
    // On a surface just left (a stick exit with mu(0+) = mu_s: x'' = 0
    // there), the deflated constant x'' h is rounding: its sign must not
    // count (it sent the flow straight back into stick at the same t, over
    // and over): it counts as the mode's side.
    if (f.surface && fresh_segment_ && deg >= 1 &&
        std::abs(gi[0]) <= Tolerances::SurfaceRounding() * surface_scale_ * h) {
      std::copy(gi, gi + deg + 1, gd);
      gd[0] = 0;
      gi = gd;
      sign = start_sign = zero_sign;
    }
  } else {
    sign = start_sign = g0 > 0 ? 1 : (g0 < 0 ? -1 : zero_sign);
    if (state_[i] == kTracked && sign != sign_[i]) {
      // Changed sign across the step boundary (the two step polynomials
      // disagree within truncation): a root at the step start.
      if (roots.Add(i, 0.0, sign, ev.Stops(i, sign))) return;
      start_sign = -sign;  // passed: its flip comes with the others
    }
  }
  sign_[i] = start_sign;
  state_[i] = kTracked;
  if (!deflated) {
    const double q[3] = {g0, deg >= 1 ? base[1] : 0.0, deg >= 2 ? base[2] : 0.0};
    if (QuadraticBoundExcludes(q, deg, sign, tail)) return;  // the common case; else past it
    own();
  }
  const double* poly = gi;
  int d = deg;
  double rest[kTaylorMaxOrder + 1], u0 = 0;  // rest: g on [u, 1] after a passed root
  for (int guard = 0; guard <= 2 * deg + 2; ++guard) {
    const PolyRoot pr = guard > 0 || deflated ? FirstSignChange(poly, d, sign, zero_sign)
                                              : FirstSignChangePast(poly, d, sign, zero_sign, tail);
    if (!pr.found) return;
    const double u = pr.u == 1 ? 1.0 : u0 + (1 - u0) * pr.u;
    // A surface just left, back on the mode's side at the start's time (two
    // contacts leaving stick at once): a touch, passed, not a step of 0.
    const bool touch = deflated && f.surface && ta_ + u * h == ta_ && -sign == zero_sign;
    if (u > roots.first || roots.Add(i, u, -sign, !touch && ev.Stops(i, -sign)) || u >= 1) return;
    if (guard == 0 && pr.monotone) return;  // the only root on [0, 1]
    // Passed: go on from u with g / (w - u) (the root is not an event twice).
    sign = -sign;
    RestrictToTail(gi, deg, u, rest);
    poly = rest;
    d = deg;
    while (d > 0 && poly[1] == 0) ++poly, --d;
    if (d == 0) return;
    ++poly, --d;
    if ((poly[0] > 0 ? 1 : -1) != sign) return;  // a touch, not a crossing: rounding
    u0 = u;
  }
}

}  // namespace stickslip
