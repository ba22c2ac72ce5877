// The mode-coupling model's Taylor recurrences (taylor_field.hpp): with
// N = 1 - gamma y, F = sigma mu(s), s = sigma (v - x') (common/law_series.hpp),
//   x'_{k+1} = (-2 beta x'_k - k11 x_k - k12 y_k + (N F)_k) / (k+1)
// in slip (x' = v in stick), y'_{k+1} = (-2 beta y'_k - k12 x_k - k22 y_k) /
// (k+1) in both; Phi' = J Phi with J's state-dependent entries N F' on x'
// and -k12 - gamma F on y as series.
#include <algorithm>

#include "common/law_series.hpp"
#include "mode_coupling/mode_coupling.hpp"
#include "stickslip/errors.hpp"

namespace stickslip::mode_coupling {

namespace {

using systems::Cauchy;
constexpr int kN = kTaylorRowSize;

class CouplingField final : public TaylorField {
  static constexpr int kExtraOrder = 6;

 public:
  bool Bind(const System& s, const ModeSet& m) override {
    const auto* o = dynamic_cast<const ModeCoupling*>(&s);
    if (!o) return false;
    p_ = o->params();
    law_.Set(p_.law);
    return BindMode(m);
  }
  bool BindMode(const ModeSet& m) override {
    stick_ = m.sticks(0);
    sigma_ = m[0] == Mode::kSlipBelow ? 1.0 : -1.0;
    return true;
  }
  int AuxRows() const override { return stick_ ? 2 : 0; }
  void Coefficients(int order, const TaylorLayout& l, TaylorRow* c) override;
  // Six orders above Jorba & Zou's, as every other field of the one core
  // (the chain's cubic, the model files' tape; its own gain not measured):
  // its products are few.
  int ExtraOrder(double /*eps*/, bool /*in_steps*/) const override { return kExtraOrder; }

 private:
  void Slip(int k, TaylorRow* c);
  void Phi(int k, const TaylorLayout& l, TaylorRow* c);

  CouplingParams p_;
  systems::LawSeries law_;
  bool stick_ = false;
  double sigma_ = 1;
  double n_[kN], f_[kN], nf_[kN], fp_[kN], nfp_[kN];  // N, F, N F, F', N F'
};

void CouplingField::Slip(int k, TaylorRow* c) {
  const double* xd = c[1];
  const double* y = c[2];
  law_.s[k] = sigma_ * ((k == 0 ? p_.v : 0.0) - xd[k]);
  law_.Next(k);
  n_[k] = (k == 0 ? 1.0 : 0.0) - p_.gamma * y[k];
  f_[k] = sigma_ * law_.mu[k];
  fp_[k] = -law_.dmu[k];
  nf_[k] = Cauchy(n_, f_, k);
  nfp_[k] = Cauchy(n_, fp_, k);
}

void CouplingField::Phi(int k, const TaylorLayout& l, TaylorRow* c) {
  const double tb = 2 * p_.beta, inv = 1.0 / (k + 1);
  for (int col = 0; col < l.tangent; ++col) {
    TaylorRow* q = c + l.phi() + col * l.n;
    if (stick_) {
      q[0][k + 1] = q[1][k + 1] = 0;
    } else {
      q[0][k + 1] = q[1][k] * inv;
      q[1][k + 1] = (-tb * q[1][k] - p_.k11 * q[0][k] - p_.k12 * q[2][k] + Cauchy(nfp_, q[1], k) -
                     p_.gamma * Cauchy(f_, q[2], k)) *
                    inv;
    }
    q[2][k + 1] = q[3][k] * inv;
    q[3][k + 1] = (-tb * q[3][k] - p_.k12 * q[0][k] - p_.k22 * q[2][k]) * inv;
  }
}

void CouplingField::Coefficients(int order, const TaylorLayout& l, TaylorRow* c) {
  const double tb = 2 * p_.beta;
  double *x = c[0], *xd = c[1], *y = c[2], *yd = c[3];
  for (int k = 0; k < order; ++k) {
    const double inv = 1.0 / (k + 1);
    if (stick_) {
      x[k + 1] = k == 0 ? p_.v : 0.0;
      xd[k + 1] = 0;
    } else {
      Slip(k, c);
      x[k + 1] = xd[k] * inv;
      xd[k + 1] = (-tb * xd[k] - p_.k11 * x[k] - p_.k12 * y[k] + nf_[k]) * inv;
    }
    y[k + 1] = yd[k] * inv;
    yd[k + 1] = (-tb * yd[k] - p_.k12 * x[k] - p_.k22 * y[k]) * inv;
    if (l.variational) Phi(k, l, c);
  }
  if (!stick_) return;
  double* lam = c[l.aux_first()];
  double* lim = c[l.aux_first() + 1];
  std::fill(lam, lam + kN, 0.0);
  std::fill(lim, lim + kN, 0.0);
  for (int k = 0; k <= order; ++k) {
    lam[k] = p_.k11 * x[k] + p_.k12 * y[k];
    lim[k] = -p_.law.mu_s * p_.gamma * y[k];
  }
  lam[0] += tb * p_.v;
  lim[0] += p_.law.mu_s;
}

}  // namespace

std::unique_ptr<TaylorField> ModeCoupling::MakeTaylorField(const TaylorRequest& request) const {
  if (request.parameter)
    throw InvalidArgument("mode_coupling: no parameter column for " +
                          ParameterName(*request.parameter));
  return std::make_unique<CouplingField>();
}

}  // namespace stickslip::mode_coupling
