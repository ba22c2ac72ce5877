// The CVODE stepper: the smooth slip field and its root functions as CVODE
// callbacks (SUNDIALS examples, cvRoberts_dns.c); every flag mapped to a
// StepOutcome here, so the event driver never reads CVODE flags. CVODE's
// own quirk, the refusal of close roots, is handled here by a restart.
#include <algorithm>
#include <sstream>

#include "integrate/cvode.hpp"
#include "integrate/stepper.hpp"

namespace stickslip {
namespace {

class CvodeStepper final : public Stepper {
 public:
  CvodeStepper(const FlowOptions& o, bool variational)
      : cv_(variational ? 6 : 2, o.method, o.rtol, o.atol, o.max_steps,
            variational ? &CvodeStepper::RhsVar : &CvodeStepper::Rhs, kNumRoots,
            &CvodeStepper::Roots, this) {}

  void Reset(const SlipProblem& problem, double t0, const double* y0) override {
    p_ = problem;
    cv_.Reinit(t0, y0);
    t_start_ = t_lo_ = t0;
    restarted_ = false;
    steps_before_ = 0;
  }
  void SetStopTime(double t) override {
    t_stop_ = t;
    cv_.SetStopTime(t);
  }
  StepOutcome Advance(double tout, double* t) override {
    error_.clear();
    cancelled_ = false;
    int flag = cv_.Advance(tout, t);
    while (flag == CV_ILL_INPUT && !cancelled_ && !restarted_ && t_lo_ > t_start_) {
      if (!Restart()) return StepOutcome::kFailed;
      flag = cv_.Advance(tout, t);
    }
    if (cancelled_) return StepOutcome::kCancelled;  // the root function stopped CVode
    if (flag == CV_ROOT_RETURN) {
      // Progress past the start surface: a state to restart from.
      if (*t - t_start_ > Tolerances::EventAtStart(t_start_)) {
        t_lo_ = *t;
        restarted_ = false;
      }
      return StepOutcome::kRoot;
    }
    if (flag == CV_TOO_MUCH_WORK) {
      Describe(flag);
      return StepOutcome::kTooMuchWork;
    }
    if (flag < 0) {
      Describe(flag);
      return StepOutcome::kFailed;
    }
    if (*t < t_stop_) t_lo_ = *t;  // an output time
    return StepOutcome::kReached;
  }
  const double* y() const override { return const_cast<Cvode&>(cv_).y(); }
  void RootInfo(int* roots_found) const override { const_cast<Cvode&>(cv_).RootInfo(roots_found); }
  bool Interpolate(double t, double* out) override { return cv_.Interpolate(t, out); }
  double LastStepStart() override { return cv_.LastStepStart(); }
  double CurrentTime() override { return cv_.CurrentTime(); }
  double SegmentStart() const override { return t_start_; }
  long steps() const override { return steps_before_ + cv_.steps(); }
  int size() const override { return cv_.size(); }
  const std::string& last_error() const override { return error_; }

 private:
  // cvRcheck2 refuses a root function that is exactly zero at the last root
  // and just after it (x' = v and x'' = 0 together at a grazing touch), with
  // CV_ILL_INPUT. Restart at the last root or output time: cvRcheck1 then
  // sets such a function aside. Once per root.
  bool Restart() {
    double buf[6];
    if (!cv_.Interpolate(t_lo_, buf)) {
      error_ = "restarting after a close root: no state at t = " + std::to_string(t_lo_);
      return false;
    }
    steps_before_ += cv_.steps();
    cv_.Reinit(t_lo_, buf);
    cv_.SetStopTime(t_stop_);
    t_start_ = t_lo_;
    restarted_ = true;
    return true;
  }
  void Describe(int flag) {
    std::ostringstream os;
    os << "CVode failed (flag " << flag << "): " << cv_.last_error();
    error_ = os.str();
  }
  static int Rhs(double /*t*/, N_Vector y, N_Vector ydot, void* data) {
    const auto* self = static_cast<const CvodeStepper*>(data);
    const double* z = N_VGetArrayPointer(y);
    double* f = N_VGetArrayPointer(ydot);
    f[0] = z[1];
    f[1] = self->p_.Acceleration(z[0], z[1]);
    return 0;
  }
  // State plus Phi' = J Phi, Phi stored column-major in z[2..5]. An augmented
  // system (rather than CVODES forward sensitivities) because it is one small
  // dense system whose error control covers Phi, with no extra solver set-up.
  static int RhsVar(double t, N_Vector y, N_Vector ydot, void* data) {
    Rhs(t, y, ydot, data);
    const auto* self = static_cast<const CvodeStepper*>(data);
    const double* z = N_VGetArrayPointer(y);
    double* f = N_VGetArrayPointer(ydot);
    const Mat2 J = self->p_.model->Jacobian(self->p_.mode, Vec2(z[0], z[1]));
    for (int col = 0; col < 2; ++col) {
      const double p0 = z[2 + 2 * col], p1 = z[3 + 2 * col];
      f[2 + 2 * col] = J(0, 0) * p0 + J(0, 1) * p1;
      f[3 + 2 * col] = J(1, 0) * p0 + J(1, 1) * p1;
    }
    return 0;
  }
  // Called after every step: the cancel hook is polled here, so one long
  // CVode call (a stiff field) stops within a step (a non-zero return ends it).
  static int Roots(double /*t*/, N_Vector y, double* g, void* data) {
    auto* self = static_cast<CvodeStepper*>(data);
    const SlipProblem& p = self->p_;
    if (p.cancel && (*p.cancel)()) {
      self->cancelled_ = true;
      return 1;
    }
    const double* z = N_VGetArrayPointer(y);
    // x' - v: an exact 0 (a start on the surface, or a tangential touch where
    // x' = v to rounding for a while) counts as still on the mode's side.
    const double rel = z[1] - p.model->v();
    const double bias = Tolerances::kRootZeroBias;
    g[0] = rel != 0 ? rel : (p.mode == Mode::kSlipBelow ? -bias : bias);
    // On steady sliding x'' and x' are both integration noise: they chatter
    // about 0 and round to exactly 0 again and again, which CVODE's root finder
    // refuses next to a root (cvRcheck2). There, and only there, neither is an
    // event. Elsewhere an exact 0 (x'' = x0 - x rounds to 0 near the exit
    // point, where a grazing orbit returns) becomes a tiny bias that moves no root.
    const double acc = p.Acceleration(z[0], z[1]);
    const bool at_rest = p.AtRest(z[0], z[1], acc);
    g[1] = at_rest ? 1.0 : (acc != 0 ? acc : bias);
    g[2] = at_rest ? 1.0 : (z[1] != 0 ? z[1] : bias);
    return 0;
  }

  SlipProblem p_;
  Cvode cv_;
  std::string error_;
  bool cancelled_ = false;
  double t_stop_ = 0;
  double t_start_ = 0, t_lo_ = 0;  // the last (re)start; the last root or output past it
  bool restarted_ = false;         // restarted at t_lo_ already
  long steps_before_ = 0;          // steps before the restart
};

}  // namespace

std::unique_ptr<Stepper> MakeCvodeStepper(const FlowOptions& options, bool variational) {
  return std::make_unique<CvodeStepper>(options, variational);
}

}  // namespace stickslip
