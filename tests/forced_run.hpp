// A run of the forced oscillator on the one flow for the tests: from a forced
// point (systems/forced/flow.hpp) to t_end, with the forced flow's defaults and the
// extremes of x and x' recorded.
#pragma once

#include <vector>

#include "stickslip/systems/forced/flow.hpp"

namespace stickslip::testing_util {

inline FlowRun RunForced(const ForcedBelt& m, const FlowPoint& start, double t_end,
                         FlowRequest rq = {}, const FlowOptions& o = ForcedBelt::FlowDefaults()) {
  rq.t_max = t_end;
  if (rq.extrema.empty()) rq.extrema = {0, 1};
  if (rq.max_steps == 0) rq.max_steps = o.max_steps;
  return Flow(m, o).Run(start, rq);
}

/// The switches of such a run.
inline std::vector<FlowSwitch> RunSwitches(const ForcedBelt& m, const FlowPoint& start,
                                           double t_end,
                                           const FlowOptions& o = ForcedBelt::FlowDefaults()) {
  std::vector<FlowSwitch> switches;
  FlowRequest rq;
  rq.switches = &switches;
  RunForced(m, start, t_end, rq, o);
  return switches;
}

}  // namespace stickslip::testing_util
