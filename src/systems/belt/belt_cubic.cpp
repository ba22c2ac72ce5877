// The seed law's Taylor kernel (belt_taylor.hpp, Cubic3): Recurrences<kCubic>
// for mu = mu_s + c1 s + c3 s^3 (k5 = 0) in one loop whose order k + 1 waits
// little for orders k - 1 and k - 2; with the forcing A cos(theta) when Forced.
#include <algorithm>

#include "systems/belt/belt_taylor.hpp"

namespace stickslip {
// With s = sigma (v - x'), s_k = -sigma x'_k (k >= 1), w = s^2 and
// (s^3)_k = 3 s0^2 s_k + 6 s0 s1 s_{k-1} + T_k (k >= 3), where
//   T_k = sum_{j=2}^{k-2} w_j s_{k-j} + s1 (s^2)'_{k-1} + s0 sum_{j=2}^{k-2} s_j s_{k-j}
// and (s^2)'_m = sum_{j=1}^{m-1} s_j s_{m-j}: T_k needs orders up to k - 2
// only. The s_k term is the slope (damp), the s_{k-1} term joins x_k =
// x'_{k-1} / k (both linear in x'_{k-1}). The sums run on x' (s_j s_{k-j} =
// x'_j x'_{k-j}) against x' stored reversed (Dot: both ascend), the square's
// by its symmetry; their newest terms (j = 2, k - 2) are added last.
template <bool Var, int N, bool Forced>
STICKSLIP_KERNEL void BeltTaylorField::Cubic3(int order, const Rows& rows, const Order0& o0) {
  const double two_beta = two_beta_, sg = sigma_, a = force_;
  const double c1 = mu_->cubic(1), c3 = mu_->cubic(3);
  double w[kTaylorMaxOrder + 1];  // (s^2)_k
  double r[kTaylorMaxOrder + 1];  // x' reversed, r[max - k] = x'_k: the sums ascend in both
  double* cc = cc_.c();
  const double* co = cos_.c();
  double* x = rows.x;
  double* xd = rows.xd;
  // Order 0 (Cubic3Dispatch): x'_1, s0, w0 and the damping 2 beta + mu'(s_0).
  const double s0 = o0.s0, damp = o0.damp;
  w[0] = o0.w0;
  const double m2s0 = -2 * sg * s0;  // w_k = (s^2)'_k + m2s0 x'_k
  r[kTaylorMaxOrder] = xd[0];
  r[kTaylorMaxOrder - 1] = xd[1];
  if constexpr (Var) {
    const double dmu = c1 + 3 * c3 * w[0];
    cc[0] = -two_beta - dmu;
    Columns<true>(0, 1.0, dmu, rows);
  }
  const double xd1 = xd[1], sg_s0 = sg * s0, c3_6 = 6 * c3 * sg_s0 * xd1;
  double sq_prev = 0;  // (s^2)'_{k-1}
  // Order k: x'_{k+1} from the sums q, p of T_k, then the rest of order k.
  auto order_k = [&](int k, double q, double p) __attribute__((always_inline)) {
    const double inv = kBeltInverse.r[k];
    const double sq = k < 3 ? (k == 1 ? 0.0 : xd1 * xd1) : q + 2 * (xd1 * xd[k - 1]);  // (s^2)'_k
    if (k < 3) {
      // (s^3)_1 without s_1 is 0; (s^3)_2 without s_2 is 3 s0 s1^2.
      const double alpha = k == 1 ? 0.0 : (3 * c3) * (sg_s0 * sq);
      if constexpr (Forced)
        xd[k + 1] = ((alpha - x[k]) - damp * xd[k] + a * co[k]) * inv;
      else
        xd[k + 1] = ((alpha - x[k]) - damp * xd[k]) * inv;
    } else {
      // sigma c3 T_k = c3 (sg s0 q - p - x'_1 (s^2)'_{k-1}), sigma s = -x';
      // sigma c3 6 s0 s1 s_{k-1} - x_k = -b x'_{k-1} (x_k = x'_{k-1} / k).
      const double t = (sg_s0 * q - p) - xd1 * sq_prev;
      const double b = kBeltInverse.r[k - 1] - c3_6;
      const double next = ((c3 * inv) * t - (b * inv) * xd[k - 1]) - (damp * inv) * xd[k];
      xd[k + 1] = Forced ? next + (a * inv) * co[k] : next;
    }
    r[kTaylorMaxOrder - k - 1] = xd[k + 1];
    w[k] = sq + m2s0 * xd[k];
    sq_prev = sq;
    x[k + 1] = xd[k] * inv;
    if constexpr (Var) {
      const double dmu = 3 * c3 * w[k];
      cc[k] = -dmu;
      Columns<true>(k, inv, dmu, rows);
    }
  };
  // The sums of order k >= 5: q by its symmetry (half the terms), the newest
  // terms (j = 2, k - 2) last.
  auto sums_k = [&](int k) __attribute__((always_inline)) {
    const double* rk = r + kTaylorMaxOrder - k;  // rk[j] = x'_{k-j}
    const double mid = k % 2 == 0 ? xd[k / 2] * xd[k / 2] : 0.0;
    const double q = 2 * (Dot(xd + 3, rk + 3, (k - 1) / 2 - 2) + xd[2] * xd[k - 2]) + mid;
    const double p = Dot(w + 3, rk + 3, k - 5) + (w[2] * xd[k - 2] + w[k - 2] * xd[2]);
    order_k(k, q, p);
  };
  if constexpr (N > 0) order = N;
  for (int k = 1; k < std::min(order, 5); ++k) {
    if (k == 3)
      order_k(k, 0.0, 0.0);
    else if (k == 4)
      order_k(k, xd[2] * xd[2], w[2] * xd[2]);
    else
      order_k(k, 0.0, 0.0);
  }
  if constexpr (N > 0) {
    // The order known at compile time: the loops unroll, the sums' lengths
    // are constants (kFixedOrders).
#pragma GCC unroll 64
    for (int k = 5; k < N; ++k) sums_k(k);
  } else {
    for (int k = 5; k < order; ++k) sums_k(k);
  }
}

// Cubic3 at order N for N in [kMinFixed, kMaxFixed] (the seed law's orders
// at rtol 1e-6 to 1e-14: JZ's p + 6), at a run-time order otherwise.
constexpr int kMinFixed = 14, kMaxFixed = 26;
template <bool Var, bool Forced>
void BeltTaylorField::Cubic3Dispatch(int order, const Rows& r) {
  // Order 0: seed eq. (3.5) at the step start.
  const double sg = sigma_, c1 = mu_->cubic(1), c3 = mu_->cubic(3);
  double* xd = r.xd;
  const double s0 = sg * (v_ - xd[0]), w0 = s0 * s0;
  const double mu0 = (mu_->mu_s() + c1 * s0) + c3 * (w0 * s0);
  if constexpr (Forced)
    xd[1] = -r.x[0] - two_beta_ * xd[0] + sg * mu0 + force_ * cos_.c()[0];
  else
    xd[1] = -r.x[0] - two_beta_ * xd[0] + sg * mu0;
  r.x[1] = xd[0];
  const Order0 o0{s0, w0, two_beta_ + (c1 + w0 * (3 * c3))};
  using Fn = void (BeltTaylorField::*)(int, const Rows&, const Order0&);
  static constexpr Fn kFixed[] = {
      &BeltTaylorField::Cubic3<Var, 14, Forced>, &BeltTaylorField::Cubic3<Var, 15, Forced>,
      &BeltTaylorField::Cubic3<Var, 16, Forced>, &BeltTaylorField::Cubic3<Var, 17, Forced>,
      &BeltTaylorField::Cubic3<Var, 18, Forced>, &BeltTaylorField::Cubic3<Var, 19, Forced>,
      &BeltTaylorField::Cubic3<Var, 20, Forced>, &BeltTaylorField::Cubic3<Var, 21, Forced>,
      &BeltTaylorField::Cubic3<Var, 22, Forced>, &BeltTaylorField::Cubic3<Var, 23, Forced>,
      &BeltTaylorField::Cubic3<Var, 24, Forced>, &BeltTaylorField::Cubic3<Var, 25, Forced>,
      &BeltTaylorField::Cubic3<Var, 26, Forced>};
  static_assert(sizeof kFixed / sizeof kFixed[0] == kMaxFixed - kMinFixed + 1);
  if (order >= kMinFixed && order <= kMaxFixed)
    return (this->*kFixed[order - kMinFixed])(order, r, o0);
  Cubic3<Var, 0, Forced>(order, r, o0);
}

template void BeltTaylorField::Cubic3Dispatch<false, false>(int, const Rows&);
template void BeltTaylorField::Cubic3Dispatch<true, false>(int, const Rows&);
template void BeltTaylorField::Cubic3Dispatch<false, true>(int, const Rows&);
template void BeltTaylorField::Cubic3Dispatch<true, true>(int, const Rows&);

}  // namespace stickslip
