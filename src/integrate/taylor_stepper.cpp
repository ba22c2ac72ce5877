// The Taylor stepper for one slip mode: coefficients of z (and Phi) by
// recurrences, order and step from the tolerance (Jorba & Zou 2005, Exp. Math.
// 14, section 3.2, with heyoka's safety factor, Biscani & Izzo 2021, eq. 10),
// events as the first sign changes of the step polynomials (poly_roots.hpp);
// the step polynomial is the dense output.
#include "integrate/taylor_stepper.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>

#include "integrate/poly_roots.hpp"
#include "stickslip/errors.hpp"
#include "stickslip/model/parameter_axis.hpp"

namespace stickslip {

// Seed eq. (3.5) on one slip branch, x'' = -x - 2 beta x' + sigma mu(s), and
// Phi' = J Phi with J = [0 1; -1 c], c = -2 beta - mu'(s), and the parameter
// column z_p' = J z_p + df/dp: coefficient k + 1 from those up to k.
template <LawKind L, bool Var>
void TaylorStepper::Recurrences(int order) {
  const Model& m = *p_.model;
  const double v = m.v(), two_beta = 2 * m.beta();
  MuSeries& mu = *mu_;
  double* s = s_.c();
  double* cc = cc_.c();
  double* x = c_[0];
  double* xd = c_[1];
  // Zeros in s past the order so far: the sums of products in MuSeries::Old
  // leave out what is new. (c_ and cc only need finite entries there.)
  for (int k = 0; k < order + kPad; ++k) s[k] = 0;
  for (int i = 0; i < n_; ++i) c_[i][0] = yend_[i];
  mu.Begin<L>(order);
  double damp = 0;  // 2 beta + mu'(s_0)
  MuSeries* shifted = Var && n_ == 8 && mu_shifted_ ? &*mu_shifted_ : nullptr;
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
      for (int col = 2; col < n_; col += 2) {
        const double cq = Cauchy(c_[col + 1], cc, k);
        c_[col][k + 1] = c_[col + 1][k] * inv;
        c_[col + 1][k + 1] = (-c_[col][k] + cq) * inv;
      }
      if (n_ == 8) {
        c_[7][k + 1] += ParamTerm(k, muk, muk_shifted, dmu) * inv;
      }
    }
  }
}

// df/dp of seed eq. (3.5) for the parameter column: beta gives (0, -2 x');
// v enters through s = sigma (v - x') only, giving (0, mu'(s)); a law
// parameter mu depends on affinely (mu_s, mu_m, mu_k, k5) gives
// (0, sigma (mu(s; p + dp) - mu(s; p)) / dp), exact for any dp. v_m, v_s and
// delta enter mu non-affinely: no column (InvalidArgument).
void TaylorStepper::ResolveParameter() {
  const ParameterAxis axis(parameter_);
  const Params& q = p_.model->params();
  if (!ParameterColumnSupported(q.law, parameter_))
    throw InvalidArgument("parameter column: '" + parameter_ +
                          "' enters the friction law non-affinely (not supported)");
  mu_shifted_.reset();
  if (parameter_ == "beta") {
    kind_ = ParamKind::kBeta;
  } else if (parameter_ == "v") {
    kind_ = ParamKind::kV;
  } else {
    kind_ = ParamKind::kAffine;
    dp_ = std::max(1.0, std::abs(axis.Get(q)));
    mu_shifted_.emplace(Friction(axis.At(q, axis.Get(q) + dp_)));
  }
}

// Coefficient k of df_2/dp (ResolveParameter), from this step's series; the
// shifted law's coefficient k is computed in the same loop (Recurrences).
double TaylorStepper::ParamTerm(int k, double muk, double muk_shifted, double dmu) const {
  switch (kind_) {
    case ParamKind::kBeta:
      return -2 * c_[1][k];
    case ParamKind::kV:
      return dmu;
    case ParamKind::kAffine:
      return sigma_ * (muk_shifted - muk) / dp_;
  }
  return 0;
}

void TaylorStepper::Coefficients(int order) {
  const bool var = n_ >= 6;
  switch (p_.model->friction().law()) {
    case LawKind::kCubic:
      return var ? Recurrences<LawKind::kCubic, true>(order)
                 : Recurrences<LawKind::kCubic, false>(order);
    case LawKind::kCoulomb:
      return var ? Recurrences<LawKind::kCoulomb, true>(order)
                 : Recurrences<LawKind::kCoulomb, false>(order);
    case LawKind::kStribeck:
      return var ? Recurrences<LawKind::kStribeck, true>(order)
                 : Recurrences<LawKind::kStribeck, false>(order);
    case LawKind::kLeine:
      return var ? Recurrences<LawKind::kLeine, true>(order)
                 : Recurrences<LawKind::kLeine, false>(order);
  }
}

// JZ section 3.2: rho = min over j = p-1, p of (eps / |z_j|)^(1/j), relative to
// |z_0| when rtol |z_0| > atol; h = rho / e^2 exp(-0.7 / (p - 1)). |z_0|
// takes x by SlipProblem::XScale.
double TaylorStepper::StepSize(int order) const {
  auto norm = [&](int k) {
    double m = 0;
    for (int i = 0; i < n_; ++i) m = std::max(m, std::abs(c_[i][k]));
    return m;
  };
  double z0 = p_.XScale(c_[0][0]);
  for (int i = 1; i < n_; ++i) z0 = std::max(z0, std::abs(c_[i][0]));
  const double log_scale = rtol_ * z0 > atol_ ? std::log(z0) : 0.0;
  // min over j of (scale / |z_j|)^(1/j), as logarithms (|z_j| = 0: +inf).
  const double r1 = (log_scale - std::log(norm(order - 1))) / (order - 1);
  const double r2 = (log_scale - std::log(norm(order))) / order;
  return std::exp(std::min(r1, r2) - 2.0 - 0.7 / (order - 1));
}

bool TaylorStepper::NewStep() {
  ta_ = tb_;
  if (tstop_ - ta_ <= Tolerances::StepEndRounding(ta_)) {  // at the stop time to rounding
    order_ = 0;
    for (int i = 0; i < n_; ++i) c_[i][0] = yend_[i];
    tb_ = tstop_;
    return true;
  }
  double z0 = std::max(p_.XScale(yend_[0]), std::abs(yend_[1]));
  if (n_ >= 6)
    for (int i = 2; i < n_; ++i) z0 = std::max(z0, std::abs(yend_[i]));
  order_ = rtol_ * z0 > atol_ ? order_rel_ : order_abs_;
  Coefficients(order_);
  double h = StepSize(order_);
  double probe = 0;  // 0 * c is 0 for finite c and NaN otherwise: one branch
  for (int i = 0; i < n_; ++i)
    for (int k = 0; k <= order_; ++k) probe += 0.0 * c_[i][k];
  if (probe != 0) return Failed("non-finite Taylor coefficients");
  if (std::isnan(h)) return Failed("non-finite step size");
  if (std::isinf(h)) h = Tolerances::kTaylorRestStep;  // higher coefficients all 0: at rest
  h = std::min(h, tstop_ - ta_);
  // Underflow: the step no longer moves t (fast fields take tiny steps near
  // t = 0, as CVODE does).
  if (!(h > 0) || ta_ + h == ta_) {
    std::ostringstream os;
    os << "step-size underflow (h = " << h << ")";
    return Failed(os.str());
  }
  ++steps_;
  tb_ = std::min(ta_ + h, tstop_);
  h = tb_ - ta_;  // the step as t sees it
  hp_[0] = 1;
  for (int k = 1; k <= order_; ++k) hp_[k] = hp_[k - 1] * h;
  for (int k = order_ + 1; k <= order_ + 3; ++k) hp_[k] = 0;  // the sums' blocks of four
  Events(h);
  if (tb_ == ta_ + h) {  // not cut at a root: z(tb) = sum_k c_k h^k, in four partial sums
    for (int i = 0; i < n_; ++i) {
      double s0 = 0, s1 = 0, s2 = 0, s3 = 0;
      for (int k = 0; k <= order_; k += 4) {  // past the order: finite c_, zero hp_
        s0 += c_[i][k] * hp_[k];
        s1 += c_[i][k + 1] * hp_[k + 1];
        s2 += c_[i][k + 2] * hp_[k + 2];
        s3 += c_[i][k + 3] * hp_[k + 3];
      }
      yend_[i] = (s0 + s1) + (s2 + s3);
    }
  } else {
    Evaluate(tb_ - ta_, yend_);
  }
  return true;
}

StepOutcome TaylorStepper::Advance(double tout, double* t) {
  error_.clear();
  long taken = 0;
  for (;;) {
    if (tout <= tb_ && !(pending_ && tout >= tb_)) {  // dense output inside this step
      t_ = std::max(std::min(tout, tb_), t_);
      Evaluate(t_ - ta_, y_);
      *t = t_;
      return StepOutcome::kReached;
    }
    if (pending_) {
      pending_ = false;
      t_ = tb_;
      std::copy(yend_, yend_ + n_, y_);
      *t = t_;
      return StepOutcome::kRoot;
    }
    if (tb_ >= tstop_) {
      t_ = tb_;
      std::copy(yend_, yend_ + n_, y_);
      *t = t_;
      return StepOutcome::kReached;
    }
    if (taken >= max_steps_) {
      std::ostringstream os;
      os << "too many steps (" << max_steps_ << ") before t = " << tout;
      t_ = tb_;
      std::copy(yend_, yend_ + n_, y_);
      *t = t_;
      error_ = os.str();
      return StepOutcome::kTooMuchWork;
    }
    if (!NewStep()) {
      t_ = tb_ = ta_;
      std::copy(yend_, yend_ + n_, y_);
      *t = t_;
      return StepOutcome::kFailed;
    }
    // max_steps counts from the last root, passed or returned (as when every
    // root returned, and as CVODE counts between returns).
    taken = passed_root_ ? 0 : taken + 1;
    if (p_.cancel && (*p_.cancel)()) {
      pending_ = false;
      tb_ = ta_;
      Evaluate(0.0, yend_);
      t_ = ta_;
      std::copy(yend_, yend_ + n_, y_);
      *t = t_;
      return StepOutcome::kCancelled;
    }
  }
}

std::unique_ptr<Stepper> MakeTaylorStepper(const FlowOptions& options, bool variational,
                                           const std::string& parameter) {
  return std::make_unique<TaylorStepper>(options, variational, parameter);
}

}  // namespace stickslip
