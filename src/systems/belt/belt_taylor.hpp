// Private to src/systems/: the Taylor recurrences of the belt (seed eq. 3.5)
// and of the forced oscillator (the belt plus A cos(theta), theta' = Omega):
// one field for both, with the variational equations, the parameter column
// and the stick mode's rows (belt_taylor.cpp: laws by MuSeries, stick,
// forcing; belt_cubic.cpp: the seed law's kernel).
#pragma once

#include <optional>

#include "integrate/series.hpp"
#include "numerics/kernel.hpp"
#include "stickslip/system/taylor_field.hpp"
#include "stickslip/systems/belt/parameter_axis.hpp"
#include "stickslip/systems/belt/params.hpp"
#include "systems/belt/mu_series.hpp"

namespace stickslip {

/// 1 / (k + 1) for the belt's Taylor recurrences (x_{k+1} = x'_k / (k + 1)).
inline constexpr Reciprocals<kTaylorMaxOrder> kBeltInverse{};

class BeltTaylorField final : public TaylorField {
 public:
  explicit BeltTaylorField(const TaylorRequest& rq) : request_(rq) {}

  bool Bind(const System& s, const ModeSet& m) override;
  bool BindMode(const ModeSet& m) override;
  int AuxRows() const override { return stick_ ? 2 : (forced_ ? 2 : 0); }
  void Coefficients(int order, const TaylorLayout& layout, TaylorRow* c) override;
  // The seed law's loop (Cubic3) only: the other laws keep JZ's rule (at
  // p + 4 the quintic chart's fold point moved by 1e-10 and a Leine
  // pure-slip amplitude by 1.3e-12; docs/benchmarks.md). The forced
  // oscillator without roots inside steps: the order of least work per
  // unit time (OrderByWork); with them JZ's (their isolation is O(p^2)).
  int ExtraOrder(double eps, bool in_steps) const override;
  double ScaleCenter(int i) const override { return i == 0 ? x_center_ : 0.0; }

  // Rows of one step: x, x', Phi's two columns (p, q pairs), the column.
  struct Rows {
    double* x;
    double* xd;
    TaylorRow* phi;  // 4 rows, or null
    TaylorRow* col;  // 2 rows (forced: 3, with theta's), or null
  };

 private:
  // Col: r.col may be set (false: the column's code is compiled out, and
  // with it the registers it held).
  template <LawKind L, bool Var, bool Forced, bool Col>
  void Recurrences(int order, const Rows& r);
  // Order 0 of the seed law's loop, outside its kernel clones: x'' at the
  // step start exactly as the model's field computes it (no FMA), which the
  // mode switches read.
  struct Order0 {
    double s0, w0, damp;
  };
  template <bool Var, int N, bool Forced>
  STICKSLIP_KERNEL void Cubic3(int order, const Rows& r, const Order0& o0);
  template <bool Var, bool Forced>
  void Cubic3Dispatch(int order, const Rows& r);
  // ConstJ: J constant over the step (coulomb: mu'(s) = 0 in slip), so each
  // sum with cc is its one term cc_0 q_k (the same value: the others are 0).
  template <bool Newest, bool ConstJ = false, bool InlineTerm = false, bool Col = true>
  void Columns(int k, double inv, double dmu, const Rows& r);
  void Stick(int order, const TaylorLayout& layout, TaylorRow* c);
  // theta's column row: d theta / dp, of rate 1 for omega's column, else 0.
  void ClockColumn(int order, TaylorRow* col) const;
  void Forcing(int order, double theta0, double* ac, double* as);
  // The laws but the seed's kernel (with the forcing, Recurrences carries
  // its series; ForcingRows then ends it and fills A cos, A sin).
  template <bool Forced>
  void LawRecurrences(int order, const Rows& r, bool var);
  void ForcingRows(int order, double* ac, double* as);
  void ResolveParameter();
  // Out of line for the seed law's kernel (its x86-64-v3 clone would fuse
  // the inline sums into FMAs: other roundings); inline (InlineTerm) where
  // the baseline code calls it, once per order.
  double ParamTerm(const Rows& r, int k, double muk, double muk_shifted, double dmu) const;
  double ParamTermInline(const Rows& r, int k, double muk, double muk_shifted, double dmu) const;

  TaylorRequest request_;
  Params q_;
  LawKind law_ = LawKind::kCubic;
  double v_ = 0, two_beta_ = 0;
  int sigma_ = 1;        // F = sigma mu(s), s = sigma (v - x')
  bool stick_ = false;   // the stick mode: x' = v
  bool cubic3_ = false;  // the cubic law without the quintic term: Cubic3
  bool forced_ = false;  // + A cos(theta), theta' = Omega (state row 2)
  double force_ = 0, omega_ = 0, mu_s_ = 0;
  double x_center_ = 0;  // steady sliding's x in slip below (ScaleCenter)
  // The bound system's law and mu(v) (x_center_ in slip below; NaN: not yet).
  const Friction* friction_ = nullptr;
  double mu_v_ = 0;
  // ExtraOrder of the forced field's last two tolerances (it depends on eps only).
  struct ExtraCache {
    double eps = NAN;
    int extra = 0;
  };
  mutable ExtraCache extra_cache_[2];
  mutable int next_cache_ = 0;
  // The series of s = sigma (v - x'), of -2 beta - mu'(s), of cos, sin theta.
  Series<kTaylorMaxOrder + 1> s_, cc_, cos_, sin_;
  std::optional<MuSeries> mu_;
  // The parameter column dz/dp: which term df/dp carries.
  enum class ParamKind { kBeta, kV, kAffine, kForce, kOmega };
  std::optional<ParameterAxis> parameter_;
  ParamKind kind_ = ParamKind::kBeta;
  std::optional<MuSeries> mu_shifted_;  // kAffine: the law at p + dp_
  double dp_ = 1;
};

// Coefficient k of df_2/dp (ResolveParameter), from this step's series; the
// shifted law's coefficient k is computed in the same loop (Recurrences).
// Inline: a call per order cost 4 % of a Den Hartog run (docs/benchmarks.md).
__attribute__((always_inline)) inline double BeltTaylorField::ParamTermInline(const Rows& r, int k,
                                                                              double muk,
                                                                              double muk_shifted,
                                                                              double dmu) const {
  switch (kind_) {
    case ParamKind::kBeta:
      return -2 * r.xd[k];
    case ParamKind::kV:
      return dmu;
    case ParamKind::kAffine:
      return sigma_ * (muk_shifted - muk) / dp_;
    case ParamKind::kForce:  // d(A cos theta)/dA
      return cos_.c()[k];
    case ParamKind::kOmega: {  // -A sin(theta) d theta / d Omega, a linear series
      const double* th = r.col[2];
      return -force_ * (sin_.c()[k] * th[0] + (k > 0 ? sin_.c()[k - 1] * th[1] : 0.0));
    }
  }
  return 0;
}

// Phi' = J Phi and the parameter column (beta, v) at order k + 1, cc_ set to k.
template <bool Newest, bool ConstJ, bool InlineTerm, bool Col>
__attribute__((always_inline)) inline void BeltTaylorField::Columns(int k, double inv, double dmu,
                                                                    const Rows& r) {
  const double* cc = cc_.c();
  TaylorRow* phi = r.phi;
  if constexpr (ConstJ) {
    for (int col = 0; col < 4; col += 2) {
      phi[col][k + 1] = phi[col + 1][k] * inv;
      phi[col + 1][k + 1] = (-phi[col][k] + phi[col + 1][k] * cc[0]) * inv;
    }
  } else if constexpr (Newest) {
    // Cubic3: the newest terms (j = 0 and k) last, as there; Phi's two
    // columns against cc in one pass (the same sums as one at a time).
    PhiColumnsNext(phi[0], phi[1], phi[2], phi[3], cc, k, inv);
  } else {
    for (int col = 0; col < 4; col += 2) {
      phi[col][k + 1] = phi[col + 1][k] * inv;
      phi[col + 1][k + 1] = (-phi[col][k] + Cauchy(phi[col + 1], cc, k)) * inv;
    }
  }
  if (!Col || !r.col) return;
  const double* p = r.col[1];
  const double cq = ConstJ    ? p[k] * cc[0]
                    : !Newest ? Cauchy(p, cc, k)
                    : k == 0  ? p[0] * cc[0]
                              : CauchyRange(p, cc, 1, k - 1, k) + (p[0] * cc[k] + p[k] * cc[0]);
  r.col[0][k + 1] = r.col[1][k] * inv;
  r.col[1][k + 1] = (-r.col[0][k] + cq) * inv;
  if (kind_ != ParamKind::kAffine)
    r.col[1][k + 1] +=
        (InlineTerm ? ParamTermInline(r, k, 0, 0, dmu) : ParamTerm(r, k, 0, 0, dmu)) * inv;
}

}  // namespace stickslip
