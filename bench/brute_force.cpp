#include "brute_force.hpp"

#include <cmath>

namespace bench {

BruteCycle BruteForce(const stickslip::Params& p, const BruteOptions& o) {
  using stickslip::FlowResult;
  using stickslip::FlowStatus;
  const stickslip::Model model(p);
  stickslip::BeltFlow flow(model, o.flow);
  stickslip::StopRule stop;
  stop.at_section = true;  // every maximum of x: x' = 0 downwards
  stop.t_max = o.t_cap;
  BruteCycle c;
  // From rest to the first maximum of x: the transient starts here.
  FlowResult r = flow.Run(0.0, stickslip::Vec2(0.0, 0.0), stop);
  double prev_period = NAN, prev_x = NAN;
  double t_last = r.t;
  while (r.ok() && r.status == FlowStatus::kSection) {
    // One more cycle from the maximum just reached (an event at t0 is none).
    r = flow.Run(t_last, r.z, r.mode, stop, false);
    if (!r.ok() || r.status != FlowStatus::kSection) break;
    ++c.cycles;
    c.period = r.t - t_last;
    c.x_max = r.extrema.x_max;
    c.x_min = r.extrema.x_min;
    c.xdot_max = r.extrema.xdot_max;
    c.t_stick = r.t_stick;
    c.ok = true;
    t_last = r.t;
    if (c.cycles >= o.min_cycles && std::abs(c.period - prev_period) <= o.converge_tol * c.period &&
        std::abs(c.x_max - prev_x) <= o.converge_tol) {
      c.converged = true;
      break;
    }
    prev_period = c.period;
    prev_x = c.x_max;
  }
  if (!r.ok()) {
    c.ok = false;
    c.message = r.message;
  } else if (!c.ok) {
    c.message = "fewer than two maxima of x before t = " + std::to_string(o.t_cap);
  }
  c.t_end = t_last;
  c.steps = flow.total_steps();
  return c;
}

}  // namespace bench
