// Slip phases of the forced flow by CVODE (ForcedOptions::integrator =
// kCvode): the field of forced.hpp and its variational equations Phi' = J Phi
// as CVODE callbacks (SUNDIALS examples, cvRoberts_dns.c), the arrival on
// x' = v as CVODE's root of g = x' - v. Stick phases and switches stay the
// driver's own (forced_stick.cpp, forced_flow.cpp): an independent path for
// the slip phases only, to check the Taylor one against (issue 21 item 2).
#include <cvodes/cvodes.h>

#include <string>

#include "forced_driver.hpp"
#include "integrate/cvode.hpp"

namespace stickslip::forced_detail {

class SlipCvode {
 public:
  SlipCvode(const ForcedModel& m, const ForcedOptions& o, bool variational)
      : m_(m),
        cv_(variational ? 6 : 2, o.method, o.rtol, o.atol, o.max_steps, &SlipCvode::Rhs, 1,
            &SlipCvode::Root, this) {}
  Cvode& cv() { return cv_; }
  Mode mode = Mode::kSlipBelow;

 private:
  static int Rhs(double t, N_Vector y, N_Vector ydot, void* data) {
    const auto* self = static_cast<const SlipCvode*>(data);
    const double* z = N_VGetArrayPointer(y);
    double* f = N_VGetArrayPointer(ydot);
    f[0] = z[1];
    f[1] = self->m_.Acceleration(self->mode, t, z[0], z[1]);
    if (N_VGetLength(y) == 6) {  // Phi' = J Phi, Phi column-major in z[2..5]
      const Mat2 J = self->m_.Jacobian(self->mode, t, Vec2(z[0], z[1]));
      for (int c = 0; c < 2; ++c) {
        f[2 + 2 * c] = J(0, 0) * z[2 + 2 * c] + J(0, 1) * z[3 + 2 * c];
        f[3 + 2 * c] = J(1, 0) * z[2 + 2 * c] + J(1, 1) * z[3 + 2 * c];
      }
    }
    return 0;
  }
  static int Root(double /*t*/, N_Vector y, double* g, void* data) {
    g[0] = N_VGetArrayPointer(y)[1] - static_cast<const SlipCvode*>(data)->m_.v();
    return 0;
  }
  const ForcedModel& m_;
  Cvode cv_;
};

Driver::Driver(const ForcedModel& m, const ForcedOptions& o, const ForcedRequest& rq,
               ForcedRun& run)
    : m_(m), o_(o), rq_(rq), run_(run), series_(m, o.rtol, o.atol, !rq.extremes) {}
Driver::~Driver() = default;

// One slip phase from (t_, x_, xd_) to rq_.t_end or the arrival on x' = v.
// A start on x' = v (g = 0) is no root: CVODE sets g aside until it leaves 0.
bool Driver::SlipByCvode() {
  if (!cvode_) cvode_ = std::make_unique<SlipCvode>(m_, o_, rq_.variational);
  cvode_->mode = mode_;
  Cvode& cv = cvode_->cv();
  const double y0[6] = {x_, xd_, phi_(0, 0), phi_(1, 0), phi_(0, 1), phi_(1, 1)};
  cv.Reinit(t_, y0);
  cv.SetStopTime(rq_.t_end);
  on_surface_ = false;
  const int toward = mode_ == Mode::kSlipBelow ? 1 : -1;  // g rises (below) or falls (above)
  const long steps_before = run_.steps;
  for (;;) {
    double t = t_;
    const int flag = cv.Advance(rq_.t_end, &t);
    run_.steps = steps_before + cv.steps();
    if (flag < 0) {
      if (flag == CV_TOO_MUCH_WORK)
        return Fail(ForcedStatus::kTooMuchWork, "max_steps = " + std::to_string(o_.max_steps));
      t_ = cv.CurrentTime();
      return Fail(ForcedStatus::kFailed,
                  "CVode failed (flag " + std::to_string(flag) + "): " + cv.last_error());
    }
    const double* y = cv.y();
    if (rq_.variational) phi_ << y[2], y[4], y[3], y[5];
    if (flag == CV_ROOT_RETURN) {
      int dir = 0;
      cv.RootInfo(&dir);
      if (dir != toward || !rq_.switching) continue;  // leaving, or no switching
      return Arrive(t, y[0]);
    }
    t_ = rq_.t_end, x_ = y[0], xd_ = y[1];  // CV_TSTOP_RETURN: the stop time exactly
    run_.extrema.Add(x_, xd_);
    Sample();
    return true;
  }
}

}  // namespace stickslip::forced_detail
