// The Taylor recurrences of the forced oscillator's slip fields
// (forced_taylor.hpp gives the equations).
#include "forced_taylor.hpp"

#include <algorithm>
#include <cmath>

namespace stickslip::forced_detail {
namespace {
constexpr Reciprocals<kMaxOrder> kInverse;
}  // namespace

template <LawKind L, bool Var>
void SlipSeries::Recur() {
  const double v = m_.v(), two_beta = 2 * m_.beta(), a = m_.force(), w = m_.omega();
  double* s = s_.c();
  double* cc = cc_.c();
  double* co = cos_.c();
  double* si = sin_.c();
  double* x = c_[0];
  double* xd = c_[1];
  // MuSeries::Old(k) sums products of s_0..s_{k-1}: s_k and later must be 0.
  for (int k = 0; k < order_ + kPad; ++k) s[k] = 0;
  co[0] = std::cos(w * t0_);
  si[0] = std::sin(w * t0_);
  mu_.Begin<L>(order_);
  double damp = 0;  // 2 beta + mu'(s_0)
  for (int k = 0; k < order_; ++k) {
    mu_.Old<L, Var>(k, s);
    const double inv = kInverse.r[k];
    if (k > 0) {
      // mu_k = alpha_k + mu'(s_0) s_k with s_k = -sigma x'_k (MuSeries::Alpha):
      // x'_{k+1} without waiting for the law's series at order k (the chain
      // from x'_k is a multiply-add; as in belt_taylor.cpp).
      const double sigma_alpha = mu_.Alpha<L>(k, sigma_);
      xd[k + 1] = ((sigma_alpha - x[k]) - damp * xd[k] + a * co[k]) * inv;
    }
    s[k] = sigma_ * ((k == 0 ? v : 0.0) - xd[k]);
    double dmu = 0;
    const double muk = mu_.New<L, Var>(k, s, &dmu);
    x[k + 1] = xd[k] * inv;
    if (k == 0) {
      xd[1] = -x[0] - two_beta * xd[0] + sigma_ * muk + a * co[0];
      damp = two_beta + mu_.slope();
    }
    co[k + 1] = -w * si[k] * inv;
    si[k + 1] = w * co[k] * inv;
    if constexpr (Var) {
      cc[k] = (k == 0 ? -two_beta : 0.0) - dmu;
      PhiColumnsNext(c_[2], c_[3], c_[4], c_[5], cc, k, inv);
    }
  }
}

void SlipSeries::Expand(Mode mode, double t0, const double* z, bool variational) {
  n_ = variational ? 6 : 2;
  sigma_ = mode == Mode::kSlipBelow ? 1 : -1;
  t0_ = t0;
  double z0 = 0;
  for (int i = 0; i < n_; ++i) {
    c_[i][0] = z[i];
    z0 = std::max(z0, std::abs(z[i]));
  }
  const bool relative = rtol_ * z0 > atol_;
  order_ = relative ? order_rel_ : order_abs_;
  log_eps_ = relative ? log_rel_ : log_abs_;
  // Cauchy() reads kPad entries past k: finite from the last step or 0.
  switch (m_.friction().law()) {
    case LawKind::kCubic:
      return variational ? Recur<LawKind::kCubic, true>() : Recur<LawKind::kCubic, false>();
    case LawKind::kCoulomb:
      return variational ? Recur<LawKind::kCoulomb, true>() : Recur<LawKind::kCoulomb, false>();
    case LawKind::kStribeck:
      return variational ? Recur<LawKind::kStribeck, true>() : Recur<LawKind::kStribeck, false>();
    case LawKind::kLeine:
      return variational ? Recur<LawKind::kLeine, true>() : Recur<LawKind::kLeine, false>();
  }
}

// rho = min over j = p-1, p of (1 / |z_j|)^(1/j), relative to |z_0| when
// rtol |z_0| > atol; h = rho (eps e^-kStepMargin)^(1/(p-1)) (JZ section 3.2:
// at their order p = -ln(eps) / 2 + 1 this is about rho / e^2). The forcing's own
// series (A c_k, A s_k) count too: they drive x' from the next order on.
double SlipSeries::StepSize() const {
  const double a = m_.force();
  auto norm = [&](int k) {
    double mx = std::max(a * std::abs(cos_.c()[k]), a * std::abs(sin_.c()[k]));
    for (int i = 0; i < n_; ++i) mx = std::max(mx, std::abs(c_[i][k]));
    return mx;
  };
  double z0 = norm(0);
  const double log_scale = rtol_ * z0 > atol_ ? std::log(z0) : 0.0;
  const int p = order_;
  const double r1 = (log_scale - std::log(norm(p - 1))) / (p - 1);
  const double r2 = (log_scale - std::log(norm(p))) / p;
  if (!by_work_) return std::exp(std::min(r1, r2) - 2.0 - 0.7 / (p - 1));
  return std::exp(std::min(r1, r2) + (log_eps_ - kStepMargin) / (p - 1));
}

}  // namespace stickslip::forced_detail
