// The belt model's Taylor recurrences (the model seam's TaylorField):
// seed eq. (3.5) on one slip branch, with the variational equations and the
// parameter column, law by law (MuSeries: the series of mu(s)).
#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <string>

#include "integrate/mu_series.hpp"
#include "integrate/taylor_field.hpp"
#include "numerics/kernel.hpp"
#include "numerics/tolerances.hpp"
#include "stickslip/errors.hpp"
#include "stickslip/model/model.hpp"
#include "stickslip/model/parameter_axis.hpp"

namespace stickslip {
namespace {

class BeltTaylorField final : public TaylorField {
 public:
  explicit BeltTaylorField(const std::optional<ParameterAxis>& parameter) : parameter_(parameter) {}

  bool Bind(const FrictionSystem& s, Mode m) override {
    const auto* belt = dynamic_cast<const Model*>(&s);
    if (!belt) return false;
    q_ = belt->params();
    law_ = belt->friction().law();
    v_ = belt->v();
    two_beta_ = 2 * belt->beta();
    sigma_ = m == Mode::kSlipBelow ? 1 : -1;
    // The series' entries are cleared or set before they are read, each step
    // (the leading zeros are never written): a new law only needs a new one.
    if (!mu_ || !mu_->Of(belt->friction())) mu_.emplace(belt->friction());
    cubic3_ = law_ == LawKind::kCubic && mu_->cubic(5) == 0;
    if (parameter_) ResolveParameter();
    return true;
  }
  void Coefficients(int order, int n, TaylorRow* c) override;
  // The seed law's loop (Cubic3) only: the other laws keep JZ's rule (at
  // p + 4 the quintic chart's fold point moved by 1e-10 and a Leine
  // pure-slip amplitude by 1.3e-12; docs/benchmarks.md).
  int ExtraOrder() const override {
    return cubic3_ && !(parameter_ && kind_ == ParamKind::kAffine)
               ? Tolerances::kTaylorExtraOrderCubic
               : 0;
  }

 private:
  template <LawKind L, bool Var>
  void Recurrences(int order, int n, TaylorRow* c);
  // Order 0 of the seed law's loop, outside its kernel clones: x'' at the
  // step start exactly as the model's field (no FMA), which the mode switches read.
  struct Order0 {
    double s0, w0, damp;
  };
  template <bool Var, int N>
  STICKSLIP_KERNEL void Cubic3(int order, int n, TaylorRow* c, const Order0& o0);
  template <bool Var>
  void Cubic3Dispatch(int order, int n, TaylorRow* c);
  template <bool Newest>
  void Columns(int k, int n, double inv, double dmu, TaylorRow* c);
  void ResolveParameter();
  double ParamTerm(const TaylorRow* c, int k, double muk, double muk_shifted, double dmu) const;

  Params q_;
  LawKind law_ = LawKind::kCubic;
  double v_ = 0, two_beta_ = 0;
  int sigma_ = 1;        // F = sigma mu(s), s = sigma (v - x')
  bool cubic3_ = false;  // the cubic law without the quintic term: Cubic3
  // The series of s = sigma (v - x'), of -2 beta - mu'(s), of mu.
  Series<kTaylorMaxOrder> s_, cc_;
  std::optional<MuSeries> mu_;
  // The parameter column dz/dp (rows 6, 7): which term df/dp carries.
  enum class ParamKind { kBeta, kV, kAffine };
  std::optional<ParameterAxis> parameter_;
  ParamKind kind_ = ParamKind::kBeta;
  std::optional<MuSeries> mu_shifted_;  // kAffine: the law at p + dp_
  double dp_ = 1;
};

// Seed eq. (3.5) on one slip branch, x'' = -x - 2 beta x' + sigma mu(s), and
// Phi' = J Phi with J = [0 1; -1 c], c = -2 beta - mu'(s), and the parameter
// column z_p' = J z_p + df/dp: coefficient k + 1 from those up to k.
template <LawKind L, bool Var>
void BeltTaylorField::Recurrences(int order, int n, TaylorRow* c) {
  const double v = v_, two_beta = two_beta_;
  MuSeries& mu = *mu_;
  double* s = s_.c();
  double* cc = cc_.c();
  double* x = c[0];
  double* xd = c[1];
  // Zeros in s past the order so far: the sums of products in MuSeries::Old
  // leave out what is new. (c and cc only need finite entries there.)
  for (int k = 0; k < order + kPad; ++k) s[k] = 0;
  mu.Begin<L>(order);
  double damp = 0;  // 2 beta + mu'(s_0)
  MuSeries* shifted = Var && n == 8 && mu_shifted_ ? &*mu_shifted_ : nullptr;
  if (shifted) shifted->Begin<L>(order);
  for (int k = 0; k < order; ++k) {
    mu.Old<L, Var>(k, s);
    if (shifted) shifted->Old<L, false>(k, s);
    const double inv = kTaylorInverse.r[k];
    if (k > 0) {
      // mu_k = alpha + mu'(s_0) s_k with s_k = -sigma x'_k: x'_{k+1} without
      // waiting for the products of s_k (the chain from x'_k is short).
      const double sigma_alpha = mu.Alpha<L>(k, sigma_);
      xd[k + 1] = ((sigma_alpha - x[k]) - damp * xd[k]) * inv;
    }
    s[k] = sigma_ * ((k == 0 ? v : 0.0) - xd[k]);
    double dmu = 0;
    const double muk = mu.New<L, Var>(k, s, &dmu);
    const double muk_shifted = shifted ? shifted->New<L, false>(k, s, nullptr) : 0.0;
    x[k + 1] = xd[k] * inv;
    if (k == 0) {
      xd[1] = -x[0] - two_beta * xd[0] + sigma_ * muk;
      damp = two_beta + mu.slope();
    }
    if constexpr (Var) {
      cc[k] = (k == 0 ? -two_beta : 0.0) - dmu;
      Columns<false>(k, n, inv, dmu, c);
      if (n == 8 && kind_ == ParamKind::kAffine) {
        c[7][k + 1] += ParamTerm(c, k, muk, muk_shifted, dmu) * inv;
      }
    }
  }
}

// Phi' = J Phi and the parameter column (beta, v) at order k + 1, cc_ set to k.
template <bool Newest>
inline void BeltTaylorField::Columns(int k, int n, double inv, double dmu, TaylorRow* c) {
  const double* cc = cc_.c();
  int col = 2;
  if constexpr (Newest) {
    // Cubic3: the newest terms (j = 0 and k) last, as there; Phi's two
    // columns against cc in one pass (the same sums as one at a time).
    PhiColumnsNext(c[2], c[3], c[4], c[5], cc, k, inv);
    col = 6;
  }
  for (; col < n; col += 2) {
    const double* p = c[col + 1];
    const double cq = !Newest  ? Cauchy(p, cc, k)
                      : k == 0 ? p[0] * cc[0]
                               : CauchyRange(p, cc, 1, k - 1, k) + (p[0] * cc[k] + p[k] * cc[0]);
    c[col][k + 1] = c[col + 1][k] * inv;
    c[col + 1][k + 1] = (-c[col][k] + cq) * inv;
  }
  if (n == 8 && kind_ != ParamKind::kAffine) c[7][k + 1] += ParamTerm(c, k, 0, 0, dmu) * inv;
}

// Recurrences<kCubic> for mu = mu_s + c1 s + c3 s^3 (k5 = 0, the seed law),
// in one loop whose order k + 1 waits little for orders k - 1 and k - 2.
// With s = sigma (v - x'), s_k = -sigma x'_k (k >= 1), w = s^2 and
// (s^3)_k = 3 s0^2 s_k + 6 s0 s1 s_{k-1} + T_k (k >= 3), where
//   T_k = sum_{j=2}^{k-2} w_j s_{k-j} + s1 (s^2)'_{k-1} + s0 sum_{j=2}^{k-2} s_j s_{k-j}
// and (s^2)'_m = sum_{j=1}^{m-1} s_j s_{m-j}: T_k needs orders up to k - 2
// only. The s_k term is the slope (damp), the s_{k-1} term joins x_k =
// x'_{k-1} / k (both linear in x'_{k-1}). The sums run on x' (s_j s_{k-j} =
// x'_j x'_{k-j}) against x' stored reversed (Dot: both ascend), the square's
// by its symmetry; their newest terms (j = 2, k - 2) are added last.
template <bool Var, int N>
STICKSLIP_KERNEL void BeltTaylorField::Cubic3(int order, int n, TaylorRow* c, const Order0& o0) {
  const double two_beta = two_beta_, sg = sigma_;
  const double c1 = mu_->cubic(1), c3 = mu_->cubic(3);
  double w[kTaylorMaxOrder + 1];  // (s^2)_k
  double r[kTaylorMaxOrder + 1];  // x' reversed, r[max - k] = x'_k: the sums ascend in both
  double* cc = cc_.c();
  double* x = c[0];
  double* xd = c[1];
  // Order 0 (Cubic3Dispatch): x'_1, s0, w0 and the damping 2 beta + mu'(s_0).
  const double s0 = o0.s0, damp = o0.damp;
  w[0] = o0.w0;
  const double m2s0 = -2 * sg * s0;  // w_k = (s^2)'_k + m2s0 x'_k
  r[kTaylorMaxOrder] = xd[0];
  r[kTaylorMaxOrder - 1] = xd[1];
  if constexpr (Var) {
    const double dmu = c1 + 3 * c3 * w[0];
    cc[0] = -two_beta - dmu;
    Columns<true>(0, n, 1.0, dmu, c);
  }
  const double xd1 = xd[1], sg_s0 = sg * s0, c3_6 = 6 * c3 * sg_s0 * xd1;
  double sq_prev = 0;  // (s^2)'_{k-1}
  // Order k: x'_{k+1} from the sums q, p of T_k, then the rest of order k.
  auto order_k = [&](int k, double q, double p) __attribute__((always_inline)) {
    const double inv = kTaylorInverse.r[k];
    const double sq = k < 3 ? (k == 1 ? 0.0 : xd1 * xd1) : q + 2 * (xd1 * xd[k - 1]);  // (s^2)'_k
    if (k < 3) {
      // (s^3)_1 without s_1 is 0; (s^3)_2 without s_2 is 3 s0 s1^2.
      const double alpha = k == 1 ? 0.0 : (3 * c3) * (sg_s0 * sq);
      xd[k + 1] = ((alpha - x[k]) - damp * xd[k]) * inv;
    } else {
      // sigma c3 T_k = c3 (sg s0 q - p - x'_1 (s^2)'_{k-1}), sigma s = -x';
      // sigma c3 6 s0 s1 s_{k-1} - x_k = -b x'_{k-1} (x_k = x'_{k-1} / k).
      const double t = (sg_s0 * q - p) - xd1 * sq_prev;
      const double b = kTaylorInverse.r[k - 1] - c3_6;
      xd[k + 1] = ((c3 * inv) * t - (b * inv) * xd[k - 1]) - (damp * inv) * xd[k];
    }
    r[kTaylorMaxOrder - k - 1] = xd[k + 1];
    w[k] = sq + m2s0 * xd[k];
    sq_prev = sq;
    x[k + 1] = xd[k] * inv;
    if constexpr (Var) {
      const double dmu = 3 * c3 * w[k];
      cc[k] = -dmu;
      Columns<true>(k, n, inv, dmu, c);
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

// df/dp of seed eq. (3.5) for the parameter column: beta gives (0, -2 x');
// v enters through s = sigma (v - x') only, giving (0, mu'(s)); a law
// parameter mu depends on affinely (mu_s, mu_m, mu_k, k5) gives
// (0, sigma (mu(s; p + dp) - mu(s; p)) / dp), exact for any dp. v_m, v_s and
// delta enter mu non-affinely: no column (InvalidArgument).
void BeltTaylorField::ResolveParameter() {
  const ParameterAxis& axis = *parameter_;
  if (!ParameterColumnSupported(q_.law, axis))
    throw InvalidArgument("parameter column: '" + axis.name() +
                          "' enters the friction law non-affinely (not supported)");
  mu_shifted_.reset();
  if (axis.id() == Parameter::kBeta) {
    kind_ = ParamKind::kBeta;
  } else if (axis.id() == Parameter::kV) {
    kind_ = ParamKind::kV;
  } else {
    kind_ = ParamKind::kAffine;
    dp_ = std::max(1.0, std::abs(axis.Get(q_)));
    mu_shifted_.emplace(Friction(axis.At(q_, axis.Get(q_) + dp_)));
  }
}

// Coefficient k of df_2/dp (ResolveParameter), from this step's series; the
// shifted law's coefficient k is computed in the same loop (Recurrences).
double BeltTaylorField::ParamTerm(const TaylorRow* c, int k, double muk, double muk_shifted,
                                  double dmu) const {
  switch (kind_) {
    case ParamKind::kBeta:
      return -2 * c[1][k];
    case ParamKind::kV:
      return dmu;
    case ParamKind::kAffine:
      return sigma_ * (muk_shifted - muk) / dp_;
  }
  return 0;
}

// Cubic3 at order N for N in [kMinFixed, kMaxFixed] (the seed law's orders
// at rtol 1e-6 to 1e-14: JZ's p + 6), at a run-time order otherwise.
constexpr int kMinFixed = 14, kMaxFixed = 26;
template <bool Var>
void BeltTaylorField::Cubic3Dispatch(int order, int n, TaylorRow* c) {
  // Order 0: seed eq. (3.5) at the step start.
  const double sg = sigma_, c1 = mu_->cubic(1), c3 = mu_->cubic(3);
  double* xd = c[1];
  const double s0 = sg * (v_ - xd[0]), w0 = s0 * s0;
  const double mu0 = (mu_->mu_s() + c1 * s0) + c3 * (w0 * s0);
  xd[1] = -c[0][0] - two_beta_ * xd[0] + sg * mu0;
  c[0][1] = xd[0];
  const Order0 o0{s0, w0, two_beta_ + (c1 + w0 * (3 * c3))};
  using Fn = void (BeltTaylorField::*)(int, int, TaylorRow*, const Order0&);
  static constexpr Fn kFixed[] = {
      &BeltTaylorField::Cubic3<Var, 14>, &BeltTaylorField::Cubic3<Var, 15>,
      &BeltTaylorField::Cubic3<Var, 16>, &BeltTaylorField::Cubic3<Var, 17>,
      &BeltTaylorField::Cubic3<Var, 18>, &BeltTaylorField::Cubic3<Var, 19>,
      &BeltTaylorField::Cubic3<Var, 20>, &BeltTaylorField::Cubic3<Var, 21>,
      &BeltTaylorField::Cubic3<Var, 22>, &BeltTaylorField::Cubic3<Var, 23>,
      &BeltTaylorField::Cubic3<Var, 24>, &BeltTaylorField::Cubic3<Var, 25>,
      &BeltTaylorField::Cubic3<Var, 26>};
  static_assert(sizeof kFixed / sizeof kFixed[0] == kMaxFixed - kMinFixed + 1);
  if (order >= kMinFixed && order <= kMaxFixed)
    return (this->*kFixed[order - kMinFixed])(order, n, c, o0);
  Cubic3<Var, 0>(order, n, c, o0);
}

void BeltTaylorField::Coefficients(int order, int n, TaylorRow* c) {
  const bool var = n >= 6;
  if (cubic3_ && !(n == 8 && kind_ == ParamKind::kAffine))
    return var ? Cubic3Dispatch<true>(order, n, c) : Cubic3Dispatch<false>(order, n, c);
  switch (law_) {
    case LawKind::kCubic:
      return var ? Recurrences<LawKind::kCubic, true>(order, n, c)
                 : Recurrences<LawKind::kCubic, false>(order, n, c);
    case LawKind::kCoulomb:
      return var ? Recurrences<LawKind::kCoulomb, true>(order, n, c)
                 : Recurrences<LawKind::kCoulomb, false>(order, n, c);
    case LawKind::kStribeck:
      return var ? Recurrences<LawKind::kStribeck, true>(order, n, c)
                 : Recurrences<LawKind::kStribeck, false>(order, n, c);
    case LawKind::kLeine:
      return var ? Recurrences<LawKind::kLeine, true>(order, n, c)
                 : Recurrences<LawKind::kLeine, false>(order, n, c);
  }
}

}  // namespace

std::unique_ptr<TaylorField> Model::MakeTaylorField(
    const std::optional<ParameterAxis>& parameter) const {
  return std::make_unique<BeltTaylorField>(parameter);
}

}  // namespace stickslip
