// The chain's Taylor recurrences (taylor_field.hpp; Jorba & Zou 2005): per
// block x_{k+1} = x'_k / (k+1) and
//   x'_{k+1} = (-c x'_k - (k_i + kc deg_i) x_k + kc sum_j x_j,k + F_k) / (m (k+1))
// in slip, where F = sigma mu(s), s = sigma (v - x'); x' = v in stick. The
// law's series mu(s(t)) and mu'(s(t)) come from s's by the usual rules
// (common/law_series.hpp).
#include <algorithm>
#include <cmath>
#include <vector>

#include "chain/chain.hpp"
#include "common/law_series.hpp"
#include "stickslip/errors.hpp"
#include "stickslip/system/taylor_field.hpp"

namespace stickslip::chain {

namespace {

using systems::Cauchy;
using systems::LawSeries;
constexpr int kN = kTaylorRowSize;

class ChainField final : public TaylorField {
 public:
  explicit ChainField(const TaylorRequest& rq) : request_(rq) {}

  bool Bind(const System& s, const ModeSet& m) override {
    const auto* c = dynamic_cast<const Chain*>(&s);
    if (!c) return false;
    chain_ = c;
    const int n = c->blocks();
    laws_.resize(n);
    inverse_mass_.resize(n);
    cubic_ = true;
    for (int i = 0; i < n; ++i) {
      laws_[i].Set(c->params().blocks[i].law);
      inverse_mass_[i] = 1 / c->params().blocks[i].m;
      cubic_ = cubic_ && laws_[i].law == LawKind::kCubic;
    }
    rest_.resize(n);
    has_rest_ = c->RestPositions(rest_.data());
    return BindMode(m);
  }
  // Every block sliding below: the step measures x_i about its rest position.
  bool BindMode(const ModeSet& m) override {
    const int n = chain_->blocks();
    mode_ = m;
    sticking_ = m.Sticking();
    center_.assign(2 * n, 0.0);
    bool below = has_rest_;
    for (int i = 0; i < n && below; ++i) below = m[i] == Mode::kSlipBelow;
    if (below)
      for (int i = 0; i < n; ++i) center_[2 * i] = rest_[i];
    return true;
  }
  int AuxRows() const override { return 2 * sticking_; }
  double ScaleCenter(int i) const override {
    return i < static_cast<int>(center_.size()) ? center_[i] : 0.0;
  }
  void Coefficients(int order, const TaylorLayout& l, TaylorRow* c) override;
  // Six orders above Jorba & Zou's where every block's law is cubic, as the
  // belt's (BeltTaylorField): 14 % less time per two-block orbit
  // (bench/chain_orbit_bench, rtol 1e-12; 3 and 9 orders gained less).
  int ExtraOrder(double /*eps*/, bool /*in_steps*/) const override {
    return cubic_ ? kCubicExtraOrder : 0;
  }

 private:
  static constexpr int kCubicExtraOrder = 6;
  // Coefficient k + 1 of block i's two state rows (and the law's series).
  void StateNext(int i, int k, TaylorRow* c);
  void PhiNext(int i, int k, const TaylorLayout& l, TaylorRow* c);
  void Aux(int order, const TaylorLayout& l, TaylorRow* c);

  TaylorRequest request_;
  const Chain* chain_ = nullptr;
  ModeSet mode_;
  int sticking_ = 0;
  bool cubic_ = false;
  bool has_rest_ = false;  // rest_ holds the rest positions (Chain::RestPositions)
  std::vector<LawSeries> laws_;
  std::vector<double> center_, rest_, inverse_mass_;
};

void ChainField::StateNext(int i, int k, TaylorRow* c) {
  const ChainParams& p = chain_->params();
  const Block& b = p.blocks[i];
  double* x = c[2 * i];
  double* xd = c[2 * i + 1];
  if (mode_.sticks(i)) {
    x[k + 1] = k == 0 ? p.v : 0.0;
    xd[k + 1] = 0;
    return;
  }
  const double sigma = mode_[i] == Mode::kSlipBelow ? 1.0 : -1.0;
  LawSeries& law = laws_[i];
  law.s[k] = sigma * ((k == 0 ? p.v : 0.0) - xd[k]);
  law.Next(k);
  double spring = b.k * x[k];
  if (i > 0) spring += p.kc * (x[k] - c[2 * i - 2][k]);
  if (i + 1 < chain_->blocks()) spring += p.kc * (x[k] - c[2 * i + 2][k]);
  const double inv = systems::kReciprocals.r[k];
  x[k + 1] = xd[k] * inv;
  xd[k + 1] = (-b.c * xd[k] - spring + sigma * law.mu[k]) * (inverse_mass_[i] * inv);
}

// Phi' = J Phi, column by column: J's slip row of block i has
// -c - mu'(s) on x_i' (a series), -(k_i + kc deg) on x_i, kc on x_j.
void ChainField::PhiNext(int i, int k, const TaylorLayout& l, TaylorRow* c) {
  const ChainParams& p = chain_->params();
  const Block& b = p.blocks[i];
  const int n = l.n;
  const LawSeries& law = laws_[i];
  const double inv = systems::kReciprocals.r[k], inv_m = inverse_mass_[i] * inv;
  for (int col = 0; col < l.tangent; ++col) {
    TaylorRow* phi = c + l.phi() + col * n;
    double* px = phi[2 * i];
    double* pv = phi[2 * i + 1];
    if (mode_.sticks(i)) {
      px[k + 1] = pv[k + 1] = 0;
      continue;
    }
    double spring = b.k * px[k];
    if (i > 0) spring += p.kc * (px[k] - phi[2 * i - 2][k]);
    if (i + 1 < chain_->blocks()) spring += p.kc * (px[k] - phi[2 * i + 2][k]);
    px[k + 1] = pv[k] * inv;
    pv[k + 1] = (-b.c * pv[k] - Cauchy(law.dmu, pv, k) - spring) * inv_m;
  }
}

// For each sticking block in order: its holding force and its limit.
void ChainField::Aux(int order, const TaylorLayout& l, TaylorRow* c) {
  const ChainParams& p = chain_->params();
  int row = l.aux_first();
  for (int i = 0; i < chain_->blocks(); ++i) {
    if (!mode_.sticks(i)) continue;
    double* lam = c[row];
    double* lim = c[row + 1];
    std::fill(lam, lam + kN, 0.0);
    std::fill(lim, lim + kN, 0.0);
    const Block& b = p.blocks[i];
    for (int k = 0; k <= order; ++k) {
      double f = b.k * c[2 * i][k];
      if (i > 0) f += p.kc * (c[2 * i][k] - c[2 * i - 2][k]);
      if (i + 1 < chain_->blocks()) f += p.kc * (c[2 * i][k] - c[2 * i + 2][k]);
      lam[k] = f;
    }
    lam[0] += b.c * p.v;
    lim[0] = b.law.mu_s;
    row += 2;
  }
}

void ChainField::Coefficients(int order, const TaylorLayout& l, TaylorRow* c) {
  const int blocks = chain_->blocks();
  for (int k = 0; k < order; ++k) {
    for (int i = 0; i < blocks; ++i) StateNext(i, k, c);
    if (l.variational)
      for (int i = 0; i < blocks; ++i) PhiNext(i, k, l, c);
  }
  Aux(order, l, c);
}

}  // namespace

std::unique_ptr<TaylorField> Chain::MakeTaylorField(const TaylorRequest& request) const {
  if (request.parameter)
    throw InvalidArgument("chain: no parameter column for " + ParameterName(*request.parameter));
  return std::make_unique<ChainField>(request);
}

}  // namespace stickslip::chain
