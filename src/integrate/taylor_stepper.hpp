// Private to src/: the Taylor stepper for one mode of any system
// (taylor_stepper.cpp: recurrences, order and step; taylor_events.cpp: the
// roots of the events on each step polynomial).
#pragma once

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "integrate/poly_roots.hpp"
#include "integrate/series.hpp"
#include "integrate/stepper.hpp"
#include "stickslip/system/taylor_field.hpp"

namespace stickslip {

static_assert(kTaylorPad == kPad, "a row's padding is the series' padding");
constexpr Reciprocals<kTaylorMaxOrder> kTaylorInverse;
constexpr Ordinals<kTaylorRowSize + 1> kOrdinals;

// JZ (3.8): order p = ceil(-ln(eps) / 2 + 1).
inline int OrderFor(double eps) {
  return std::min(kTaylorMaxOrder, static_cast<int>(std::ceil(-0.5 * std::log(eps) + 1.0)));
}

class TaylorStepper final : public Stepper {
 public:
  // parameter: also the column dz/dp for that parameter index.
  TaylorStepper(const FlowOptions& o, bool variational, std::optional<int> parameter)
      : rtol_(o.rtol),
        atol_(o.atol),
        max_steps_(o.max_steps),
        variational_(variational || parameter.has_value()),
        order_rel_(OrderFor(o.rtol)),
        order_abs_(OrderFor(o.atol)),
        parameter_(parameter) {}

  void Reset(const SegmentProblem& problem, double t0, const double* y0) override;
  void SetStopTime(double t) override { tstop_ = t; }
  StepOutcome Advance(double tout, double* t) override;
  const double* y() const override { return y_.data(); }
  void RootInfo(int* rf) const override { std::copy(rf_.begin(), rf_.begin() + nf_, rf); }
  double CurrentTime() override { return tb_; }
  double SegmentStart() const override { return t0_; }
  long steps() const override { return orders_.steps; }
  TaylorOrders orders() const override {
    TaylorOrders o = orders_;
    if (o.steps == 0) o.min = 0;  // no steps: no kTaylorMaxOrder sentinel
    return o;
  }
  int size() const override { return m_; }
  const std::string& last_error() const override { return error_; }

 private:
  enum SignState { kFresh, kTracked, kDeflate, kInactive };
  // The roots of one step: the first of a terminal event (rf, first), and
  // the roots passed on the way.
  struct Roots {
    double first = 2;
    int* rf = nullptr;  // one per function
    int nf = 0;
    struct Passed {
      double u;
      int i, direction;
    };
    std::vector<Passed>* passed = nullptr;
    // Returns whether the root stops.
    bool Add(int i, double u, int direction, bool stops) {
      if (!stops) {
        passed->push_back({u, i, direction});
        return false;
      }
      if (u > first) return true;
      if (u < first) std::fill(rf, rf + nf, 0);
      first = u;
      rf[i] = direction;
      return true;
    }
  };
  // tail: sum_{k>=3} |g_k| of gi (the quadratic bound).
  // Function i's roots; base: the polynomial of its shape (EventFunction::
  // base), whose g_0 is replaced by g0_[i].
  void EventRoots(int i, const double* base, int deg, double tail, double h, Roots& roots);
  // The step polynomials (in u = tau / h) of every distinct event function.
  void EventPolynomials(int order);

  TaylorRow* c() { return reinterpret_cast<TaylorRow*>(rows_.data()); }
  const TaylorRow* c() const { return reinterpret_cast<const TaylorRow*>(rows_.data()); }
  bool NewStep();
  bool FiniteCoefficients() const;
  void Coefficients(int order) {
    TaylorRow* r = c();
    for (int i = 0; i < m_; ++i) r[i][0] = yend_[i];
    field_->Coefficients(order, layout_, r);
  }
  // state_scale: StateScale of the state at the step start.
  double StepSize(int order, int jz_order, double state_scale) const;
  double StateScale(const double* y) const;
  void Events(double h);
  // The step polynomial at tau = t - ta (the clocks at t itself).
  // rows: the first rows only (the state's n for an event hook, EventHook).
  // Out of line: one copy for the dense output, a cut step's end and the
  // hooks (the hot code's footprint, docs/benchmarks.md).
  [[gnu::noinline]] void Evaluate(double t, double* out, int rows = -1) const;
  // The clock rows at t, from the problem's rates and offsets.
  [[gnu::noinline]] void Clocks(double t, double* y) const {
    if (!p_->clock_rate) return;  // no anchors: the step polynomial's own
    for (int j = clock_first_; j < clock_last_; ++j)
      y[j] = p_->clock_rate[j - clock_first_] * t + p_->clock_offset[j - clock_first_];
  }
  // The failures, out of line and cold (the step's hot code stays dense).
  [[gnu::cold, gnu::noinline]] bool Failed(const char* what);
  [[gnu::cold, gnu::noinline]] bool StepUnderflow(double h);
  [[gnu::cold, gnu::noinline]] void TooManySteps(double tout);
  // Reset's binding and sizes for a problem of another setup key.
  [[gnu::noinline]] void Setup(const SegmentProblem& problem);
  // Sizes the buffers for n state rows, m_ rows and nf event functions.
  // Out of line: it runs once per shape, not in the segment's hot code.
  [[gnu::noinline]] void Grow(int n, int nf);

  double rtol_, atol_;
  long max_steps_;
  bool variational_;
  int order_rel_, order_abs_;
  int order_ = 0;
  int extra_rel_ = 0, extra_abs_ = 0;  // the field's orders above JZ's (ExtraOrder)
  const SegmentProblem* p_ = nullptr;
  TaylorLayout layout_;
  int m_ = 0;                             // the integrated rows (state, Phi, column)
  int rows_n_ = 0;                        // with the auxiliary rows
  int clock_first_ = 0, clock_last_ = 0;  // clock rows [first, last): out of the step size
  int col_clock_first_ = 0,
      col_clock_last_ = 0;  // the column's clock rows (t - t0 exactly): out too
  // This step's Taylor coefficients, kPad finite entries past the order;
  // the recurrences that fill them (the system's, per mode).
  std::vector<double> rows_;
  bool rows_dirty_ = false;    // a failed step may have left non-finite entries
  double hp_[kTaylorRowSize];  // powers of this step's h
  std::optional<int> parameter_;
  std::unique_ptr<TaylorField> field_;
  // What field_ was bound to last (SegmentProblem::system_epoch).
  const System* bound_system_ = nullptr;
  long bound_epoch_ = -1;
  ModeSet bound_mode_;
  long setup_ = -1;                 // the setup key of the last Setup (SegmentProblem::setup)
  std::vector<double> center_;      // TaylorField::ScaleCenter per state component
  double ta_ = 0, tb_ = 0, t_ = 0;  // step [ta, tb]; t the last time returned
  double t0_ = 0;                   // the last Reset's start
  double tstop_ = INFINITY;
  std::vector<double> yend_, y_;  // state at tb, at t
  // Per event function: sign tracking, sign, this step's roots; per base
  // polynomial: its coefficients and tail.
  int nf_ = 0;  // the segment's event functions (the vectors below may be longer)
  std::vector<SignState> state_;
  std::vector<int> sign_, rf_;
  // g0_: each function's g_0.
  std::vector<double> poly_, tail_, raw0_, g0_;  // raw0_: a base's g_0 before its offset
  std::vector<Roots::Passed> passed_;
  bool pending_ = false;        // a root at tb not yet returned
  bool passed_root_ = false;    // the last step passed a root
  bool fresh_segment_ = false;  // the first step of a segment, or after a root returned
  double surface_scale_ = 1;    // the state's size, for SurfaceRounding
  std::vector<double> hook_y_;
  int sized_n_ = 0, sized_m_ = 0, sized_nf_ = 0;  // what the buffers hold (Grow)
  TaylorOrders orders_;                           // the steps since Reset and their orders
  std::string error_;
};

}  // namespace stickslip
