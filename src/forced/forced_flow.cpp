// The forced flow's driver: slip phases through the one event loop
// (RunSegment, integrate/event_driver.hpp) with the forced steppers
// (forced_stepper.hpp), their events (arrival on x' = v, extrema of x and
// x'), and the Filippov rule at every arrival.
#include <algorithm>
#include <cmath>
#include <sstream>

#include "forced_driver.hpp"
#include "numerics/numbers.hpp"
#include "numerics/tolerances.hpp"
#include "stickslip/errors.hpp"

namespace stickslip {

const char* ForcedEventName(ForcedEventKind k) { return Name(k); }

const char* ForcedStatusName(ForcedStatus s) { return Name(s); }

std::string ForcedOptions::ValidationError() const {
  using T = Tolerances;
  if (!(rtol >= T::kForcedRtolMin && rtol <= T::kTolMax))
    return "rtol = " + Num(rtol) + " must lie in [" + Num(T::kForcedRtolMin) + ", " +
           Num(T::kTolMax) + "]";
  // Messages only on failure: a flow is made per shooting call, and formatting
  // the range every time was 12 % of forced_bench (callgrind).
  if (!(atol >= T::kAtolMin && atol <= T::kTolMax))
    return "atol = " + Num(atol) + " must lie in [" + Num(T::kAtolMin) + ", " + Num(T::kTolMax) +
           "]";
  if (max_steps < 1) return "max_steps = " + std::to_string(max_steps) + " must be >= 1";
  if (max_events < 1) return "max_events = " + std::to_string(max_events) + " must be >= 1";
  if (integrator == Integrator::kCvode && !(rtol >= T::kCvodeRtolMin && atol >= T::kCvodeAtolMin))
    return "rtol = " + Num(rtol) + ", atol = " + Num(atol) +
           ": CVODE needs rtol >= " + Num(T::kCvodeRtolMin) +
           " and atol >= " + Num(T::kCvodeAtolMin);
  return "";
}

ForcedPoint ForcedStart(const ForcedModel& m, double t, double x, double xdot) {
  ForcedPoint p{t, x, xdot, Mode::kSlipBelow};
  if (xdot > m.v()) p.mode = Mode::kSlipAbove;
  if (xdot == m.v()) p.mode = m.InStickBand(t, x) ? Mode::kStick : m.ExitMode(t, x);
  return p;
}

ForcedFlow::ForcedFlow(const ForcedModel& model, const ForcedOptions& options)
    : model_(model), options_(options) {
  const std::string e = options.ValidationError();
  if (!e.empty()) throw InvalidArgument(e);
}

ForcedRun ForcedFlow::Run(const ForcedPoint& start, const ForcedRequest& request) const {
  if (!(request.t_end >= start.t) || !std::isfinite(request.t_end))
    throw InvalidArgument("t_end = " + Num(request.t_end) +
                          " must be finite and >= t = " + Num(start.t));
  if (options_.integrator == Integrator::kCvode && request.extremes)
    throw InvalidArgument("extremes inside steps need the Taylor integrator");
  if (!request.switching && start.mode == Mode::kStick)
    throw InvalidArgument("a run without switching needs a slip start");
  ForcedRun run;
  forced_detail::Driver(model_, options_, request, run).Run(start);
  return run;
}

namespace forced_detail {

void Driver::Run(const ForcedPoint& start) {
  t_ = start.t, x_ = start.x, xd_ = start.xdot, mode_ = start.mode;
  if (mode_ == Mode::kStick) {
    xd_ = m_.v();
    phi_ << 1, 0, 0, 0;  // stick has no x' direction
  }
  run_.extrema.Add(x_, xd_);
  Sample();
  while (t_ < rq_.t_end && (mode_ == Mode::kStick ? Stick() : Slip())) {
  }
  run_.end = {t_, x_, xd_, mode_};
  run_.jacobian = phi_;
}

bool Driver::Fail(ForcedStatus s, const std::string& what) {
  std::ostringstream os;
  os << what << " at t = " << Num(t_, 17);
  run_.status = s;
  run_.message = os.str();
  return false;
}

bool Driver::Record(ForcedEventKind kind, Mode before, Mode after) {
  run_.extrema.Add(x_, xd_);
  if (rq_.events) rq_.events->push_back({kind, t_, x_, before, after});
  Sample();
  stalled_events_ = t_ == last_event_t_ ? stalled_events_ + 1 : 0;
  last_event_t_ = t_;
  if (stalled_events_ > 8) return Fail(ForcedStatus::kFailed, "switching does not advance t");
  if (++events_ > o_.max_events)
    return Fail(ForcedStatus::kTooMuchWork, "max_events = " + std::to_string(o_.max_events));
  return true;
}

bool Driver::Arrive(double t, double x) {
  t_ = t, x_ = x, xd_ = m_.v();
  const Mode before = mode_, after = m_.ModeAfterArrival(mode_, t, x);
  if (after == Mode::kStick) {
    phi_.row(1).setZero();  // S_in = diag(1, 0)
    mode_ = after;
    ++run_.sticks;
    return Record(ForcedEventKind::kStickIn, before, after);
  }
  if (after == before) return Record(ForcedEventKind::kTouch, before, after);
  if (rq_.variational) phi_ = m_.SaltationCrossing(before, after, t, x) * phi_;
  mode_ = after;
  ++run_.crossings;
  return Record(ForcedEventKind::kCrossing, before, after);
}

// A slip phase's events: the arrival on x' = v, terminal, in the direction
// towards it (also at once from a start on it: the flow turns back); the
// extrema of x' and x (at v = 0 those of x are the arrivals), not terminal.
EventList Driver::SlipEvents() const {
  EventList events;
  const int toward = mode_ == Mode::kSlipBelow ? 1 : -1;
  if (rq_.switching) events.Add(Event{0, toward, true, true});
  if (rq_.extremes) {
    events.Add(Event{1, kAnyRoot, false});
    if (m_.v() != 0) events.Add(Event{2, kAnyRoot, false});
  }
  return events;
}

void Driver::OnExtremum(void* self, int /*g*/, const double* y) {
  static_cast<Driver*>(self)->run_.extrema.Add(y[0], y[1]);
}

void Driver::OnStep(void* self, double t, const double* y) {
  auto& d = *static_cast<Driver*>(self);
  d.run_.extrema.Add(y[0], y[1]);
  if (d.rq_.samples) d.rq_.samples->push_back({t, y[0], y[1], d.mode_});
}

bool Driver::Slip() {
  ForcedSlipProblem& p = problem_;
  if (!events_set_ || p.mode != mode_) {
    p.mode = mode_;
    p.SetEvents(SlipEvents(), EventHook{&Driver::OnExtremum, this});
    events_set_ = true;
  }
  p.max_steps = o_.max_steps - run_.steps;
  const double y0[6] = {x_, xd_, phi_(0, 0), phi_(1, 0), phi_(0, 1), phi_(1, 1)};
  SegmentEnd e;
  long steps = 0;
  if (o_.integrator == Integrator::kCvode) {
    if (!cvode_) cvode_ = MakeForcedCvode(m_, o_, rq_.variational);
    e = RunSegment(*cvode_, p, t_, y0, rq_.t_end, &steps);
  } else {
    e = RunSegment(taylor_, p, t_, y0, rq_.t_end, SegmentOutput{});
    steps = taylor_.steps();
  }
  run_.steps += steps;
  // Where the segment ended, also when cut short: the run's end, and (as for
  // every Taylor step's end) in its extrema.
  t_ = e.t, x_ = e.y[0], xd_ = e.y[1];
  if (rq_.variational) phi_ << e.y[2], e.y[4], e.y[3], e.y[5];
  if (e.kind == SegmentEnd::kTooMuchWork || e.kind == SegmentEnd::kFailed)
    run_.extrema.Add(x_, xd_);
  switch (e.kind) {
    case SegmentEnd::kEvent:  // the arrival, the only terminal event
      return Arrive(e.t, e.y[0]);
    case SegmentEnd::kTime:
      return true;
    case SegmentEnd::kTooMuchWork:
      return Fail(ForcedStatus::kTooMuchWork, "max_steps = " + std::to_string(o_.max_steps));
    default:  // kFailed (no cancel hook)
      return Fail(ForcedStatus::kFailed, e.reason);
  }
}

}  // namespace forced_detail
}  // namespace stickslip
