#include "integrate/poly_roots.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

#include "integrate/series.hpp"

namespace stickslip {
namespace {

constexpr int kMaxDegree = 40;
constexpr int kMaxDepth = 60;     // halvings: 2^-60 is below double resolution on [0, 1]
constexpr int kMaxPieces = 2000;  // a bound on the work where g stays near 0
constexpr int kLowDegree = 8;     // LowHullExcludes

struct Piece {
  double u0, u1;
  int depth;
  double b[kMaxDegree + 1];
};

// b_i = sum_{k <= i} C(i, k) / C(n, k) c_k (Farouki & Rajan 1988), with the
// ratios tabulated once for every degree: rows of independent products.
class BernsteinTable {
 public:
  BernsteinTable() {
    int at = 0;
    for (int n = 0; n <= kMaxDegree; ++n) {
      start_[n] = at;
      for (int i = 0; i <= n; ++i) {
        double ratio = 1;  // C(i, k) / C(n, k), from k = 0
        for (int k = 0; k <= i; ++k) {
          ratio_[at++] = ratio;
          if (k < i) ratio *= static_cast<double>(i - k) / (n - k);
        }
      }
    }
  }
  const double* Row(int n, int i) const { return ratio_ + start_[n] + i * (i + 1) / 2; }

 private:
  static constexpr int kSize = (kMaxDegree + 1) * (kMaxDegree + 2) * (kMaxDegree + 3) / 6;
  int start_[kMaxDegree + 1];
  double ratio_[kSize];
};

// Out of line and not cloned: one copy for both hulls, not a constant-
// degree clone beside it (the hot code's footprint, docs/benchmarks.md,
// "Where the fetch cliff is").
[[gnu::noinline, gnu::noclone]] void ToBernstein(const double* c, int n, double* b) {
  static const BernsteinTable table;
  for (int i = 0; i <= n; ++i) {
    const double* r = table.Row(n, i);
    double s0 = 0, s1 = 0;
    int k = 0;
    for (; k + 1 <= i; k += 2) {
      s0 += r[k] * c[k];
      s1 += r[k + 1] * c[k + 1];
    }
    if (k == i) s0 += r[k] * c[k];
    b[i] = s0 + s1;
  }
}

// De Casteljau at 1/2: left half into l, right half into r.
void Split(const double* b, int n, double* l, double* r) {
  double w[kMaxDegree + 1];
  std::copy(b, b + n + 1, w);
  for (int j = 0; j <= n; ++j) {
    l[j] = w[0];
    r[n - j] = w[n - j];
    for (int i = 0; i < n - j; ++i) w[i] = 0.5 * (w[i] + w[i + 1]);
  }
}

int Sign(double x, int zero_sign) { return x > 0 ? 1 : (x < 0 ? -1 : zero_sign); }

// std::nextafter(x, 2.0) for x in [0, 2) by the bits (the libm call is not inlined).
double NextUp(double x) {
  if (!(x >= 0 && x < 2)) return std::nextafter(x, 2.0);
  if (x == 0) return std::numeric_limits<double>::denorm_min();
  std::uint64_t b;
  std::memcpy(&b, &x, sizeof b);
  ++b;
  std::memcpy(&x, &b, sizeof b);
  return x;
}

// std::nextafter(x, 0.0) for x in (0, 2] by the bits.
double NextDown(double x) {
  if (!(x > 0 && x <= 2)) return std::nextafter(x, 0.0);
  std::uint64_t b;
  std::memcpy(&b, &x, sizeof b);
  --b;
  std::memcpy(&x, &b, sizeof b);
  return x;
}

}  // namespace

void RestrictToTail(const double* c, int n, double u, double* out) {
  std::copy(c, c + n + 1, out);
  for (int j = 0; j < n; ++j)
    for (int k = n - 1; k >= j; --k) out[k] += u * out[k + 1];
  double scale = 1;
  for (int k = 1; k <= n; ++k) out[k] *= (scale *= 1 - u);
}

namespace {
// Horner(a, n, u) and Horner(b, n, u) in one loop: the same operations in the
// same order as each alone, their four chains interleaved.
inline void HornerPair(const double* a, const double* b, int n, double u, double* ga, double* gb) {
  const double u2 = u * u;
  int k = n % 2 == 0 ? n : n - 1;  // highest even index
  double ea = a[k], oa = n % 2 == 1 ? a[n] : 0.0;
  double eb = b[k], ob = n % 2 == 1 ? b[n] : 0.0;
  for (k -= 2; k >= 0; k -= 2) {
    ea = ea * u2 + a[k];
    oa = oa * u2 + a[k + 1];
    eb = eb * u2 + b[k];
    ob = ob * u2 + b[k + 1];
  }
  *ga = ea + u * oa;
  *gb = eb + u * ob;
}

// The first point of [u0, u1] where sign * g has changed sign, given that it
// has at u1 (g1 = g(u1), the caller's) and not at u0: Newton on the
// polynomial, safeguarded by the bracket [lo, hi] (g has `sign` at lo and not
// at hi), then bisection.
double RefineRoot(const double* c, int n, int sign, int zero_sign, double u0, double u1,
                  double g1) {
  auto g = [&](double u) { return Horner(c, n, u); };
  auto changed = [&](double u) { return Sign(g(u), zero_sign) != sign; };
  double lo = u0, hi = u1, x = 0.5 * (u0 + u1);
  const double g0 = u0 == 0 ? c[0] : g(u0);  // g(0) = c_0, as Horner gives it
  if (g0 != g1) {                            // start from the secant (regula falsi) point
    const double xs = u0 - g0 * (u1 - u0) / (g1 - g0);
    if (xs > u0 && xs < u1) x = xs;
  }
  // g' by its own coefficients (dc_n = 0: Horner to degree n gives g' as
  // to n - 1); g and g' in one loop of four independent chains.
  double dc[kMaxDegree + 1];
  for (int k = 1; k <= n; ++k) dc[k - 1] = k * c[k];
  dc[n] = 0;
  for (int it = 0; it < Tolerances::kPolyNewtonCap; ++it) {
    double gx, dg;
    HornerPair(c, dc, n, x, &gx, &dg);
    (Sign(gx, zero_sign) != sign ? hi : lo) = x;
    double next = x - gx / dg;
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    const bool done = std::abs(next - x) <= Tolerances::kPolyNewtonStep * Tolerances::Scale(x);
    x = next;
    if (done || !(hi - lo > Tolerances::PolyWidth(hi))) break;
  }
  if (x > lo && x < hi) {
    // Newton's x is within an ulp or so of the change: its neighbour on the
    // other side mostly decides it (two evaluations); else a probe a few ulp
    // away and the bisection.
    const double d = Tolerances::PolyProbe(x);
    if (changed(x)) {
      hi = x;
      const double below = NextDown(x);
      if (below > lo && !changed(below)) return x;
      if (x - d > lo && !changed(x - d)) lo = x - d;
    } else {
      lo = x;
      const double above = NextUp(x);
      if (above < hi && changed(above)) return above;
      if (x + d < hi && changed(x + d)) hi = x + d;
    }
  }
  for (int it = 0; it < Tolerances::kPolyBisectionCap && NextUp(lo) < hi; ++it) {
    const double mid = 0.5 * (lo + hi);
    if (mid <= lo || mid >= hi) break;
    (changed(mid) ? hi : lo) = mid;
  }
  return hi;
}

// Monotone on [0, 1]: one root at most, there iff the sign at 1 differs; no
// isolation needed.
PolyRoot MonotoneRoot(const double* c, int n, int sign, int zero_sign) {
  PolyRoot out;
  out.monotone = true;
  const double g1 = Horner(c, n, 1.0);
  if (Sign(g1, zero_sign) != sign)
    out.found = true, out.u = RefineRoot(c, n, sign, zero_sign, 0.0, 1.0, g1);
  return out;
}

// Whether sign * c stays above 0 on [0, 1] by the Bernstein hull of its
// first kLowDegree + 1 terms less the rest, sum_{k > kLowDegree} |c_k|, with
// twice the rounding margin (as CubicBoundExcludes): then no evaluation of c
// changes sign there, and the full search finds no root either. Most calls
// past the quadratic bound have no root (12102 of 17713 on the Coulomb orbit
// diagram), and this hull takes 45 products against the full one's 253 at
// degree 22 (docs/benchmarks.md, "A low-degree hull").
bool LowHullExcludes(const double* c, int n, int sign, double scale) {
  if (n <= kLowDegree) return false;
  double rest = 0;
  for (int k = kLowDegree + 1; k <= n; ++k) rest += std::abs(c[k]);
  double b[kLowDegree + 1];
  ToBernstein(c, kLowDegree, b);
  double lower = INFINITY;
  for (int i = 0; i <= kLowDegree; ++i) lower = std::min(lower, sign * b[i]);
  return lower - rest > 2 * Tolerances::PolyMargin(n, scale);
}

}  // namespace

PolyRoot FirstSignChange(const double* c, int n, int sign, int zero_sign) {
  const double tail = AbsSum(c + 3, n - 2);  // sum_{k>=3} |c_k|
  // The cheap bound first, then the Bernstein hull.
  if (QuadraticBoundExcludes(c, n, sign, tail)) return PolyRoot();
  return FirstSignChangePast(c, n, sign, zero_sign, tail);
}

PolyRoot FirstSignChangePast(const double* c, int n, int sign, int zero_sign, double tail) {
  PolyRoot out;
  double scale = tail;
  for (int k = 0; k <= std::min(n, 2); ++k) scale += std::abs(c[k]);
  if (scale == 0) return out;
  // Rounding of the conversion and the halvings: a few ulp of sum |c_k| per degree.
  const double margin = Tolerances::PolyMargin(n, scale);
  auto g = [&](double u) { return Horner(c, n, u); };
  auto changed = [&](double u) { return Sign(g(u), zero_sign) != sign; };
  if (Monotone(c, n)) return MonotoneRoot(c, n, sign, zero_sign);
  // The cubic part's bound, before the Bernstein coefficients (O(n^2)).
  if (CubicBoundExcludes(c, n, sign, tail - (n >= 3 ? std::abs(c[3]) : 0.0), scale)) return out;
  if (LowHullExcludes(c, n, sign, scale)) return out;
  // Depth-first, left half first: the first interval that holds a sign change
  // holds the first root.
  Piece stack[kMaxDepth + 2];
  int top = 0, pieces = 0;
  stack[0].u0 = 0;
  stack[0].u1 = 1;
  stack[0].depth = 0;
  ToBernstein(c, n, stack[0].b);
  while (top >= 0) {
    Piece& p = stack[top];
    const double* b = p.b;
    double lower = INFINITY;  // min of sign * b_i: a lower bound of sign * g here
    int variations = 0;
    for (int i = 0; i <= n; ++i) {
      lower = std::min(lower, sign * b[i]);
      if (i > 0 && Sign(b[i], zero_sign) != Sign(b[i - 1], zero_sign)) ++variations;
    }
    if (lower > margin) {  // no root here
      --top;
      continue;
    }
    const double u0 = p.u0, u1 = p.u1;
    const double g1 = g(u1);
    const bool end_changed = Sign(g1, zero_sign) != sign;
    const bool isolated = variations == 1 && end_changed && !changed(u0);
    // Within rounding of 0 (lower >= -margin), only a sign change that shows
    // in the values counts: halving further would chase noise.
    const bool noise = lower >= -margin || ++pieces > kMaxPieces;
    if (isolated || noise || p.depth >= kMaxDepth || u1 - u0 <= Tolerances::PolyWidth(u1)) {
      if (!end_changed) {  // a touch within rounding, or no root: nothing here
        --top;
        continue;
      }
      // Bracket [u0, u1]: g has `sign` at u0 (or u0 is the interval start) and not at u1.
      if (changed(u0)) {
        out.found = true;
        out.u = u0;
        return out;
      }
      out.found = true;
      out.u = RefineRoot(c, n, sign, zero_sign, u0, u1, g1);
      return out;
    }
    // Halve: the right half below the left one on the stack.
    Piece& right = stack[top];
    double lb[kMaxDegree + 1], rb[kMaxDegree + 1];
    Split(b, n, lb, rb);
    const double mid = 0.5 * (u0 + u1);
    const int depth = p.depth + 1;
    right.u0 = mid;
    right.u1 = u1;
    right.depth = depth;
    std::copy(rb, rb + n + 1, right.b);
    Piece& l = stack[++top];
    l.u0 = u0;
    l.u1 = mid;
    l.depth = depth;
    std::copy(lb, lb + n + 1, l.b);
  }
  return out;
}

}  // namespace stickslip
