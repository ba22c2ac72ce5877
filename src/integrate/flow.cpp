#include "stickslip/integrate/flow.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "integrate/event_driver.hpp"
#include "integrate/stepper.hpp"
#include "stickslip/errors.hpp"
#include "stickslip/model/parameter_axis.hpp"

namespace stickslip {

const char* IntegratorName(Integrator i) { return Name(i); }
const char* MethodName(Method m) { return Name(m); }

std::unique_ptr<Stepper> MakeCvodeStepper(const FlowOptions& options, bool variational);
std::unique_ptr<Stepper> MakeTaylorStepper(const FlowOptions& options, bool variational,
                                           const std::optional<ParameterAxis>& parameter);

std::unique_ptr<Stepper> MakeStepper(const FlowOptions& options, bool variational,
                                     const std::optional<ParameterAxis>& parameter) {
  return options.integrator == Integrator::kTaylor
             ? MakeTaylorStepper(options, variational, parameter)
             : MakeCvodeStepper(options, variational);
}

const char* FlowStatusName(FlowStatus s) { return Name(s); }

std::string FlowOptions::ValidationError() const {
  std::ostringstream os;
  using T = Tolerances;
  if (!(rtol >= T::kRtolMin && rtol <= T::kTolMax)) {
    os << "rtol = " << rtol << " must be in [" << T::kRtolMin << ", " << T::kTolMax << "]";
  } else if (!(atol >= T::kAtolMin && atol <= T::kTolMax)) {
    os << "atol = " << atol << " must be in [" << T::kAtolMin << ", " << T::kTolMax << "]";
  } else if (max_steps < kMinSteps) {
    os << "max_steps = " << max_steps << " must be >= " << kMinSteps;
  } else if (max_switches < 1) {
    os << "max_switches = " << max_switches << " must be >= 1";
  }
  return os.str();
}

Flow::Flow(const FrictionSystem& system, const FlowOptions& options)
    : system_(system.Clone()), options_(options) {
  const std::string err = options.ValidationError();
  if (!err.empty()) throw InvalidArgument(err);
}

Flow::~Flow() = default;

const Model& Flow::model() const {
  const auto* belt = dynamic_cast<const Model*>(system_.get());
  if (!belt) throw InvalidArgument("Flow::model: the system is not the belt model");
  return *belt;
}

void Flow::set_parameter_column(const ParameterAxis& axis) {
  if (!system_->SupportsParameterColumn(axis))
    throw InvalidArgument("parameter column: '" + axis.name() +
                          "' enters the friction law non-affinely (not supported)");
  // The stepper stays for when the same column is asked again.
  if (axis != param_axis_) {
    param_.reset();
    param_axis_ = axis;
  }
  parameter_ = axis;
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

// The state of one Run between segments.
struct Flow::Walk {
  FlowResult r;
  Mode mode;
  double t;
  Vec2 z;
  Mat2 M = Mat2::Identity();
  double next_output;
  SegmentOutput out;
};

namespace {
void Extend(FlowResult& r, const Vec2& z) { r.extrema.Add(z[0], z[1]); }

// The non-terminal events of g1 = x'' and g2 = x': extrema of x' and x.
void RecordExtremum(void* context, int g, const double* y) {
  Extrema& e = *static_cast<Extrema*>(context);
  if (g == 1) {
    e.AddXdot(y[1]);
  } else if (g == 2) {
    e.AddX(y[0]);
  }
}

// A slip segment's events (stepper.hpp names the root functions).
EventList SlipEvents(const StopRule& stop, Mode mode, bool starts_on_surface) {
  EventList events;
  // Arrival at x' = v ends the segment; a start just off it that reaches it
  // at once arrives there.
  if (stop.switching) events.Add(Event{0, kAnyRoot, true, !starts_on_surface});
  events.Add(Event{1, kAnyRoot, false});  // extrema of x'
  events.Add(Event{2, kAnyRoot, false});  // extrema of x
  if (stop.at_velocity_max && mode == Mode::kSlipBelow) events.Add(Event{1, -1, true});
  if (stop.at_section) events.Add(Event{2, -1, true});  // a maximum of x
  return events;
}
}  // namespace

Flow::SlipEnd Flow::Slip(double t0, const Vec2& z0, const StopRule& stop, bool variational,
                         const SegmentOutput& out, FlowResult& r) {
  Stepper& cv = Solver(variational);
  const int n = cv.size();
  Extrema extrema = r.extrema;
  SlipProblem problem{system_.get(), mode_, options_.rtol, options_.atol,
                      cancel_ ? &cancel_ : nullptr};
  problem.x_center = mode_ == Mode::kSlipBelow ? system_->SteadySliding().x : 0.0;
  problem.SetEvents(SlipEvents(stop, mode_, z0[1] == system_->v()),
                    EventHook{&RecordExtremum, &extrema});
  const double init[8] = {z0[0], z0[1], 1.0, 0.0, 0.0, 1.0, 0.0, 0.0};
  const SegmentEnd e = RunSegment(cv, problem, t0, init, stop.t_max, out);
  total_steps_ += cv.steps();
  taylor_orders_.Merge(cv.orders());
  r.extrema.Merge(extrema);
  double y[8];
  std::copy(e.y, e.y + n, y);
  auto end = [&](SlipEnd::Kind kind, double t) {
    SlipEnd se{kind, t, Vec2(y[0], y[1]), Mat2::Identity(), Vec2::Zero()};
    if (variational) se.phi << y[2], y[4], y[3], y[5];
    if (n == 8) se.dzdp = Vec2(y[6], y[7]);
    return se;
  };
  switch (e.kind) {
    case SegmentEnd::kEvent:
      if (e.g == 0) {  // on the surface x' = v
        y[1] = system_->v();
        return end(SlipEnd::kArrival, e.t);
      }
      if (e.g == 1) return end(SlipEnd::kVelocityMax, e.t);
      y[1] = 0.0;  // on the section x' = 0
      return end(SlipEnd::kSection, e.t);
    case SegmentEnd::kTime:
      return end(SlipEnd::kTime, e.t);
    case SegmentEnd::kCancelled:
      r.message = Where("cancelled", e.t);
      return end(SlipEnd::kCancel, e.t);
    case SegmentEnd::kTooMuchWork:
      if (Settled(problem, y)) {
        // Settled on stable steady sliding, where it stays: the rest of the
        // segment is (xbar, 0), and no event can follow.
        std::fill(y, y + n, 0.0);
        y[0] = system_->SteadySliding().x;
        const double t_rest = std::isfinite(stop.t_max) ? stop.t_max : e.t_end;
        while (out.on() && *out.next < t_rest) {
          (*out.observer)(Sample{*out.next, Vec2(y[0], 0.0), mode_});
          *out.next += out.dt;
        }
        return end(SlipEnd::kTime, t_rest);
      }
      return end(SlipEnd::kFail, Failed(cv.CurrentTime(), y, cv.last_error(), r));
    case SegmentEnd::kFailed:
      return end(SlipEnd::kFail, Failed(e.t, y, e.reason, r));
  }
  return end(SlipEnd::kFail, e.t);
}

bool Flow::Settled(const SlipProblem& problem, const double* y) const {
  return mode_ == Mode::kSlipBelow && system_->SteadySliding().stable() &&
         problem.AtRest(y[0], y[1], system_->Acceleration(mode_, y[0], y[1]));
}

std::string Flow::Where(const char* what, double t) const {
  std::ostringstream os;
  os << what << " at t = " << t << " in " << ModeName(mode_);
  return os.str();
}

double Flow::Failed(double t, const double* y, const std::string& reason, FlowResult& r) const {
  std::ostringstream os;
  os << IntegratorName(options_.integrator) << " failed at t = " << t << " in " << ModeName(mode_)
     << " at x = " << y[0] << ", x' = " << y[1] << ": " << reason;
  r.message = os.str();
  return t;
}

// Seed eq. (3.6): x = x(0) + v t until x + 2 beta v = mu_s; then slip below
// (v > 0: stick always ends at x0). False when t_max comes first.
bool Flow::Stick(Walk& w, const StopRule& stop, bool variational) {
  const double v = system_->v();
  const double x_exit = system_->ExitPoint()[0];
  const double t_exit = w.t + (x_exit - w.z[0]) / v;
  const double t_stop = std::min(t_exit, stop.t_max);
  while (w.out.on() && w.next_output < t_stop) {
    (*w.out.observer)(
        Sample{w.next_output, Vec2(w.z[0] + v * (w.next_output - w.t), v), Mode::kStick});
    w.next_output += w.out.dt;
  }
  w.r.t_stick += t_stop - w.t;
  if (t_exit >= stop.t_max) {
    w.z[0] += v * (stop.t_max - w.t);
    w.t = stop.t_max;
    return false;
  }
  w.t = t_exit;
  w.z = system_->ExitPoint();
  Extend(w.r, w.z);
  if (variational) w.M = system_->SaltationStickOut() * w.M;
  Switch(w, Mode::kSlipBelow);
  return true;
}

void Flow::Switch(Walk& w, Mode next) {
  w.mode = next;
  ++w.r.switches;
  w.r.modes.push_back(next);
  if (w.out.on()) (*w.out.observer)(Sample{w.t, w.z, next});
}

FlowResult Flow::Run(double t0, const Vec2& z0, Mode m0, const StopRule& stop, bool variational,
                     double output_dt, const Observer& observer) {
  if (!z0.allFinite()) throw InvalidArgument("Flow::Run: start state is not finite");
  if (m0 == Mode::kStick && (z0[1] != system_->v() || !system_->InStickInterval(z0[0])))
    throw InvalidArgument("Flow::Run: stick mode requested off the stick set");
  if (!(stop.t_max > t0)) throw InvalidArgument("Flow::Run: t_max must be > t0");
  Walk w{FlowResult{}, m0, t0, z0, Mat2::Identity(), t0, SegmentOutput{}};
  w.out = SegmentOutput{output_dt, &w.next_output, &observer};
  FlowResult& r = w.r;
  r.extrema = Extrema::Point(z0[0], z0[1]);
  r.modes.push_back(m0);
  const bool column = variational && has_parameter_column() && m0 != Mode::kStick;
  if (w.out.on()) {
    observer(Sample{t0, z0, m0});
    w.next_output = t0 + output_dt;
  }
  auto done = [&](FlowStatus s) {
    r.status = s;
    r.t = w.t;
    r.z = w.z;
    r.mode = w.mode;
    r.jacobian = w.M;
    r.has_dzdp = column && r.switches == 0;
    if (!r.has_dzdp) r.dzdp = Vec2::Zero();
    Extend(r, w.z);
    if (w.out.on()) observer(Sample{w.t, w.z, w.mode});
    return std::move(r);
  };
  for (;;) {
    if (r.switches > options_.max_switches) {
      std::ostringstream os;
      os << "more than " << options_.max_switches << " mode changes by t = " << w.t;
      r.message = os.str();
      return done(FlowStatus::kTooManySwitches);
    }
    if (w.mode == Mode::kStick) {
      if (!Stick(w, stop, variational)) return done(FlowStatus::kTimeLimit);
      continue;
    }
    mode_ = w.mode;
    const SlipEnd e = Slip(w.t, w.z, stop, variational, w.out, r);
    if (variational) w.M = e.phi * w.M;
    if (column && r.switches == 0) r.dzdp = e.dzdp;
    w.t = e.t;
    w.z = e.z;
    Extend(r, w.z);
    if (e.kind != SlipEnd::kArrival) return done(SlipStatus(e.kind));
    const Mode next = system_->ModeAfterArrival(w.mode, w.z[0]);
    if (next == Mode::kStick && stop.at_stick) return done(FlowStatus::kStick);
    if (variational)
      w.M = (next == Mode::kStick ? FrictionSystem::SaltationStickIn()
                                  : system_->SaltationCrossing(w.mode, next, w.z)) *
            w.M;
    if (next != Mode::kStick) ++r.crossings;
    Switch(w, next);
  }
}

FlowStatus Flow::SlipStatus(int kind) {
  switch (kind) {
    case SlipEnd::kFail:
      return FlowStatus::kIntegratorFailed;
    case SlipEnd::kCancel:
      return FlowStatus::kCancelled;
    case SlipEnd::kSection:
      return FlowStatus::kSection;
    case SlipEnd::kVelocityMax:
      return FlowStatus::kVelocityMax;
    default:
      return FlowStatus::kTimeLimit;
  }
}

}  // namespace stickslip
