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

Extrema ExtremaOf(const Eigen::VectorXd& lo, const Eigen::VectorXd& hi) {
  return lo.size() >= 2 && hi.size() >= 2 ? Extrema{lo[0], hi[0], lo[1], hi[1]} : Extrema::Empty();
}

}  // namespace stickslip
