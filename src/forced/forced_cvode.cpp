// The forced oscillator's CVODE slip stepper (ForcedOptions::integrator =
// kCvode) for the one event loop: the field of forced.hpp and its variational
// equations Phi' = J Phi as CVODE callbacks (SUNDIALS examples,
// cvRoberts_dns.c), the arrival on x' = v as CVODE's root of g0 = x' - v.
// An independent path for the slip phases, to check the Taylor one against
// (issue 21 item 2); stick phases and switches are the driver's.
#include <cvodes/cvodes.h>

#include <string>

#include "forced_stepper.hpp"
#include "integrate/cvode.hpp"

namespace stickslip::forced_detail {

class ForcedCvodeStepper {
 public:
  ForcedCvodeStepper(const ForcedModel& m, const ForcedOptions& o, bool variational)
      : m_(m),
        cv_(variational ? 6 : 2, o.method, o.rtol, o.atol, o.max_steps, &ForcedCvodeStepper::Rhs, 1,
            &ForcedCvodeStepper::Root, this) {}
  void Reset(const ForcedSlipProblem& p, double t0, const double* y0) {
    p_ = &p;
    cv_.Reinit(t0, y0);
    t0_ = t0;
  }
  void SetStopTime(double t) { cv_.SetStopTime(t); }
  // A start on x' = v (g = 0) is no root: CVODE sets g aside until it leaves 0.
  StepOutcome Advance(double tout, double* t) {
    const int flag = cv_.Advance(tout, t);
    if (flag == CV_ROOT_RETURN) return StepOutcome::kRoot;
    if (flag < 0) {
      error_ = "CVode failed (flag " + std::to_string(flag) + "): " + cv_.last_error();
      return flag == CV_TOO_MUCH_WORK ? StepOutcome::kTooMuchWork : StepOutcome::kFailed;
    }
    if (p_->on_step.fn) p_->on_step(*t, cv_.y());
    return StepOutcome::kReached;
  }
  const double* y() { return cv_.y(); }
  void RootInfo(int* rf) {
    cv_.RootInfo(rf);
    rf[1] = rf[2] = 0;
  }
  double CurrentTime() { return cv_.CurrentTime(); }
  double SegmentStart() const { return t0_; }
  long steps() const { return cv_.steps(); }
  const std::string& last_error() const { return error_; }

 private:
  static int Rhs(double t, N_Vector y, N_Vector ydot, void* data) {
    const auto* self = static_cast<const ForcedCvodeStepper*>(data);
    const Mode mode = self->p_->mode;
    const double* z = N_VGetArrayPointer(y);
    double* f = N_VGetArrayPointer(ydot);
    f[0] = z[1];
    f[1] = self->m_.Acceleration(mode, t, z[0], z[1]);
    if (N_VGetLength(y) == 6) {  // Phi' = J Phi, Phi column-major in z[2..5]
      const Mat2 J = self->m_.Jacobian(mode, t, Vec2(z[0], z[1]));
      for (int c = 0; c < 2; ++c) {
        f[2 + 2 * c] = J(0, 0) * z[2 + 2 * c] + J(0, 1) * z[3 + 2 * c];
        f[3 + 2 * c] = J(1, 0) * z[2 + 2 * c] + J(1, 1) * z[3 + 2 * c];
      }
    }
    return 0;
  }
  static int Root(double /*t*/, N_Vector y, double* g, void* data) {
    g[0] = N_VGetArrayPointer(y)[1] - static_cast<const ForcedCvodeStepper*>(data)->m_.v();
    return 0;
  }
  const ForcedModel& m_;
  Cvode cv_;
  const ForcedSlipProblem* p_ = nullptr;
  double t0_ = 0;
  std::string error_;
};

void ForcedCvodeDeleter::operator()(ForcedCvodeStepper* s) const { delete s; }

ForcedCvodePtr MakeForcedCvode(const ForcedModel& m, const ForcedOptions& o, bool variational) {
  return ForcedCvodePtr(new ForcedCvodeStepper(m, o, variational));
}

SegmentEnd RunSegment(ForcedCvodeStepper& cv, const ForcedSlipProblem& p, double t0,
                      const double* y0, double t_max, long* steps) {
  const SegmentEnd e = RunSegment(cv, p, t0, y0, t_max, SegmentOutput{});
  *steps = cv.steps();
  return e;
}

}  // namespace stickslip::forced_detail
