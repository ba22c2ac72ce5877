// The forced oscillator's points on the one flow (forced/flow.hpp): the state
// (x, x', theta = Omega t) of ForcedModel, and back.
#include "stickslip/forced/flow.hpp"

namespace stickslip {

ForcedPoint ForcedStart(const ForcedModel& m, double t, double x, double xdot) {
  ForcedPoint p{t, x, xdot, Mode::kSlipBelow};
  if (xdot > m.v()) p.mode = Mode::kSlipAbove;
  if (xdot == m.v()) p.mode = m.InStickBand(t, x) ? Mode::kStick : m.ExitMode(t, x);
  return p;
}

FlowPoint ToFlowPoint(const ForcedModel& m, const ForcedPoint& p) {
  return {p.t, Eigen::Vector3d(p.x, p.mode == Mode::kStick ? m.v() : p.xdot, m.omega() * p.t),
          ModeSet(p.mode)};
}

ForcedPoint ToForcedPoint(const FlowPoint& p) { return {p.t, p.z[0], p.z[1], p.mode[0]}; }

Extrema RunExtrema(const FlowRun& r) {
  return r.lo.size() >= 2 && r.hi.size() >= 2 ? Extrema{r.lo[0], r.hi[0], r.lo[1], r.hi[1]}
                                              : Extrema::Empty();
}

}  // namespace stickslip
