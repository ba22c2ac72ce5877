// The forced oscillator's points on the one flow (forced/flow.hpp): the state
// (x, x', theta = Omega t) of ForcedModel.
#include "stickslip/forced/flow.hpp"

namespace stickslip {

FlowPoint ForcedStart(const ForcedModel& m, double t, double x, double xdot) {
  Mode mode = Mode::kSlipBelow;
  if (xdot > m.v()) mode = Mode::kSlipAbove;
  if (xdot == m.v()) mode = m.InStickBand(t, x) ? Mode::kStick : m.ExitMode(t, x);
  return ForcedStart(m, t, x, xdot, mode);
}

FlowPoint ForcedStart(const ForcedModel& m, double t, double x, double xdot, Mode mode) {
  return {t, Eigen::Vector3d(x, mode == Mode::kStick ? m.v() : xdot, m.omega() * t), ModeSet(mode)};
}

Extrema RunExtrema(const FlowRun& r) {
  return r.lo.size() >= 2 && r.hi.size() >= 2 ? Extrema{r.lo[0], r.hi[0], r.lo[1], r.hi[1]}
                                              : Extrema::Empty();
}

}  // namespace stickslip
