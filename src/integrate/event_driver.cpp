// The event loop's instance for the belt's steppers (event_driver.hpp).
#include "integrate/event_driver.hpp"

namespace stickslip {

template SegmentEnd RunSegment<Stepper, SlipProblem>(Stepper&, const SlipProblem&, double,
                                                     const double*, double, const SegmentOutput&);

}  // namespace stickslip
