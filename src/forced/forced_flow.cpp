// The forced oscillator's view of the one flow (forced/flow.hpp): a
// ForcedRequest as a FlowRequest on ForcedModel (state x, x', theta = Omega
// t), the run as ForcedRun.
#include <algorithm>
#include <cmath>
#include <sstream>

#include "forced_shooting.hpp"
#include "numerics/numbers.hpp"
#include "numerics/tolerances.hpp"
#include "stickslip/errors.hpp"
#include "stickslip/flow/flow.hpp"
#include "stickslip/forced/flow.hpp"

namespace stickslip {

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

namespace {
ForcedStatus Status(const FlowRun& r, const ForcedOptions& o, std::string* why) {
  switch (r.status) {
    case FlowStatus::kTimeLimit:
    case FlowStatus::kStickExit:
      return ForcedStatus::kReached;
    case FlowStatus::kTooManySwitches:
      *why = "max_events = " + std::to_string(o.max_events) + " at t = " + Num(r.end.t, 17);
      return ForcedStatus::kTooMuchWork;
    case FlowStatus::kTooMuchWork:
      *why = "max_steps = " + std::to_string(o.max_steps) + " at t = " + Num(r.end.t, 17);
      return ForcedStatus::kTooMuchWork;
    default:
      *why = r.message;
      return ForcedStatus::kFailed;
  }
}
}  // namespace

namespace forced_detail {

FlowOptions FlowOptionsOf(const ForcedOptions& o) {
  FlowOptions fo;
  fo.rtol = o.rtol;
  fo.atol = o.atol;
  fo.integrator = o.integrator;
  fo.method = o.method;
  fo.max_steps = o.max_steps;
  fo.max_switches = o.max_events;
  return fo;
}

bool SameFlowOptions(const FlowOptions& a, const FlowOptions& b) {
  return a.rtol == b.rtol && a.atol == b.atol && a.integrator == b.integrator &&
         a.method == b.method && a.max_steps == b.max_steps && a.max_switches == b.max_switches;
}

}  // namespace forced_detail

// One flow per thread for the options last used (a ForcedFlow is made per
// shooting call, per period of an orbit diagram: the flow, its steppers and
// its buffers are kept, the model assigned).
ForcedFlow::Scratch& ForcedFlow::Cache(const ForcedModel& model, const ForcedOptions& o) {
  thread_local Scratch sc;
  const FlowOptions fo = forced_detail::FlowOptionsOf(o);
  if (sc.flow && forced_detail::SameFlowOptions(sc.flow->options(), fo)) {
    sc.flow->set_system(model);
    return sc;
  }
  sc.flow = std::make_unique<Flow>(model, fo);
  sc.request = FlowRequest();
  sc.request.extrema = {0, 1};
  return sc;
}

// The forced oscillator as a system with the phase theta = Omega t
// (ForcedModel): one Run of the one flow, its results on (x, x').
ForcedRun ForcedFlow::Run(const ForcedPoint& start, const ForcedRequest& request) const {
  if (!(request.t_end >= start.t) || !std::isfinite(request.t_end))
    throw InvalidArgument("t_end = " + Num(request.t_end) +
                          " must be finite and >= t = " + Num(start.t));
  if (options_.integrator == Integrator::kCvode && request.extremes)
    throw InvalidArgument("extremes inside steps need the Taylor integrator");
  if (!request.switching && start.mode == Mode::kStick)
    throw InvalidArgument("a run without switching needs a slip start");
  Scratch& sc = Cache(model_, options_);
  ForcedRun run;
  FlowPoint p;
  p.t = start.t;
  p.z = Eigen::Vector3d(start.x, start.mode == Mode::kStick ? model_.v() : start.xdot,
                        model_.omega() * start.t);
  p.mode = ModeSet(start.mode);
  run.extrema.Add(p.z[0], p.z[1]);
  if (request.samples) request.samples->push_back({p.t, p.z[0], p.z[1], start.mode});
  if (request.t_end == start.t) {
    run.end = {p.t, p.z[0], p.z[1], start.mode};
    if (start.mode == Mode::kStick) run.jacobian << 1, 0, 0, 0;
    return run;
  }
  FlowRequest& rq = sc.request;
  rq.t_max = request.t_end;
  rq.switching = request.switching;
  rq.variational = request.variational;
  rq.stop_at_exit = request.stop_at_exit;
  rq.extrema_in_steps = request.extremes;
  rq.max_steps = options_.max_steps;
  std::vector<FlowSwitch> switches;
  rq.switches = request.events ? &switches : nullptr;
  rq.step_observer = nullptr;
  if (request.samples)
    rq.step_observer = [&](double t, const double* z, const ModeSet& m) {
      request.samples->push_back({t, z[0], z[1], m[0]});
    };
  sc.flow->Run(p, rq, &sc.run);
  const FlowRun& r_ = sc.run;
  run.status = Status(r_, options_, &run.message);
  run.end = {r_.end.t, r_.end.z[0], r_.end.z[1], r_.end.mode[0]};
  if (request.variational) run.jacobian = r_.jacobian;
  run.extrema = Extrema{r_.lo[0], r_.hi[0], r_.lo[1], r_.hi[1]};
  run.sticks = r_.sticks;
  run.exits = r_.exits;
  run.crossings = r_.crossings;
  run.steps = r_.steps;
  for (const FlowSwitch& s : switches)
    request.events->push_back(
        {static_cast<ForcedEventKind>(s.kind), s.t, s.z[0], s.before[0], s.after[0]});
  return run;
}

}  // namespace stickslip
