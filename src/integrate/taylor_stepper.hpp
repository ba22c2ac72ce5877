// Private to src/: the Taylor stepper for one slip mode (taylor_stepper.cpp:
// recurrences, order and step; taylor_events.cpp: the roots of the events on
// each step polynomial).
#pragma once

#include <algorithm>
#include <cmath>
#include <memory>
#include <sstream>
#include <string>

#include "integrate/poly_roots.hpp"
#include "integrate/series.hpp"
#include "integrate/stepper.hpp"
#include "integrate/taylor_field.hpp"

namespace stickslip {

// JZ (3.8): order p = ceil(-ln(eps) / 2 + 1).
inline int OrderFor(double eps) {
  return std::min(kTaylorMaxOrder, static_cast<int>(std::ceil(-0.5 * std::log(eps) + 1.0)));
}

class TaylorStepper final : public Stepper {
 public:
  // parameter: also the column dz/dp for that parameter (then size() is 8).
  TaylorStepper(const FlowOptions& o, bool variational,
                const std::optional<ParameterAxis>& parameter)
      : rtol_(o.rtol),
        atol_(o.atol),
        max_steps_(o.max_steps),
        n_(parameter     ? 8
           : variational ? 6
                         : 2),
        order_rel_(OrderFor(o.rtol)),
        order_abs_(OrderFor(o.atol)),
        parameter_(parameter) {}

  void Reset(const SlipProblem& problem, double t0, const double* y0) override {
    p_ = problem;
    // The model's recurrences for this mode (the seam: system.hpp).
    if (!field_ || !field_->Bind(*p_.model, p_.mode)) {
      field_ = p_.model->MakeTaylorField(parameter_);
      field_->Bind(*p_.model, p_.mode);
    }
    extra_order_ = field_->ExtraOrder();
    for (int i = 0; i < n_; ++i) std::fill(c_[i], c_[i] + kTaylorRowSize, 0.0);
    std::copy(y0, y0 + n_, yend_);
    std::copy(y0, y0 + n_, y_);
    ta_ = tb_ = t_ = t0_ = t0;
    tstop_ = INFINITY;
    orders_ = TaylorOrders();
    orders_.min = kTaylorMaxOrder;
    pending_ = passed_root_ = false;
    for (auto& s : state_) s = kFresh;
  }
  void SetStopTime(double t) override { tstop_ = t; }
  StepOutcome Advance(double tout, double* t) override;
  const double* y() const override { return y_; }
  void RootInfo(int* rf) const override { std::copy(rf_, rf_ + kNumRoots, rf); }
  bool Interpolate(double t, double* out) override {
    const double slack = Tolerances::DenseOutputSlack(t);
    if (!(t >= ta_ - slack && t <= tb_ + slack)) return false;
    Evaluate(t - ta_, out);
    return true;
  }
  double LastStepStart() override { return ta_; }
  double CurrentTime() override { return tb_; }
  double SegmentStart() const override { return t0_; }
  long steps() const override { return orders_.steps; }
  TaylorOrders orders() const override {
    TaylorOrders o = orders_;
    if (o.steps == 0) o.min = 0;  // no steps: no kTaylorMaxOrder sentinel
    return o;
  }
  int size() const override { return n_; }
  const std::string& last_error() const override { return error_; }

 private:
  enum SignState { kFresh, kTracked, kDeflate, kInactive };
  // The roots of one step: the first of a terminal event (rf, first), and
  // the roots passed on the way.
  struct Roots {
    double first = 2;
    int rf[kNumRoots] = {0, 0, 0};
    struct Passed {
      double u;
      int i, direction;
    } passed[2 * kTaylorMaxOrder + 8];
    int n_passed = 0;
    // Returns whether the root stops.
    bool Add(int i, double u, int direction, bool stops) {
      if (!stops) {
        if (n_passed < static_cast<int>(sizeof passed / sizeof passed[0]))
          passed[n_passed++] = {u, i, direction};
        return false;
      }
      if (u > first) return true;
      if (u < first) std::fill(rf, rf + kNumRoots, 0);
      first = u;
      rf[i] = direction;
      return true;
    }
  };
  // tail: sum_{k>=3} |g_k| of gi (the quadratic bound).
  void EventRoots(int i, const double* gi, int deg, double tail, Roots& roots);

  bool NewStep();
  bool FiniteCoefficients() const;
  void Coefficients(int order) {
    for (int i = 0; i < n_; ++i) c_[i][0] = yend_[i];
    field_->Coefficients(order, n_, c_);
  }
  double StepSize(int order, int jz_order) const;
  void Events(double h);
  void Evaluate(double tau, double* out) const {
    for (int i = 0; i < n_; ++i) out[i] = Horner(c_[i], order_, tau);
  }
  bool Failed(const std::string& what) {
    std::ostringstream os;
    os << "taylor: " << what << " at t = " << ta_;
    error_ = os.str();
    return false;
  }

  double rtol_, atol_;
  long max_steps_;
  int n_, order_rel_, order_abs_;
  int order_ = 0;
  int extra_order_ = 0;  // the field's orders above JZ's (TaylorField::ExtraOrder)
  SlipProblem p_;
  // This step's Taylor coefficients, kPad finite entries past the order for
  // Cauchy(); the recurrences that fill them (the model's, per mode).
  TaylorRow c_[8];
  double hp_[kTaylorRowSize];               // powers of this step's h
  std::optional<ParameterAxis> parameter_;  // the parameter column's, if any
  std::unique_ptr<TaylorField> field_;
  double ta_ = 0, tb_ = 0, t_ = 0;  // step [ta, tb]; t the last time returned
  double t0_ = 0;                   // the last Reset's start
  double tstop_ = INFINITY;
  double yend_[8], y_[8];  // state at tb, at t
  SignState state_[kNumRoots];
  int sign_[kNumRoots] = {1, 1, 1};
  bool pending_ = false;      // a root at tb not yet returned
  bool passed_root_ = false;  // the last step passed a root
  int rf_[kNumRoots] = {0, 0, 0};
  TaylorOrders orders_;  // the steps since Reset and their orders
  std::string error_;
};

}  // namespace stickslip
