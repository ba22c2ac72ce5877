// A sampled trajectory of the forced oscillator (forced/simulate.hpp): the
// flow is run from one breakpoint to the next (multiples of dt, and of the
// forcing period for the stroboscopic section), each switch kept as a row.
#include <algorithm>
#include <cmath>

#include "numerics/numbers.hpp"
#include "stickslip/errors.hpp"
#include "stickslip/forced/simulate.hpp"

namespace stickslip {

std::string ForcedSimulationOptions::ValidationError() const {
  const std::string e = flow.ValidationError();
  if (!e.empty()) return e;
  if (!(t_end > 0) || !std::isfinite(t_end)) return "t_end = " + Num(t_end) + " must be > 0";
  if (!(dt > 0) || !std::isfinite(dt)) return "dt = " + Num(dt) + " must be > 0";
  if (max_rows < 1) return "max_rows = " + std::to_string(max_rows) + " must be >= 1";
  return "";
}

namespace {
ForcedPoint Row(const FlowPoint& z) { return {z.t, z.z[0], z.z[1], z.mode[0]}; }
}  // namespace

ForcedSimulation SimulateForced(const ForcedModel& model, const FlowPoint& start,
                                const ForcedSimulationOptions& o) {
  const std::string e = o.ValidationError();
  if (!e.empty()) throw InvalidArgument(e);
  if (!(o.t_end > start.t))
    throw InvalidArgument("t_end = " + Num(o.t_end) + " must be > the start's t = " + Num(start.t));
  // A flow of its own: `cancelled` may run another forced tool on this thread.
  Flow flow(model, o.flow);
  const double T = model.period();
  const bool strobe = o.section == ForcedSection::kStrobe;
  ForcedSimulation r;
  ForcedPoint p = Row(start);
  r.rows.push_back(p);
  r.extrema.Add(p.x, p.xdot);
  // Breakpoints: k dt and (strobe) n T, the next ones after the start.
  double k = std::floor(start.t / o.dt) + 1, n = std::ceil(start.t / T);
  while (k * o.dt <= start.t) k += 1;  // rounding: the breakpoints lie after the start
  while (n * T < start.t) n += 1;
  if (strobe && n * T == start.t) r.section.push_back({0, p}), n += 1;
  std::vector<FlowSwitch> events;
  FlowRequest rq;
  rq.extrema = {0, 1};
  rq.max_steps = o.flow.max_steps;
  rq.switches = &events;
  FlowRun run;
  while (p.t < o.t_end) {
    if (o.cancelled && o.cancelled()) {
      r.status = ForcedSimulationStatus::kCancelled;
      r.message = "cancelled at t = " + Num(p.t);
      return r;
    }
    const double t_row = k * o.dt, t_sec = strobe ? n * T : INFINITY;
    rq.t_max = std::min({t_row, t_sec, o.t_end});
    events.clear();
    flow.Run(ForcedStart(model, p.t, p.x, p.xdot, p.mode), rq, &run);
    r.steps += run.steps, r.sticks += run.sticks, r.exits += run.exits;
    r.crossings += run.crossings;
    for (const FlowSwitch& ev : events) {
      const ForcedPoint q{ev.t, ev.z[0], model.v(), ev.after[0]};
      r.rows.push_back(q);
      if (!strobe && ev.kind == SwitchKind::kStickOut)
        r.section.push_back({static_cast<long>(r.section.size()), q});
    }
    if (!Reached(run)) {
      r.status = ForcedSimulationStatus::kFailed;
      r.message = std::string(Name(run.status)) + ": " + run.message;
      return r;
    }
    r.extrema.Merge(RunExtrema(run));
    p = Row(run.end);
    if (!std::isfinite(p.x) || !std::isfinite(p.xdot)) {
      r.status = ForcedSimulationStatus::kFailed;
      r.message = "non-finite state at t = " + Num(p.t);
      return r;
    }
    if (p.t >= t_row || p.t >= o.t_end) r.rows.push_back(p), k += 1;
    if (p.t >= t_sec) r.section.push_back({static_cast<long>(r.section.size()), p}), n += 1;
    if (static_cast<long>(r.rows.size() + r.section.size()) > o.max_rows) {
      r.status = ForcedSimulationStatus::kRowLimit;
      r.message = "more than max_rows = " + std::to_string(o.max_rows) +
                  " rows and section points (rows at switches included) by t = " + Num(p.t);
      return r;
    }
  }
  return r;
}

}  // namespace stickslip
