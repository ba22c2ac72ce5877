#include "stickslip/integrate/flow.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "integrate/stepper.hpp"
#include "stickslip/errors.hpp"
#include "stickslip/model/parameter_axis.hpp"

namespace stickslip {

const char* IntegratorName(Integrator i) { return i == Integrator::kTaylor ? "taylor" : "cvode"; }
const char* MethodName(Method m) { return m == Method::kAdams ? "adams" : "bdf"; }

std::unique_ptr<Stepper> MakeCvodeStepper(const FlowOptions& options, bool variational);
std::unique_ptr<Stepper> MakeTaylorStepper(const FlowOptions& options, bool variational,
                                           const std::string& parameter);

std::unique_ptr<Stepper> MakeStepper(const FlowOptions& options, bool variational,
                                     const std::string& parameter) {
  return options.integrator == Integrator::kTaylor
             ? MakeTaylorStepper(options, variational, parameter)
             : MakeCvodeStepper(options, variational);
}

const char* FlowStatusName(FlowStatus s) {
  switch (s) {
    case FlowStatus::kTimeLimit:
      return "time-limit";
    case FlowStatus::kStick:
      return "stick";
    case FlowStatus::kSection:
      return "section";
    case FlowStatus::kVelocityMax:
      return "velocity-max";
    case FlowStatus::kIntegratorFailed:
      return "integrator-failed";
    case FlowStatus::kTooManySwitches:
      return "too-many-switches";
    case FlowStatus::kCancelled:
      return "cancelled";
  }
  return "?";
}

std::string FlowOptions::ValidationError() const {
  std::ostringstream os;
  if (!(rtol >= 1e-14 && rtol <= 1e-2)) {
    os << "rtol = " << rtol << " must be in [1e-14, 1e-2]";
  } else if (!(atol >= 1e-16 && atol <= 1e-2)) {
    os << "atol = " << atol << " must be in [1e-16, 1e-2]";
  } else if (max_steps < 10) {
    os << "max_steps = " << max_steps << " must be >= 10";
  } else if (max_switches < 1) {
    os << "max_switches = " << max_switches << " must be >= 1";
  }
  return os.str();
}

Flow::Flow(const Model& model, const FlowOptions& options) : model_(model), options_(options) {
  const std::string err = options.ValidationError();
  if (!err.empty()) throw InvalidArgument(err);
}

Flow::~Flow() = default;

bool ParameterColumnSupported(LawKind law, const std::string& name) {
  return !((name == "v_m" && law == LawKind::kCubic) ||
           (name == "v_s" && law == LawKind::kStribeck) ||
           (name == "delta" && law == LawKind::kLeine));
}

void Flow::set_parameter_column(const std::string& name) {
  if (!name.empty()) {
    ParameterAxis{name};  // throws for an unknown name
    if (!ParameterColumnSupported(model_.params().law, name))
      throw InvalidArgument("parameter column: '" + name +
                            "' enters the friction law non-affinely (not supported)");
  }
  // The stepper stays for when the same column is asked again.
  if (!name.empty() && name != param_name_) {
    param_.reset();
    param_name_ = name;
  }
  parameter_ = name;
}

Stepper& Flow::Solver(bool variational) {
  if (variational && has_parameter_column()) {
    if (!param_) param_ = MakeStepper(options_, true, parameter_);
    return *param_;
  }
  auto& slot = variational ? var_ : plain_;
  if (!slot) slot = MakeStepper(options_, variational);
  return *slot;
}

struct Flow::SlipEnd {
  enum Kind { kArrival, kSection, kVelocityMax, kTime, kFail, kCancel } kind;
  double t;
  Vec2 z;
  Mat2 phi;
  Vec2 dzdp;  // with the parameter column
};

namespace {
// Each root function fires once per instant: roots that keep coming at one t,
// to rounding (steps of zero or rounding length, each resetting the stepper's
// step count), would loop for ever, so they are a failure that says where.
struct RootRepeats {
  double t = NAN;  // where the run of repeats began
  int count = 0;
  bool Stuck(double t_root) {
    const bool same = std::abs(t_root - t) <= 64 * 2.2e-16 * std::max(1.0, std::abs(t));
    count = same ? count + 1 : 0;
    if (!same) t = t_root;
    return count > 2 * kNumRoots;
  }
};

void Extend(FlowResult& r, const Vec2& z) {
  r.x_min = std::min(r.x_min, z[0]);
  r.x_max = std::max(r.x_max, z[0]);
  r.xdot_min = std::min(r.xdot_min, z[1]);
  r.xdot_max = std::max(r.xdot_max, z[1]);
}
}  // namespace

Flow::SlipEnd Flow::Slip(double t0, const Vec2& z0, const StopRule& stop, bool variational,
                         double output_dt, double& next_output, const Observer& observer,
                         FlowResult& r) {
  Stepper& cv = Solver(variational);
  const int n = cv.size();
  // The roots that end the segment stop the stepper; extrema of x and x' it
  // may pass, recording them.
  Extrema extrema{r.x_min, r.x_max, r.xdot_min, r.xdot_max};
  SlipProblem problem{&model_, mode_, options_.rtol, options_.atol, cancel_ ? &cancel_ : nullptr};
  problem.x_center = mode_ == Mode::kSlipBelow ? model_.SteadySliding().x : 0.0;
  problem.stop_dir[0] = stop.switching ? kAnyRoot : 0;
  problem.stop_dir[1] = stop.at_velocity_max && mode_ == Mode::kSlipBelow ? -1 : 0;
  problem.stop_dir[2] = stop.at_section ? -1 : 0;
  problem.extrema = &extrema;
  double init[8] = {z0[0], z0[1], 1.0, 0.0, 0.0, 1.0, 0.0, 0.0};
  cv.Reset(problem, t0, init);
  // The stop time in chunks of 1e9 (a finite stop time for CVODE), extended
  // until stop.t_max.
  double t_end = std::min(stop.t_max, t0 + 1e9);
  cv.SetStopTime(t_end);
  // A segment that starts at an output time (a switch there, to rounding) has
  // that sample already: the switch's.
  while (output_dt > 0 && observer && next_output <= t0 + 1e-14 * std::max(1.0, std::abs(t0)))
    next_output += output_dt;
  const double v = model_.v();
  long steps_before = cv.steps();

  auto finish = [&](SlipEnd::Kind kind, double t, const double* y) {
    r.x_min = std::min(r.x_min, extrema.x_min);
    r.x_max = std::max(r.x_max, extrema.x_max);
    r.xdot_min = std::min(r.xdot_min, extrema.xdot_min);
    r.xdot_max = std::max(r.xdot_max, extrema.xdot_max);
    SlipEnd e{kind, t, Vec2(y[0], y[1]), Mat2::Identity(), Vec2::Zero()};
    if (variational) e.phi << y[2], y[4], y[3], y[5];
    if (n == 8) e.dzdp = Vec2(y[6], y[7]);
    total_steps_ += cv.steps() - steps_before;
    return e;
  };
  double buf[8];

  double t_lo = t0, t_start = t0;
  bool restarted = false;
  RootRepeats repeats;
  for (;;) {
    const bool sampling = output_dt > 0 && observer;
    const double tout = sampling ? std::min(next_output, t_end) : t_end;
    double t = t0;
    const StepOutcome flag = cv.Advance(tout, &t);
    const double* y = cv.y();
    if (flag == StepOutcome::kCloseRoots && !restarted && t_lo > t_start) {
      // cvRcheck2 refuses a root function that is exactly zero at the last
      // root and just after it (x' = v and x'' = 0 together at a grazing
      // touch). Restart there: cvRcheck1 then sets such a function aside.
      if (!cv.Interpolate(t_lo, buf)) {
        r.message = "restarting after a close root: no state at t = " + std::to_string(t_lo);
        return finish(SlipEnd::kFail, t_lo, cv.y());
      }
      total_steps_ += cv.steps() - steps_before;
      cv.Reset(problem, t_lo, buf);
      steps_before = 0;
      cv.SetStopTime(t_end);
      t_start = t_lo;
      restarted = true;
      continue;
    }
    if (flag == StepOutcome::kCancelled || (cancel_ && cancel_())) {
      std::ostringstream os;
      os << "cancelled at t = " << t << " in " << ModeName(mode_);
      r.message = os.str();
      return finish(SlipEnd::kCancel, t, y);
    }
    if (flag == StepOutcome::kTooMuchWork && mode_ == Mode::kSlipBelow &&
        model_.SteadySliding().stable() &&
        problem.AtRest(y[0], y[1], model_.Acceleration(mode_, y[0], y[1]))) {
      // Settled on stable steady sliding, where it stays: the rest of the
      // segment is (xbar, 0), and no event can follow.
      double rest[8] = {model_.SteadySliding().x, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
      const double t_rest = std::isfinite(stop.t_max) ? stop.t_max : t_end;
      while (sampling && next_output < t_rest) {
        observer(Sample{next_output, Vec2(rest[0], 0.0), mode_});
        next_output += output_dt;
      }
      return finish(SlipEnd::kTime, t_rest, rest);
    }
    if (flag == StepOutcome::kFailed || flag == StepOutcome::kTooMuchWork ||
        flag == StepOutcome::kCloseRoots) {
      t = cv.CurrentTime();
      std::ostringstream os;
      os << IntegratorName(options_.integrator) << " failed at t = " << t << " in "
         << ModeName(mode_) << " at x = " << y[0] << ", x' = " << y[1] << ": " << cv.last_error();
      r.message = os.str();
      return finish(SlipEnd::kFail, t, y);
    }
    if (flag == StepOutcome::kRoot) {
      int rf[kNumRoots];
      cv.RootInfo(rf);
      if (repeats.Stuck(t)) {
        std::ostringstream os;
        os << IntegratorName(options_.integrator) << " failed at t = " << t << " in "
           << ModeName(mode_) << " at x = " << y[0] << ", x' = " << y[1]
           << ": events repeat at this time without progress";
        r.message = os.str();
        return finish(SlipEnd::kFail, t, y);
      }
      // A root exactly at an output time: report the sample, or the next call
      // would ask CVODE for tout = t.
      if (sampling && t >= next_output) {
        observer(Sample{t, Vec2(y[0], y[1]), mode_});
        next_output += output_dt;
      }
      // A start on a root surface (x'' = 0 at the stick exit, x' = 0 on the
      // section) holds only to rounding; an event at t = t0 is not an event.
      // But a start just off x' = v that reaches it at once arrives there.
      const bool arrives_at_once = rf[0] != 0 && stop.switching && z0[1] != v;
      if (t - t_start <= 1e-12 * std::max(1.0, std::abs(t_start)) && !arrives_at_once) continue;
      if (rf[0] != 0 && stop.switching) {
        double z[2] = {y[0], v};
        std::copy(y + 2, y + n, buf + 2);
        buf[0] = z[0];
        buf[1] = z[1];
        return finish(SlipEnd::kArrival, t, buf);
      }
      if (rf[1] != 0) {
        // No fallback for a touch of x' = v within one step: both steppers
        // test every root function wherever they test one (CVODE's
        // cvRootfind; the first sign change of each Taylor step polynomial),
        // so an arrival always comes before an extremum of x' beyond v.
        r.xdot_min = std::min(r.xdot_min, y[1]);
        r.xdot_max = std::max(r.xdot_max, y[1]);
        if (stop.at_velocity_max && rf[1] < 0 && mode_ == Mode::kSlipBelow)
          return finish(SlipEnd::kVelocityMax, t, y);
      }
      if (rf[2] != 0) {
        r.x_min = std::min(r.x_min, y[0]);
        r.x_max = std::max(r.x_max, y[0]);
        if (stop.at_section && rf[2] < 0) {
          std::copy(y, y + n, buf);
          buf[1] = 0.0;
          return finish(SlipEnd::kSection, t, buf);
        }
      }
      t_lo = t;
      restarted = false;
      continue;
    }
    if (t >= t_end && t_end < stop.t_max) {  // the next chunk
      t_end = std::min(stop.t_max, t_end + 1e9);
      cv.SetStopTime(t_end);
      continue;
    }
    if (t >= t_end) return finish(SlipEnd::kTime, t, y);
    // An output time.
    observer(Sample{t, Vec2(y[0], y[1]), mode_});
    next_output += output_dt;
    t_lo = t;
  }
}

FlowResult Flow::Run(double t0, const Vec2& z0, Mode m0, const StopRule& stop, bool variational,
                     double output_dt, const Observer& observer) {
  if (!z0.allFinite()) throw InvalidArgument("Flow::Run: start state is not finite");
  if (m0 == Mode::kStick && (z0[1] != model_.v() || !model_.InStickInterval(z0[0])))
    throw InvalidArgument("Flow::Run: stick mode requested off the stick set");
  if (!(stop.t_max > t0)) throw InvalidArgument("Flow::Run: t_max must be > t0");
  FlowResult r;
  r.x_min = r.x_max = z0[0];
  r.xdot_min = r.xdot_max = z0[1];
  r.modes.push_back(m0);
  Mode mode = m0;
  double t = t0;
  Vec2 z = z0;
  Mat2 M = Mat2::Identity();
  const double v = model_.v();
  const bool sampling = output_dt > 0 && observer;
  const bool column = variational && has_parameter_column() && m0 != Mode::kStick;
  double next_output = t0;
  if (sampling) {
    observer(Sample{t0, z0, m0});
    next_output = t0 + output_dt;
  }
  auto done = [&](FlowStatus s) {
    r.status = s;
    r.t = t;
    r.z = z;
    r.mode = mode;
    r.jacobian = M;
    r.has_dzdp = column && r.switches == 0;
    if (!r.has_dzdp) r.dzdp = Vec2::Zero();
    Extend(r, z);
    if (sampling) observer(Sample{t, z, mode});
    return r;
  };

  for (;;) {
    if (r.switches > options_.max_switches) {
      std::ostringstream os;
      os << "more than " << options_.max_switches << " mode changes by t = " << t;
      r.message = os.str();
      return done(FlowStatus::kTooManySwitches);
    }
    if (mode == Mode::kStick) {
      // Seed eq. (3.6): x = x(0) + v t until x + 2 beta v = mu_s.
      const double x_exit = model_.ExitPoint()[0];
      const double t_exit = t + (x_exit - z[0]) / v;
      const double t_stop = std::min(t_exit, stop.t_max);
      while (sampling && next_output < t_stop) {
        observer(Sample{next_output, Vec2(z[0] + v * (next_output - t), v), Mode::kStick});
        next_output += output_dt;
      }
      r.t_stick += t_stop - t;
      if (t_exit >= stop.t_max) {
        z[0] += v * (stop.t_max - t);
        t = stop.t_max;
        return done(FlowStatus::kTimeLimit);
      }
      t = t_exit;
      z = model_.ExitPoint();
      Extend(r, z);
      if (variational) M = model_.SaltationStickOut() * M;
      mode = Mode::kSlipBelow;  // v > 0: stick always ends at x0 into slip below
      ++r.switches;
      r.modes.push_back(mode);
      if (sampling) observer(Sample{t, z, mode});
      continue;
    }
    mode_ = mode;
    const SlipEnd e = Slip(t, z, stop, variational, output_dt, next_output, observer, r);
    if (variational) M = e.phi * M;
    if (column && r.switches == 0) r.dzdp = e.dzdp;
    t = e.t;
    z = e.z;
    Extend(r, z);
    switch (e.kind) {
      case SlipEnd::kFail:
        return done(FlowStatus::kIntegratorFailed);
      case SlipEnd::kCancel:
        return done(FlowStatus::kCancelled);
      case SlipEnd::kTime:
        return done(FlowStatus::kTimeLimit);
      case SlipEnd::kSection:
        return done(FlowStatus::kSection);
      case SlipEnd::kVelocityMax:
        return done(FlowStatus::kVelocityMax);
      case SlipEnd::kArrival:
        break;
    }
    const Mode next = model_.ModeAfterArrival(mode, z[0]);
    if (next == Mode::kStick && stop.at_stick) return done(FlowStatus::kStick);
    if (variational)
      M = (next == Mode::kStick ? Model::SaltationStickIn()
                                : model_.SaltationCrossing(mode, next, z)) *
          M;
    if (next != Mode::kStick) ++r.crossings;
    mode = next;
    ++r.switches;
    r.modes.push_back(mode);
    if (sampling) observer(Sample{t, z, mode});
  }
}

}  // namespace stickslip
