// The event loop's helpers (event_driver.hpp), and its instance for the
// belt's steppers.
#include "integrate/event_driver.hpp"

namespace stickslip {
namespace event_detail {

void Emit(const SegmentOutput& out, Mode mode, double t, const double* y) {
  (*out.observer)(Sample{t, Vec2(y[0], y[1]), mode});
  *out.next += out.dt;
}

int Dispatch(const SegmentProblem& p, const int* rf, const double* y, int* direction) {
  for (int i = 0; i < kNumRoots; ++i) {
    if (rf[i] == 0) continue;
    if (p.on_event.fn && p.events.NonTerminal(i, rf[i])) p.on_event(i, y);
    if (p.events.Terminal(i, rf[i])) {
      *direction = rf[i];
      return i;
    }
  }
  return -1;
}

bool CountsAtStart(const SegmentProblem& p, const int* rf) {
  for (int i = 0; i < kNumRoots; ++i)
    if (rf[i] != 0 && p.events.AtStart(i, rf[i])) return true;
  return false;
}

}  // namespace event_detail

template SegmentEnd RunSegment<Stepper, SlipProblem>(Stepper&, const SlipProblem&, double,
                                                     const double*, double, const SegmentOutput&);

}  // namespace stickslip
