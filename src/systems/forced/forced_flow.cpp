// The forced oscillator's points on the one flow (systems/forced/flow.hpp): the state
// (x, x', theta = Omega t) of ForcedBelt.
#include "stickslip/systems/forced/flow.hpp"

namespace stickslip {

FlowPoint ForcedStart(const ForcedBelt& m, double t, double x, double xdot) {
  Mode mode = Mode::kSlipBelow;
  if (xdot > m.v()) mode = Mode::kSlipAbove;
  if (xdot == m.v()) mode = m.InStickBand(t, x) ? Mode::kStick : m.ExitMode(t, x);
  return ForcedStart(m, t, x, xdot, mode);
}

FlowPoint ForcedStart(const ForcedBelt& m, double t, double x, double xdot, Mode mode) {
  return {t, Eigen::Vector3d(x, mode == Mode::kStick ? m.v() : xdot, m.omega() * t), ModeSet(mode)};
}

}  // namespace stickslip
