// The events of the Taylor stepper: the roots of g0 = x' - v, g1 = x'' and
// g2 = x' on each step polynomial, none missed (poly_roots.hpp, after heyoka's
// event detection, Biscani & Izzo 2021, MNRAS 504, section 4).
#include <algorithm>

#include "integrate/poly_roots.hpp"
#include "integrate/taylor_stepper.hpp"

namespace stickslip {

// The roots of g0 = x' - v, g1 = x'', g2 = x' on this step, in u = tau / h.
// The first root that stops (SlipProblem::stop_dir) ends the step there; the
// extrema before it that do not stop are recorded and passed.
void TaylorStepper::Events(double h) {
  const int n = order_;
  const double* xd = c_[1];
  // hp_ (the powers of h) is 0 past the order, c_ finite: whole blocks.
  double g[kNumRoots][kTaylorRowSize];
  for (int k = 0; k <= n + 1; ++k) g[2][k] = xd[k] * hp_[k];
  for (int k = 0; k <= n + 1; ++k) g[1][k] = kOrdinals.k[k + 1] * xd[k + 1] * hp_[k];
  g[1][n] = 0;  // x'' has degree n - 1
  std::copy(g[2], g[2] + n + 1, g[0]);
  g[0][0] = xd[0] - p_.model->v();
  // sum_{k>=3} |g_k| for the quadratic bound, once for g0 and g2 (they differ in g_0).
  const double tail02 = AbsSum(g[2] + 3, n - 2), tail1 = AbsSum(g[1] + 3, n - 3);
  const double tail[kNumRoots] = {tail02, tail1, tail02};
  const bool at_rest = p_.AtRest(c_[0][0], c_[1][0], c_[1][1]);
  Roots roots;
  for (int i = 0; i < kNumRoots; ++i) {
    if (i > 0 && at_rest) {  // noise on steady sliding: no events
      state_[i] = kInactive;
      continue;
    }
    if (!p_.events.Watched(i)) continue;  // no event on g_i
    EventRoots(i, g[i], i == 1 ? n - 1 : n, tail[i], roots);
  }
  // The roots passed before the end of the step; each flips its sign, and
  // those of non-terminal events go to their hook.
  passed_root_ = false;
  for (int j = 0; j < roots.n_passed; ++j) {
    const auto& r = roots.passed[j];
    if (r.u >= roots.first) continue;
    passed_root_ = true;
    sign_[r.i] = -sign_[r.i];
    // A root passed at the step end, to rounding: the next step starts on it.
    if (roots.first > 1 && (1 - r.u) * h <= Tolerances::StepEndRounding(tb_))
      state_[r.i] = kDeflate;
    if (!p_.on_event.fn || !p_.Passes(r.i, r.direction)) continue;
    double y[8];
    Evaluate(r.u * h, y);
    p_.on_event(r.i, y);
  }
  std::copy(roots.rf, roots.rf + kNumRoots, rf_);
  if (roots.first > 1) return;
  pending_ = true;
  for (int i = 0; i < kNumRoots; ++i)
    if (rf_[i] != 0) {
      state_[i] = kDeflate;
      sign_[i] = rf_[i];
    }
  tb_ = roots.first == 1 ? tb_ : ta_ + roots.first * h;
}

// The roots of g_i (degree deg) on (0, 1] in order, up to the first that
// stops or beyond roots.first: passed ones go to roots.passed.
void TaylorStepper::EventRoots(int i, const double* gi, int deg, double tail, Roots& roots) {
  // g0: an exact 0 counts as the mode's side; g1, g2: as positive (as the CVODE stepper).
  const int zero_sign = i == 0 && p_.mode == Mode::kSlipBelow ? -1 : 1;
  if (state_[i] == kInactive) state_[i] = kFresh;
  if (state_[i] == kFresh && gi[0] == 0) state_[i] = kDeflate;
  int sign, start_sign;  // g's sign after u = 0; sign_[i] before the passed roots
  const bool deflated = state_[i] == kDeflate;
  if (deflated) {
    // A root at the step start (a start on the surface, or the root just
    // returned) is not an event: g / u from there on.
    while (deg > 0 && gi[1] == 0) ++gi, --deg;
    if (deg == 0) return;  // g vanishes identically
    ++gi, --deg;
    sign = start_sign = gi[0] > 0 ? 1 : -1;
  } else {
    sign = start_sign = gi[0] > 0 ? 1 : (gi[0] < 0 ? -1 : zero_sign);
    if (state_[i] == kTracked && sign != sign_[i]) {
      // Changed sign across the step boundary (the two step polynomials
      // disagree within truncation): a root at the step start.
      if (roots.Add(i, 0.0, sign, p_.Stops(i, sign))) return;
      start_sign = -sign;  // passed: its flip comes with the others
    }
  }
  sign_[i] = start_sign;
  state_[i] = kTracked;
  if (!deflated && QuadraticBoundExcludes(gi, deg, sign, tail)) return;  // the common case
  const double* poly = gi;
  int d = deg;
  double rest[kTaylorMaxOrder + 1];  // g on [u, 1] after a passed root
  double u0 = 0;
  for (int guard = 0; guard <= 2 * deg + 2; ++guard) {
    const PolyRoot r = FirstSignChange(poly, d, sign, zero_sign);
    if (!r.found) return;
    const double u = r.u == 1 ? 1.0 : u0 + (1 - u0) * r.u;
    if (u > roots.first || roots.Add(i, u, -sign, p_.Stops(i, -sign)) || u >= 1) return;
    if (guard == 0 && Monotone(gi, deg)) return;  // the only root on [0, 1]
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
