// The CVODE stepper: a mode's field and the segment's event functions as
// CVODE callbacks (SUNDIALS examples, cvRoberts_dns.c); every flag mapped to
// a StepOutcome here, so the event driver never reads CVODE flags. CVODE's
// own quirk, the refusal of close roots, is handled here by a restart.
#include <algorithm>
#include <sstream>
#include <vector>

#include "integrate/cvode.hpp"
#include "integrate/stepper.hpp"

namespace stickslip {
namespace {

class CvodeStepper final : public Stepper {
 public:
  CvodeStepper(const FlowOptions& o, const System& s, bool variational)
      : n_(s.dimension()),
        nt_(s.tangent_dimension()),
        variational_(variational),
        o_(o),
        f_(n_),
        J_(nt_, nt_) {}

  void Reset(const SegmentProblem& problem, double t0, const double* y0) override {
    p_ = &problem;
    // At least one root function: the cancel hook is polled from there.
    const int nroots = std::max(1, problem.Events().functions());
    if (!cv_) {
      cv_ = std::make_unique<Cvode>(size(), o_.method, o_.rtol, o_.atol, o_.max_steps,
                                    variational_ ? &CvodeStepper::RhsVar : &CvodeStepper::Rhs,
                                    nroots, &CvodeStepper::Roots, this);
    } else if (nroots != nroots_) {
      cv_->RootInit(nroots, &CvodeStepper::Roots);
    }
    nroots_ = nroots;
    // A clock's events (a stick force with A cos(theta)) turn within a
    // period while the state's field may be polynomial, so that CVODE's
    // error control alone would step over them: steps of at most 1 / Omega,
    // as the forced stick phases had (theta moves by one radian a step).
    double rate = 0;
    for (int j = 0; j < n_ - nt_; ++j) rate = std::max(rate, std::abs(problem.clock_rate[j]));
    cv_->SetMaxStep(rate > 0 ? 1 / rate : 0.0);
    rf_.assign(nroots, 0);
    cv_->Reinit(t0, y0);
    t_start_ = t_lo_ = t0;
    restarted_ = false;
    steps_before_ = 0;
  }
  void SetStopTime(double t) override {
    t_stop_ = t;
    cv_->SetStopTime(t);
  }
  StepOutcome Advance(double tout, double* t) override {
    error_.clear();
    cancelled_ = false;
    int flag = cv_->Advance(tout, t);
    while (flag == CV_ILL_INPUT && !cancelled_ && !restarted_ && t_lo_ > t_start_) {
      if (!Restart()) return StepOutcome::kFailed;
      flag = cv_->Advance(tout, t);
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
    if (p_->on_step.fn) p_->on_step(*t, cv_->y());
    return StepOutcome::kReached;
  }
  const double* y() const override { return cv_->y(); }
  void RootInfo(int* roots_found) const override {
    if (p_->Events().functions() > 0) cv_->RootInfo(roots_found);
  }
  double CurrentTime() override { return cv_->CurrentTime(); }
  double SegmentStart() const override { return t_start_; }
  long steps() const override { return steps_before_ + (cv_ ? cv_->steps() : 0); }
  int size() const override { return variational_ ? n_ + nt_ * nt_ : n_; }
  const std::string& last_error() const override { return error_; }

 private:
  // cvRcheck2 refuses a root function that is exactly zero at the last root
  // and just after it (x' = v and x'' = 0 together at a grazing touch), with
  // CV_ILL_INPUT. Restart at the last root or output time: cvRcheck1 then
  // sets such a function aside. Once per root.
  bool Restart() {
    std::vector<double> buf(size());
    if (!cv_->Interpolate(t_lo_, buf.data())) {
      error_ = "restarting after a close root: no state at t = " + std::to_string(t_lo_);
      return false;
    }
    steps_before_ += cv_->steps();
    cv_->Reinit(t_lo_, buf.data());
    cv_->SetStopTime(t_stop_);
    t_start_ = t_lo_;
    restarted_ = true;
    return true;
  }
  void Describe(int flag) {
    std::ostringstream os;
    os << "CVode failed (flag " << flag << "): " << cv_->last_error();
    error_ = os.str();
  }
  void Field(const double* z, double* f) const {
    using Map = Eigen::Map<const Eigen::VectorXd>;
    Eigen::Map<Eigen::VectorXd> out(f, n_);
    p_->system->Field(p_->mode, Map(z, n_), out);
  }
  static int Rhs(double /*t*/, N_Vector y, N_Vector ydot, void* data) {
    const auto* self = static_cast<const CvodeStepper*>(data);
    self->Field(N_VGetArrayPointer(y), N_VGetArrayPointer(ydot));
    return 0;
  }
  // State plus Phi' = J Phi on the tangent block, Phi column-major after the
  // state. An augmented system (rather than CVODES forward sensitivities)
  // because it is one small dense system whose error control covers Phi.
  static int RhsVar(double t, N_Vector y, N_Vector ydot, void* data) {
    Rhs(t, y, ydot, data);
    auto* self = static_cast<CvodeStepper*>(data);
    const int n = self->n_, nt = self->nt_;
    const double* z = N_VGetArrayPointer(y);
    double* f = N_VGetArrayPointer(ydot);
    self->p_->system->Jacobian(self->p_->mode, Eigen::Map<const Eigen::VectorXd>(z, n), self->J_);
    Eigen::Map<const Eigen::MatrixXd> phi(z + n, nt, nt);
    Eigen::Map<Eigen::MatrixXd> dphi(f + n, nt, nt);
    dphi.noalias() = self->J_ * phi;
    return 0;
  }
  // Called after every step: the cancel hook is polled here, so one long
  // CVode call (a stiff field) stops within a step (a non-zero return ends it).
  static int Roots(double /*t*/, N_Vector y, double* g, void* data) {
    auto* self = static_cast<CvodeStepper*>(data);
    const SegmentProblem& p = *self->p_;
    if (p.cancel && (*p.cancel)()) {
      self->cancelled_ = true;
      return 1;
    }
    const double* z = N_VGetArrayPointer(y);
    self->Field(z, self->f_.data());
    // On steady sliding x'' and x' are both integration noise: they chatter
    // about 0 and round to exactly 0 again and again, which CVODE's root
    // finder refuses next to a root (cvRcheck2). There, and only there, no
    // event but the arrivals counts. Elsewhere an exact 0 becomes a tiny bias
    // that moves no root (an arrival's toward the mode's side).
    const bool at_rest = p.has_rest && p.AtRest(z, self->f_.data());
    const double bias = Tolerances::kRootZeroBias;
    const EventList& ev = p.Events();
    if (ev.functions() == 0) g[0] = 1.0;  // no event: the cancel poll only
    for (int i = 0; i < ev.functions(); ++i) {
      const EventFunction& fn = ev.function(i);
      if (!fn.surface && at_rest) {
        g[i] = 1.0;
        continue;
      }
      const double v = self->Value(fn, z);
      g[i] = v != 0 ? v : fn.zero_sign * bias;
    }
    return 0;
  }
  // An event function at the state z (f_ holds the field there).
  double Value(const EventFunction& fn, const double* z) const {
    const Eigen::Map<const Eigen::VectorXd> zz(z, n_);
    if (fn.exit_contact >= 0)
      return p_->system->StickForce(p_->mode, fn.exit_contact, zz) -
             fn.exit_sign * p_->system->StaticLimit(fn.exit_contact, zz);
    const double* src = fn.derivative ? f_.data() : z;
    double s = -fn.offset;
    for (int t = 0; t < fn.size; ++t) s += fn.terms[t].weight * src[fn.terms[t].row];
    return s;
  }

  int n_, nt_;
  bool variational_;
  FlowOptions o_;
  const SegmentProblem* p_ = nullptr;
  std::unique_ptr<Cvode> cv_;
  int nroots_ = -1;
  std::vector<int> rf_;
  Eigen::VectorXd f_;
  Eigen::MatrixXd J_;
  std::string error_;
  bool cancelled_ = false;
  double t_stop_ = 0;
  double t_start_ = 0, t_lo_ = 0;  // the last (re)start; the last root or output past it
  bool restarted_ = false;         // restarted at t_lo_ already
  long steps_before_ = 0;          // steps before the restart
};

}  // namespace

std::unique_ptr<Stepper> MakeCvodeStepper(const FlowOptions& options, const System& system,
                                          bool variational) {
  return std::make_unique<CvodeStepper>(options, system, variational);
}

}  // namespace stickslip
