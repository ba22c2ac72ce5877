// The forced oscillator's points on the one flow (flow/flow.hpp): ForcedBelt
// is a system with the phase theta = Omega t, so a run of it is a Flow::Run
// from a ForcedStart.
#pragma once

#include "stickslip/flow/flow.hpp"
#include "stickslip/integrate/extrema.hpp"
#include "stickslip/systems/forced/forced.hpp"

namespace stickslip {

/// The forced oscillator's state at time t as a start of the one flow: (x, x',
/// theta = Omega t) with Filippov's mode: slip by the sign of x' - v; on x' = v
/// stick inside the band, else the slip side the force points to.
FlowPoint ForcedStart(const ForcedBelt& m, double t, double x, double xdot);
/// The same in a given mode (trusted; x' = v in stick).
FlowPoint ForcedStart(const ForcedBelt& m, double t, double x, double xdot, Mode mode);

/// A run's extremes of x and x' (FlowRequest::extrema = {0, 1}; ExtremaOf).
inline Extrema RunExtrema(const FlowRun& r) { return ExtremaOf(r.lo, r.hi); }

/// A run of the forced model reached its end: the time or the requested stick exit.
inline bool Reached(const FlowRun& r) {
  return r.status == FlowStatus::kTimeLimit || r.status == FlowStatus::kStickExit;
}

}  // namespace stickslip
