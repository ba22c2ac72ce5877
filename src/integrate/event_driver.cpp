// The event loop's helpers (event_driver.hpp), and its instance for the
// belt's steppers.
#include "integrate/event_driver.hpp"

namespace stickslip {
namespace event_detail {

void Emit(const SegmentOutput& out, Mode mode, double t, const double* y) {
  (*out.observer)(Sample{t, Vec2(y[0], y[1]), mode});
  *out.next += out.dt;
}

}  // namespace event_detail

template SegmentEnd RunSegment<Stepper, SlipProblem>(Stepper&, const SlipProblem&, double,
                                                     const double*, double, const SegmentOutput&);

}  // namespace stickslip
