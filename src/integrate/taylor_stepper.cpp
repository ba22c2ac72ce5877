// The Taylor stepper for one slip mode: coefficients of z (and Phi) by
// recurrences, order and step from the tolerance (Jorba & Zou 2005, Exp. Math.
// 14, section 3.2, with heyoka's safety factor, Biscani & Izzo 2021, eq. 10),
// events as the first sign changes of the step polynomials (poly_roots.hpp);
// the step polynomial is the dense output.
#include "integrate/taylor_stepper.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "integrate/poly_roots.hpp"

namespace stickslip {

// JZ section 3.2: rho = min over j = p-1, p of (eps / |z_j|)^(1/j), relative to
// |z_0| when rtol |z_0| > atol; h = rho / e^2 exp(-0.7 / (p - 1)). |z_0|
// takes x by SlipProblem::XScale. At an order q above JZ's p (jz_order),
// rho from z_{q-1}, z_q and the step that keeps their error per step,
// (h / rho)^(q+1) = (e^-2 exp(-0.7 / (p - 1)))^(p+1).
double TaylorStepper::StepSize(int order, int jz_order) const {
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
  if (order == jz_order) return std::exp(std::min(r1, r2) - 2.0 - 0.7 / (order - 1));
  const int p = jz_order;
  return std::exp(std::min(r1, r2) - (2.0 + 0.7 / (p - 1)) * (p + 1) / (order + 1));
}

inline bool TaylorStepper::FiniteCoefficients() const {
  // 0 * c is 0 for finite c and NaN otherwise: one branch (two sums, not one chain).
  double probe0 = 0, probe1 = 0;
  for (int i = 0; i < n_; ++i) {
    int k = 0;
    for (; k + 1 <= order_; k += 2) probe0 += 0.0 * c_[i][k], probe1 += 0.0 * c_[i][k + 1];
    if (k == order_) probe0 += 0.0 * c_[i][k];
  }
  return probe0 + probe1 == 0;
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
  const int jz_order = rtol_ * z0 > atol_ ? order_rel_ : order_abs_;
  order_ = std::min(kTaylorMaxOrder, jz_order + extra_order_);
  Coefficients(order_);
  // The extra orders overflow on a stiff field (v_m 1e-6): JZ's order then,
  // the entries past it finite again (NewStep's sums run past the order).
  if (!FiniteCoefficients()) {
    if (order_ == jz_order) return Failed("non-finite Taylor coefficients");
    for (int i = 0; i < n_; ++i) std::fill(c_[i] + jz_order + 1, c_[i] + kTaylorRowSize, 0.0);
    Coefficients(order_ = jz_order);
    if (!FiniteCoefficients()) return Failed("non-finite Taylor coefficients");
    ++orders_.fallbacks;
  }
  double h = StepSize(order_, jz_order);
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
  ++orders_.steps;
  orders_.sum += order_;
  orders_.min = std::min(orders_.min, order_);
  orders_.max = std::max(orders_.max, order_);
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
                                           const std::optional<ParameterAxis>& parameter) {
  return std::make_unique<TaylorStepper>(options, variational, parameter);
}

}  // namespace stickslip
