// The belt's and the forced oscillator's Taylor recurrences (belt_taylor.hpp):
// seed eq. (3.5) on one slip branch, with the variational equations and the
// parameter column, law by law (MuSeries: the series of mu(s)); the forcing
// A cos(theta) (Jorba & Zou 2005, section 2: c_{k+1} = -Omega s_k / (k+1),
// s_{k+1} = Omega c_k / (k+1)); and the stick mode's rows.
#include "systems/belt/belt_taylor.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>

#include "numerics/tolerances.hpp"
#include "stickslip/errors.hpp"
#include "stickslip/systems/belt/model.hpp"
#include "stickslip/systems/forced/forced.hpp"

namespace stickslip {
namespace {

// The step of order p costs about p^2 + kLinearWork p (the Cauchy sums of
// the law's series and of Phi, against sincos, exp, the event polynomials);
// the order of least work per unit time minimises (p^2 + b p) exp(L / (p -
// 1)), L = -ln(eps) + kStepMargin (Jorba & Zou 2005, section 3.2: cost p^2;
// here with a linear term). b = 25 gives 22 at eps = 1e-12, where the
// measured time per forcing period is least (docs/benchmarks.md).
constexpr double kLinearWork = 25, kStepMargin = 0.7 + 1.4;
int OrderByWork(double eps) {
  const double L = -std::log(eps) + kStepMargin;
  int best = 2;
  double best_work = INFINITY;
  for (int p = 2; p <= kTaylorMaxOrder; ++p) {
    const double work = std::log(p * (p + kLinearWork)) + L / (p - 1);
    if (work < best_work) best_work = work, best = p;
  }
  return best;
}
// JZ (3.8): p = ceil(-ln(eps) / 2 + 1), as the stepper's OrderFor.
int JzOrder(double eps) {
  return std::min(kTaylorMaxOrder, static_cast<int>(std::ceil(-0.5 * std::log(eps) + 1.0)));
}
}  // namespace

bool BeltTaylorField::Bind(const System& s, const ModeSet& m) {
  const Friction* law = nullptr;
  if (const auto* belt = dynamic_cast<const Model*>(&s)) {
    q_ = belt->params();
    law = &belt->friction();
    forced_ = false;
    force_ = omega_ = 0;
  } else if (const auto* f = dynamic_cast<const ForcedBelt*>(&s)) {
    q_ = f->params().base;
    law = &f->friction();
    forced_ = true;
    force_ = f->force();
    omega_ = f->omega();
  } else {
    return false;
  }
  law_ = q_.law;
  v_ = q_.v;
  two_beta_ = 2 * q_.beta;
  mu_s_ = q_.mu_s;
  const Friction& friction = *law;
  // The series' entries are cleared or set before they are read, each step
  // (the leading zeros are never written): a new law only needs a new one.
  if (!mu_ || !mu_->Of(friction)) mu_.emplace(friction);
  cubic3_ = law_ == LawKind::kCubic && mu_->cubic(5) == 0;
  friction_ = &friction;
  mu_v_ = NAN;  // mu(v), read in slip below only (BindMode)
  if (request_.parameter) ResolveParameter();
  return BindMode(m);
}

bool BeltTaylorField::BindMode(const ModeSet& m) {
  stick_ = m[0] == Mode::kStick;
  sigma_ = m[0] == Mode::kSlipBelow ? 1 : -1;
  if (!forced_ && m[0] == Mode::kSlipBelow && std::isnan(mu_v_)) mu_v_ = friction_->Mu(v_);
  x_center_ = !forced_ && m[0] == Mode::kSlipBelow ? mu_v_ : 0.0;
  return true;
}

int BeltTaylorField::ExtraOrder(double eps, bool in_steps) const {
  if (stick_) return 0;
  if (forced_) {
    if (in_steps) return 0;
    // Two tolerances (rtol, atol) a stepper asks for at every segment: cached.
    for (const ExtraCache& e : extra_cache_)
      if (e.eps == eps) return e.extra;
    ExtraCache& e = extra_cache_[next_cache_];
    next_cache_ ^= 1;
    e.eps = eps;
    e.extra = std::max(0, OrderByWork(eps) - JzOrder(eps));
    return e.extra;
  }
  const bool affine_column = request_.parameter && kind_ == ParamKind::kAffine;
  return cubic3_ && !affine_column ? Tolerances::kTaylorExtraOrderCubic : 0;
}

// The forcing's series to order + 1: cos and sin of theta = theta0 + Omega t;
// with ac, as: A cos and A sin to order (the auxiliary rows). The recurrence
// carries c_k, s_k in registers: stores to the rows, which may alias the
// series for all the compiler knows, would make each order reload them.
void BeltTaylorField::Forcing(int order, double theta0, double* ac, double* as) {
  double* co = cos_.c();
  double* si = sin_.c();
  const double w = omega_;
  double ck = std::cos(theta0), sk = std::sin(theta0);
  co[0] = ck;
  si[0] = sk;
  for (int k = 0; k <= order; ++k) {
    const double c1 = -w * sk * kBeltInverse.r[k], s1 = w * ck * kBeltInverse.r[k];
    co[k + 1] = ck = c1;
    si[k + 1] = sk = s1;
  }
  if (!ac) return;
  const double a = force_;
  for (int k = 0; k <= order; ++k) ac[k] = a * co[k], as[k] = a * si[k];
}

// Stick (x' = v): x = x0 + v t, Phi and the column constant (the stick field
// does not depend on the state), theta' = Omega; the auxiliary rows are the
// stick force lambda = x + 2 beta v - A cos(theta) and its limit mu_s.
void BeltTaylorField::Stick(int order, const TaylorLayout& layout, TaylorRow* c) {
  if (forced_) Forcing(order, c[2][0], nullptr, nullptr);
  for (int i = 0; i < layout.aux_first(); ++i) std::fill(c[i] + 1, c[i] + order + 1, 0.0);
  c[0][1] = v_;
  if (forced_) c[2][1] = omega_;
  double* lambda = c[layout.aux_first()];
  double* limit = c[layout.aux_first() + 1];
  for (int k = 0; k <= order; ++k) {
    lambda[k] = c[0][k] - (forced_ ? force_ * cos_.c()[k] : 0.0);
    limit[k] = 0;
  }
  lambda[0] += two_beta_ * v_;
  limit[0] = mu_s_;
  if (!layout.column) return;
  // The column of the stick field (v, 0, Omega): d/dv gives x_p' = 1.
  if (kind_ == ParamKind::kV) c[layout.param()][1] = 1;
  if (forced_) ClockColumn(order, c + layout.param());
}

void BeltTaylorField::ClockColumn(int order, TaylorRow* col) const {
  std::fill(col[2] + 1, col[2] + order + 1, 0.0);
  if (kind_ == ParamKind::kOmega) col[2][1] = 1;
}

void BeltTaylorField::Coefficients(int order, const TaylorLayout& layout, TaylorRow* c) {
  if (stick_) return Stick(order, layout, c);
  const bool var = layout.variational;
  const Rows r{c[0], c[1], var ? c + layout.phi() : nullptr,
               layout.column ? c + layout.param() : nullptr};
  const bool affine_column = layout.column && kind_ == ParamKind::kAffine;
  const bool cubic3 = cubic3_ && !affine_column;
  if (forced_) {
    double* ac = c[layout.aux_first()];
    double* as = c[layout.aux_first() + 1];
    // The seed law's kernel reads the whole forcing series first; the other
    // laws' recurrences carry it along, order by order (ForcingRows after).
    Forcing(cubic3 ? order : -1, c[2][0], cubic3 ? ac : nullptr, cubic3 ? as : nullptr);
    std::fill(c[2] + 1, c[2] + order + 1, 0.0);
    c[2][1] = omega_;
    if (r.col) ClockColumn(order, r.col);
    if (cubic3)
      return var ? Cubic3Dispatch<true, true>(order, r) : Cubic3Dispatch<false, true>(order, r);
    LawRecurrences<true>(order, r, var);
    return ForcingRows(order, ac, as);
  }
  if (cubic3)
    return var ? Cubic3Dispatch<true, false>(order, r) : Cubic3Dispatch<false, false>(order, r);
  LawRecurrences<false>(order, r, var);
}

// The laws' recurrences but the seed law's kernel, by law and variational rows.
template <bool Forced>
void BeltTaylorField::LawRecurrences(int order, const Rows& r, bool var) {
#define STICKSLIP_LAW(L)                                          \
  return !var    ? Recurrences<L, false, Forced, false>(order, r) \
         : r.col ? Recurrences<L, true, Forced, true>(order, r)   \
                 : Recurrences<L, true, Forced, false>(order, r);
  switch (law_) {
    case LawKind::kCubic:
      STICKSLIP_LAW(LawKind::kCubic)
    case LawKind::kCoulomb:
      STICKSLIP_LAW(LawKind::kCoulomb)
    case LawKind::kStribeck:
      STICKSLIP_LAW(LawKind::kStribeck)
    case LawKind::kLeine:
      STICKSLIP_LAW(LawKind::kLeine)
  }
#undef STICKSLIP_LAW
}

// The forcing's last order (Forcing's, to order + 1) and the rows A cos,
// A sin, after Recurrences carried the series to order.
void BeltTaylorField::ForcingRows(int order, double* ac, double* as) {
  double* co = cos_.c();
  double* si = sin_.c();
  const double w = omega_, inv = kBeltInverse.r[order];
  const double c1 = -w * si[order] * inv, s1 = w * co[order] * inv;
  co[order + 1] = c1;
  si[order + 1] = s1;
  const double a = force_;
  for (int k = 0; k <= order; ++k) ac[k] = a * co[k], as[k] = a * si[k];
}

// Seed eq. (3.5) on one slip branch, x'' = -x - 2 beta x' + sigma mu(s)
// (+ A cos theta), and Phi' = J Phi with J = [0 1; -1 c], c = -2 beta -
// mu'(s), and the parameter column z_p' = J z_p + df/dp: coefficient k + 1
// from those up to k.
template <LawKind L, bool Var, bool Forced, bool Col>
void BeltTaylorField::Recurrences(int order, const Rows& r) {
  const double v = v_, two_beta = two_beta_, a = force_;
  MuSeries& mu = *mu_;
  double* s = s_.c();
  double* cc = cc_.c();
  double* co = cos_.c();
  double* si = sin_.c();
  // The forcing's series (Forcing's recurrence, in this loop: its chain runs
  // beside x's), c_k and s_k carried in registers.
  const double w = omega_;
  double ck = Forced ? co[0] : 0.0, sk = Forced ? si[0] : 0.0;
  double* x = r.x;
  double* xd = r.xd;
  // Zeros in s past the order so far: the cubic's sums of products in
  // MuSeries::Old leave out what is new (the other laws' never read s past k).
  // (c and cc only need finite entries there.)
  if constexpr (L == LawKind::kCubic)
    for (int k = 0; k < order + kPad; ++k) s[k] = 0;
  mu.Begin<L>(order);
  double damp = 0;  // 2 beta + mu'(s_0)
  MuSeries* shifted = Col && Var && r.col && mu_shifted_ ? &*mu_shifted_ : nullptr;
  if (shifted) shifted->Begin<L>(order);
  for (int k = 0; k < order; ++k) {
    mu.Old<L, Var>(k, s);
    if (shifted) shifted->Old<L, false>(k, s);
    const double inv = kBeltInverse.r[k];
    if (k > 0) {
      // mu_k = alpha + mu'(s_0) s_k with s_k = -sigma x'_k: x'_{k+1} without
      // waiting for the products of s_k (the chain from x'_k is short).
      const double sigma_alpha = mu.Alpha<L>(k, sigma_);
      if constexpr (Forced)
        xd[k + 1] = ((sigma_alpha - x[k]) - damp * xd[k] + a * (Var ? co[k] : ck)) * inv;
      else
        xd[k + 1] = ((sigma_alpha - x[k]) - damp * xd[k]) * inv;
    }
    s[k] = sigma_ * ((k == 0 ? v : 0.0) - xd[k]);
    double dmu = 0;
    const double muk = mu.New<L, Var>(k, s, &dmu);
    const double muk_shifted = shifted ? shifted->New<L, false>(k, s, nullptr) : 0.0;
    x[k + 1] = xd[k] * inv;
    if (k == 0) {
      if constexpr (Forced)
        xd[1] = -x[0] - two_beta * xd[0] + sigma_ * muk + a * co[0];
      else
        xd[1] = -x[0] - two_beta * xd[0] + sigma_ * muk;
      damp = two_beta + mu.slope();
    }
    if constexpr (Forced && Var) {  // from memory: registers held for the columns' sums
      co[k + 1] = -w * si[k] * inv;
      si[k + 1] = w * co[k] * inv;
    } else if constexpr (Forced) {
      const double c1 = -w * sk * inv, s1 = w * ck * inv;
      co[k + 1] = ck = c1;
      si[k + 1] = sk = s1;
    }
    if constexpr (Var) {
      cc[k] = (k == 0 ? -two_beta : 0.0) - dmu;
      // The forced oscillator's two columns in one pass, as its own
      // recurrences had them (PhiColumnsNext); the belt's one at a time.
      Columns<Forced, L == LawKind::kCoulomb, true, Col>(k, inv, dmu, r);
      if (Col && r.col && kind_ == ParamKind::kAffine)
        r.col[1][k + 1] += ParamTermInline(r, k, muk, muk_shifted, dmu) * inv;
    }
  }
}

// df/dp of seed eq. (3.5) for the parameter column: beta gives (0, -2 x');
// v enters through s = sigma (v - x') only, giving (0, mu'(s)); a law
// parameter mu depends on affinely (mu_s, mu_m, mu_k, k5) gives
// (0, sigma (mu(s; p + dp) - mu(s; p)) / dp), exact for any dp. v_m, v_s and
// delta enter mu non-affinely: no column (InvalidArgument). The forcing's A
// gives (0, cos theta); Omega enters through theta (its column row, t - t0).
void BeltTaylorField::ResolveParameter() {
  const int j = *request_.parameter;
  mu_shifted_.reset();
  if (forced_ && (j == ForcedBelt::kForceIndex || j == ForcedBelt::kOmegaIndex)) {
    kind_ = j == ForcedBelt::kForceIndex ? ParamKind::kForce : ParamKind::kOmega;
    parameter_.reset();
    return;
  }
  if (j < 0 || j >= kBeltParameters)
    throw InvalidArgument("parameter column: no belt parameter " + std::to_string(j));
  const ParameterAxis axis(static_cast<Parameter>(j));
  if (!ParameterColumnSupported(q_.law, axis))
    throw InvalidArgument("parameter column: '" + axis.name() +
                          "' enters the friction law non-affinely (not supported)");
  parameter_ = axis;
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

double BeltTaylorField::ParamTerm(const Rows& r, int k, double muk, double muk_shifted,
                                  double dmu) const {
  return ParamTermInline(r, k, muk, muk_shifted, dmu);
}

std::unique_ptr<TaylorField> Model::MakeTaylorField(const TaylorRequest& request) const {
  return std::make_unique<BeltTaylorField>(request);
}

std::unique_ptr<TaylorField> ForcedBelt::MakeTaylorField(const TaylorRequest& request) const {
  return std::make_unique<BeltTaylorField>(request);
}

}  // namespace stickslip
