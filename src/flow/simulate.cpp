// A streamed trajectory of any system (flow/simulate.hpp): one flow run to
// t_end, or, for the stroboscopic section, one run per period, each stopping
// exactly on t = n period and continuing the same output grid.
#include "stickslip/flow/simulate.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "numerics/numbers.hpp"
#include "stickslip/errors.hpp"

namespace stickslip {

std::string SimulationOptions::ValidationError() const {
  const std::string e = flow.ValidationError();
  if (!e.empty()) return e;
  if (!(t_end > 0) || !std::isfinite(t_end))
    return "t_end = " + Num(t_end) + " must be a finite number > 0";
  if (!(dt > 0) || !std::isfinite(dt)) return "dt = " + Num(dt) + " must be a finite number > 0";
  if (section == SimulationSection::kStrobe && (!(period > 0) || !std::isfinite(period)))
    return "period = " + Num(period) + " must be a finite number > 0 for the stroboscopic section";
  if (max_rows < 1) return "max_rows = " + std::to_string(max_rows) + " must be >= 1";
  return "";
}

namespace {

bool Finite(double t, const double* z, int n) {
  if (!std::isfinite(t)) return false;
  for (int i = 0; i < n; ++i)
    if (!std::isfinite(z[i])) return false;
  return true;
}

// The run's bookkeeping: counts the rows against max_rows, and stops the
// flow (through its cancel hook) at a non-finite state or a full table.
struct Stream {
  Stream(const SimulationOptions& o, const SimulationSink& sink, int n, Simulation& r)
      : o(o), sink(sink), n(n), r(r) {}
  const SimulationOptions& o;
  const SimulationSink& sink;
  const int n;
  Simulation& r;
  std::vector<FlowSwitch> switches;
  std::string stop;  // why the stream stopped the flow, with where
  SimulationStatus stop_status = SimulationStatus::kComplete;

  double last_t = std::numeric_limits<double>::quiet_NaN();
  Eigen::VectorXd last_z;
  ModeSet last_mode;

  bool Stopped() const { return !stop.empty(); }
  // The simulation ends where the stream stopped the flow.
  void End(Simulation* out) const { out->status = stop_status, out->message = stop; }
  // A point given twice (a switch on an output time, say) is one row.
  bool Repeats(double t, const double* z, const ModeSet& m) {
    const Eigen::Map<const Eigen::VectorXd> zz(z, n);
    if (t == last_t && m == last_mode && zz == last_z) return true;
    last_t = t, last_z = zz, last_mode = m;
    return false;
  }
  bool Take(double t, const double* z) {
    if (Stopped()) return false;
    if (!Finite(t, z, n)) {
      stop = "non-finite state at t = " + Num(t), stop_status = SimulationStatus::kFailed;
      return false;
    }
    if (r.rows + r.section_points >= o.max_rows) {
      stop = "more than max_rows = " + std::to_string(o.max_rows) +
             " rows and section points (rows at switches included) by t = " + Num(t);
      stop_status = SimulationStatus::kRowLimit;
      return false;
    }
    return true;
  }
  void Row(double t, const double* z, const ModeSet& m) {
    if (Repeats(t, z, m) || !Take(t, z)) return;
    ++r.rows;
    if (sink.row) sink.row(t, z, m);
    for (const FlowSwitch& s : switches)  // the switches at this row (Record's order)
      if (s.kind == SwitchKind::kStickOut) Section(s.t, s.z.data(), s.after);
    switches.clear();
  }
  void Section(double t, const double* z, const ModeSet& m) {
    if (!Take(t, z)) return;
    if (sink.section) sink.section(r.section_points, t, z, m);
    ++r.section_points;
  }
};

// One flow run's counts, extremes and end into the simulation's.
void Add(const FlowRun& run, const SimulationOptions& o, int n, Simulation* r) {
  r->steps += run.steps, r->sticks += run.sticks, r->exits += run.exits;
  r->crossings += run.crossings, r->switches += run.switches, r->t_stick += run.t_stick;
  r->flow = run.status;
  if (Finite(run.end.t, run.end.z.data(), n)) r->end = run.end;
  for (std::size_t i = 0; i < o.extrema.size(); ++i)
    r->lo[i] = std::min(r->lo[i], run.lo[i]), r->hi[i] = std::max(r->hi[i], run.hi[i]);
}

// The run's end after one flow run; false if the simulation ends here.
bool Continues(const FlowRun& run, Stream& st, Simulation& r) {
  if (st.Stopped()) {
    st.End(&r);
    return false;
  }
  if (run.status == FlowStatus::kContactOpen) {
    r.status = SimulationStatus::kContactOpen, r.opened = run.opened;
    r.message = "contact " + std::to_string(run.opened) + " opens at t = " + Num(run.end.t);
    return false;
  }
  if (run.status == FlowStatus::kTimeLimit) return true;
  r.status = run.status == FlowStatus::kCancelled ? SimulationStatus::kCancelled
                                                  : SimulationStatus::kFailed;
  r.message = run.status == FlowStatus::kCancelled
                  ? run.message
                  : std::string(Name(run.status)) + ": " + run.message;
  return false;
}

}  // namespace

Simulation Simulate(const System& system, const FlowPoint& start, const SimulationOptions& o,
                    const SimulationSink& sink) {
  const std::string e = o.ValidationError();
  if (!e.empty()) throw InvalidArgument(e);
  if (!(o.t_end > start.t))
    throw InvalidArgument("t_end = " + Num(o.t_end) + " must be > the start's t = " + Num(start.t));
  Flow flow(system, o.flow);  // its own: `cancelled` may run another tool on this thread
  Simulation r;
  r.end = start;
  const double inf = std::numeric_limits<double>::infinity();
  r.lo = Eigen::VectorXd::Constant(o.extrema.size(), inf);
  r.hi = Eigen::VectorXd::Constant(o.extrema.size(), -inf);
  Stream st(o, sink, system.dimension(), r);
  flow.set_cancel([&] { return st.Stopped() || (o.cancelled && o.cancelled()); });
  FlowRequest rq;
  rq.output_dt = o.dt;
  rq.output_origin = start.t;
  rq.extrema = o.extrema;
  rq.observer = [&st](double t, const double* z, const ModeSet& m) { st.Row(t, z, m); };
  if (o.section == SimulationSection::kExit) rq.switches = &st.switches;
  const bool strobe = o.section == SimulationSection::kStrobe;
  double n = strobe ? std::ceil(start.t / o.period) : 0;
  while (strobe && n * o.period < start.t) n += 1;
  if (strobe && n * o.period == start.t) st.Section(start.t, start.z.data(), start.mode), n += 1;
  rq.stop_after_switches = o.flow.max_switches;  // a bound per output interval, below
  FlowRun run;
  FlowPoint p = start;
  for (;;) {
    const double t_sec = strobe ? n * o.period : inf;
    const bool last = !(t_sec < o.t_end);
    rq.t_max = last ? o.t_end : t_sec;
    rq.output_end = last;
    const double t0 = p.t;
    flow.Run(p, rq, &run);
    rq.output_index = run.output_index;  // the next run goes on on the same grid
    Add(run, o, system.dimension(), &r);
    if (run.status == FlowStatus::kSwitchCount && !st.Stopped()) {
      if (!(run.end.t - t0 > o.dt)) {  // Zeno-like: FlowOptions::max_switches within one dt
        r.status = SimulationStatus::kFailed;
        r.message =
            "too-many-switches: more than max_switches = " + std::to_string(o.flow.max_switches) +
            " mode changes between t = " + Num(t0) + " and " + Num(run.end.t) +
            ", within one output interval";
        return r;
      }
      p = run.end;
      continue;
    }
    if (!Continues(run, st, r)) return r;
    p = run.end;
    if (!last || t_sec == o.t_end) st.Section(p.t, p.z.data(), p.mode);  // t = n T, t_end's too
    if (st.Stopped()) {
      st.End(&r);
      return r;
    }
    if (last) return r;
    n += 1;
  }
}

}  // namespace stickslip
