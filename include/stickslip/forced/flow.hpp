// The forced oscillator's points (t, x, x', mode) on the one flow
// (flow/flow.hpp): ForcedModel is a system with the phase theta = Omega t, so
// a run of it is a Flow::Run from ToFlowPoint; these convert its points.
#pragma once

#include "stickslip/flow/flow.hpp"
#include "stickslip/integrate/extrema.hpp"
#include "stickslip/model/forced.hpp"

namespace stickslip {

/// A point of the forced flow: time, state and mode (kStick has x' = v).
struct ForcedPoint {
  double t = 0, x = 0, xdot = 0;
  Mode mode = Mode::kSlipBelow;
};
/// The mode of (x, x') at time t: slip by the sign of x' - v; on x' = v stick
/// inside the band, else the slip side the force points to.
ForcedPoint ForcedStart(const ForcedModel& m, double t, double x, double xdot);

/// The forced point as the one flow's start (x, x', theta = Omega t; x' = v
/// in stick), and a flow point as a forced point (contact 0's mode).
FlowPoint ToFlowPoint(const ForcedModel& m, const ForcedPoint& p);
ForcedPoint ToForcedPoint(const FlowPoint& p);

/// The extremes of x and x' of a run that recorded them (FlowRequest::extrema
/// = {0, 1}), else Extrema::Empty().
Extrema RunExtrema(const FlowRun& r);

/// A run of the forced model reached its end: the time or the requested stick exit.
inline bool Reached(const FlowRun& r) {
  return r.status == FlowStatus::kTimeLimit || r.status == FlowStatus::kStickExit;
}

}  // namespace stickslip
