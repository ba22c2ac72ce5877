// The Taylor stepper for one mode: coefficients of every row by the system's
// recurrences, order and step from the tolerance (Jorba & Zou 2005, Exp.
// Math. 14, section 3.2, with heyoka's safety factor, Biscani & Izzo 2021,
// eq. 10), events as the first sign changes of the step polynomials
// (poly_roots.hpp); the step polynomial is the dense output.
#include "integrate/taylor_stepper.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace stickslip {

void TaylorStepper::Reset(const SegmentProblem& problem, double t0, const double* y0) {
  // The same mode, events and values as at the last Reset: only a restart.
  const bool same = problem.setup >= 0 && problem.setup == setup_ && &problem == p_ &&
                    problem.system == bound_system_ && problem.system_epoch == bound_epoch_ &&
                    !rows_dirty_;
  p_ = &problem;
  if (!same) Setup(problem);
  std::copy(y0, y0 + m_, yend_.begin());
  std::copy(y0, y0 + m_, y_.begin());
  // No step yet: the "step" [t0, t0] is the start itself (dense output there).
  order_ = 0;
  for (int i = 0; i < m_; ++i) rows_[static_cast<size_t>(i) * kTaylorRowSize] = y0[i];
  ta_ = tb_ = t_ = t0_ = t0;
  tstop_ = INFINITY;
  orders_ = TaylorOrders();
  orders_.min = kTaylorMaxOrder;
  pending_ = passed_root_ = false;
  fresh_segment_ = true;
  surface_scale_ = 1;
  for (int i = 0; i < layout_.tangent; ++i) surface_scale_ += std::abs(y0[i]);
  for (int i = 0; i < nf_; ++i) state_[i] = kFresh, sign_[i] = 1, rf_[i] = 0;
}

void TaylorStepper::Setup(const SegmentProblem& problem) {
  setup_ = -1;  // the key last: a Setup cut short by an exception is not kept
  // The system's recurrences for this mode (taylor_field.hpp); Bind refuses
  // a system of another type.
  // The same system and values in another mode: BindMode, if the field can.
  const bool same = field_ && problem.system_epoch >= 0 && problem.system == bound_system_ &&
                    problem.system_epoch == bound_epoch_;
  const bool bound = same && (problem.mode == bound_mode_ || field_->BindMode(problem.mode));
  if (!bound && (!field_ || !field_->Bind(*problem.system, problem.mode))) {
    TaylorRequest rq;
    rq.variational = variational_;
    rq.parameter = parameter_;
    field_ = problem.system->MakeTaylorField(rq);
    field_->Bind(*problem.system, problem.mode);
  }
  bound_system_ = problem.system, bound_epoch_ = problem.system_epoch, bound_mode_ = problem.mode;
  const bool in_steps = problem.Events().AnyPassing();  // roots inside steps
  extra_rel_ = field_->ExtraOrder(rtol_, in_steps);
  extra_abs_ = field_->ExtraOrder(atol_, in_steps);
  layout_ = problem.layout;
  layout_.aux = field_->AuxRows();
  m_ = layout_.aux_first();
  rows_n_ = layout_.rows();
  // Entries past a step's order must only be finite: the last segment's
  // are, so the rows are cleared only when they grow or a step failed.
  const size_t cells = static_cast<size_t>(rows_n_) * kTaylorRowSize;
  if (rows_.size() < cells || rows_dirty_) rows_.assign(std::max(cells, rows_.size()), 0.0);
  rows_dirty_ = false;
  const int n = layout_.n;
  clock_first_ = layout_.tangent;
  clock_last_ = n;
  col_clock_first_ = layout_.column ? layout_.param() + layout_.tangent : m_;
  col_clock_last_ = layout_.column ? layout_.param() + n : m_;
  const int nf = nf_ = problem.Events().functions();
  if (n > sized_n_ || m_ > sized_m_ || nf > sized_nf_) Grow(n, nf);
  for (int i = 0; i < n; ++i) center_[i] = field_->ScaleCenter(i);
  setup_ = problem.setup;
}

// Buffers only grow: a mode's segment after another's of fewer rows or
// events reuses them (entries past m_ and nf_ are not read).
void TaylorStepper::Grow(int n, int nf) {
  sized_n_ = std::max(sized_n_, n), sized_m_ = std::max(sized_m_, m_);
  sized_nf_ = std::max(sized_nf_, nf);
  AtLeast(center_, sized_n_);
  AtLeast(yend_, sized_m_);
  AtLeast(y_, sized_m_);
  AtLeast(hook_y_, sized_m_);
  AtLeast(state_, sized_nf_);
  AtLeast(sign_, sized_nf_);
  AtLeast(rf_, sized_nf_);
  AtLeast(poly_, static_cast<size_t>(sized_nf_) * kTaylorRowSize);
  AtLeast(tail_, sized_nf_);
  AtLeast(g0_, sized_nf_);
  AtLeast(raw0_, sized_nf_);
}

bool TaylorStepper::Failed(const char* what) {
  rows_dirty_ = true;  // perhaps non-finite coefficients
  std::ostringstream os;
  os << "taylor: " << what << " at t = " << ta_;
  error_ = os.str();
  return false;
}

bool TaylorStepper::StepUnderflow(double h) {
  std::ostringstream os;
  os << "step-size underflow (h = " << h << ")";
  return Failed(os.str().c_str());
}

void TaylorStepper::TooManySteps(double tout) {
  std::ostringstream os;
  os << "too many steps (" << max_steps_ << ") before t = " << tout;
  error_ = os.str();
}

// The size of the state for the choice of rtol or atol (and JZ's scale):
// state components by min(|z|, |z - center|), the rest by |.|; clocks out.
double TaylorStepper::StateScale(const double* y) const {
  double z0 = 0;
  for (int i = 0; i < clock_first_; ++i)
    z0 = std::max(z0, std::min(std::abs(y[i]), std::abs(y[i] - center_[i])));
  for (int i = clock_last_; i < col_clock_first_; ++i) z0 = std::max(z0, std::abs(y[i]));
  for (int i = col_clock_last_; i < m_; ++i) z0 = std::max(z0, std::abs(y[i]));
  return z0;
}

// JZ section 3.2: rho = min over j = p-1, p of (eps / |z_j|)^(1/j), relative to
// |z_0| when rtol |z_0| > atol; h = rho / e^2 exp(-0.7 / (p - 1)). |z_0|
// takes the state by StateScale. At an order q above JZ's p (jz_order),
// rho from z_{q-1}, z_q and the step that keeps their error per step,
// (h / rho)^(q+1) = (e^-2 exp(-0.7 / (p - 1)))^(p+1). Every row counts but
// the clocks' and the column's clock rows (their series are exact).
double TaylorStepper::StepSize(int order, int jz_order, double state_scale) const {
  const TaylorRow* r = c();
  // One pass over the counted rows: the norms of orders order - 1 and order
  // and the scale z0, the integrated rows' StateScale of their order 0 (the
  // state at ta) and the auxiliary rows' (max is exact: the same values as
  // separate passes).
  double z0 = state_scale, n1 = 0, n2 = 0;
  auto norms = [&](const double* ri) {
    n1 = std::max(n1, std::abs(ri[order - 1]));
    n2 = std::max(n2, std::abs(ri[order]));
  };
  for (int i = 0; i < clock_first_; ++i) norms(r[i]);
  for (int i = clock_last_; i < col_clock_first_; ++i) norms(r[i]);
  for (int i = col_clock_last_; i < m_; ++i) norms(r[i]);
  for (int i = std::max(m_, col_clock_last_); i < rows_n_; ++i) {
    z0 = std::max(z0, std::abs(r[i][0]));
    norms(r[i]);
  }
  const double log_scale = rtol_ * z0 > atol_ ? std::log(z0) : 0.0;
  // min over j of (scale / |z_j|)^(1/j), as logarithms (|z_j| = 0: +inf).
  const double r1 = (log_scale - std::log(n1)) / (order - 1);
  const double r2 = (log_scale - std::log(n2)) / order;
  if (order == jz_order) return std::exp(std::min(r1, r2) - 2.0 - 0.7 / (order - 1));
  const int p = jz_order;
  return std::exp(std::min(r1, r2) - (2.0 + 0.7 / (p - 1)) * (p + 1) / (order + 1));
}

// A non-finite coefficient of order j >= 1 makes every later one of its
// chain non-finite (each order is sums and products of the ones before,
// divided by finite constants; 0 * inf and inf - inf are NaN): order 0 and
// the last two orders of each row tell (a constant field, as in stick,
// carries nothing up from order 0).
inline bool TaylorStepper::FiniteCoefficients() const {
  // 0 * c is 0 for finite c and NaN otherwise: one branch.
  const TaylorRow* r = c();
  double probe = 0;
  // The state, Phi and column rows (the auxiliary ones follow from them;
  // anchored clocks are exact).
  const int skip_to = p_->clock_rate ? clock_last_ : clock_first_;
  const int lo = std::max(0, order_ - 1);
  for (int i = 0; i < m_; i = i + 1 == clock_first_ ? skip_to : i + 1)
    probe += 0.0 * r[i][0] + 0.0 * r[i][lo] + 0.0 * r[i][order_];
  return probe == 0;
}

bool TaylorStepper::NewStep() {
  ta_ = tb_;
  TaylorRow* r = c();
  if (tstop_ - ta_ <= Tolerances::StepEndRounding(ta_)) {  // at the stop time to rounding
    order_ = 0;
    for (int i = 0; i < m_; ++i) r[i][0] = yend_[i];
    tb_ = tstop_;
    return true;
  }
  const double z0 = StateScale(yend_.data());
  const bool relative = rtol_ * z0 > atol_;
  const int jz_order = relative ? order_rel_ : order_abs_;
  order_ = std::min(kTaylorMaxOrder, jz_order + (relative ? extra_rel_ : extra_abs_));
  Coefficients(order_);
  // The extra orders overflow on a stiff field (v_m 1e-6): JZ's order then,
  // the entries past it finite again (NewStep's sums run past the order).
  if (!FiniteCoefficients()) {
    if (order_ == jz_order) return Failed("non-finite Taylor coefficients");
    for (int i = 0; i < rows_n_; ++i) std::fill(r[i] + jz_order + 1, r[i] + kTaylorRowSize, 0.0);
    Coefficients(order_ = jz_order);
    if (!FiniteCoefficients()) return Failed("non-finite Taylor coefficients");
    ++orders_.fallbacks;
  }
  double h = StepSize(order_, jz_order, z0);  // r[i][0] = yend_[i]: StateScale's z0
  if (std::isnan(h)) return Failed("non-finite step size");
  if (std::isinf(h)) h = Tolerances::kTaylorRestStep;  // higher coefficients all 0: at rest
  h = std::min(h, tstop_ - ta_);
  // Underflow: the step no longer moves t (fast fields take tiny steps near
  // t = 0, as CVODE does).
  if (!(h > 0) || ta_ + h == ta_) return StepUnderflow(h);
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
  fresh_segment_ = false;
  if (tb_ == ta_ + h) {  // not cut at a root: z(tb) = sum_k c_k h^k, in four partial sums
    const int skip_to = p_->clock_rate ? clock_last_ : clock_first_;  // anchored clocks: Clocks
    for (int i = 0; i < m_; i = i + 1 == clock_first_ ? skip_to : i + 1) {
      double s0 = 0, s1 = 0, s2 = 0, s3 = 0;
      for (int k = 0; k <= order_; k += 4) {  // past the order: finite c_, zero hp_
        s0 += r[i][k] * hp_[k];
        s1 += r[i][k + 1] * hp_[k + 1];
        s2 += r[i][k + 2] * hp_[k + 2];
        s3 += r[i][k + 3] * hp_[k + 3];
      }
      yend_[i] = (s0 + s1) + (s2 + s3);
    }
    Clocks(tb_, yend_.data());
  } else {
    Evaluate(tb_, yend_.data());
  }
  return true;
}

void TaylorStepper::Evaluate(double t, double* out, int rows) const {
  const TaylorRow* r = c();
  const double tau = t - ta_;
  const int m = rows < 0 ? m_ : rows;
  for (int i = 0; i < m; ++i) out[i] = Horner(r[i], order_, tau);
  Clocks(t, out);
}

StepOutcome TaylorStepper::Advance(double tout, double* t) {
  error_.clear();
  long taken = 0;
  auto at = [&](double time, const std::vector<double>& y) {
    t_ = time;
    std::copy(y.begin(), y.begin() + m_, y_.begin());
    *t = t_;
  };
  for (;;) {
    if (tout <= tb_ && !(pending_ && tout >= tb_)) {  // dense output inside this step
      t_ = std::max(std::min(tout, tb_), t_);
      Evaluate(t_, y_.data());
      *t = t_;
      return StepOutcome::kReached;
    }
    if (pending_) {
      pending_ = false;
      fresh_segment_ = true;  // the loop may go on from this root
      at(tb_, yend_);
      return StepOutcome::kRoot;
    }
    if (tb_ >= tstop_) {
      at(tb_, yend_);
      return StepOutcome::kReached;
    }
    if (taken >= max_steps_) {
      at(tb_, yend_);
      TooManySteps(tout);
      return StepOutcome::kTooMuchWork;
    }
    if (!NewStep()) {
      tb_ = ta_;
      at(ta_, yend_);
      return StepOutcome::kFailed;
    }
    // max_steps counts from the last root, passed or returned (as when every
    // root returned, and as CVODE counts between returns).
    taken = passed_root_ ? 0 : taken + 1;
    if (p_->cancel && (*p_->cancel)()) {
      pending_ = false;
      tb_ = ta_;
      Evaluate(ta_, yend_.data());
      at(ta_, yend_);
      return StepOutcome::kCancelled;
    }
    if (!pending_ && p_->on_step.fn) p_->on_step(tb_, yend_.data());
  }
}

std::unique_ptr<Stepper> MakeTaylorStepper(const FlowOptions& options, bool variational,
                                           std::optional<int> parameter) {
  return std::make_unique<TaylorStepper>(options, variational, parameter);
}

}  // namespace stickslip
