// Private to src/: the one event loop of a smooth integration segment. A
// stepper (stepper.hpp: Taylor or CVODE) only steps; the driver runs it to
// the segment's stop time, emits the output samples, and dispatches its roots
// to the problem's events (events.hpp): a terminal event ends the segment, a
// non-terminal one calls its hook and the segment goes on (heyoka's model).
#pragma once

#include <string>

#include "integrate/stepper.hpp"

namespace stickslip {

struct SegmentEnd {
  enum Kind {
    kEvent,        // a terminal event on root function `g`, direction `direction`
    kTime,         // reached the stop time
    kTooMuchWork,  // max_steps steps without reaching an output or the stop
    kFailed,       // the stepper failed, or roots repeat without progress; `reason`
    kCancelled,    // the cancel hook returned true
  } kind = kTime;
  int g = -1, direction = 0;
  double t = 0;
  double t_end = 0;           // the stop time in force when it ended
  const double* y = nullptr;  // the stepper's state at t (until its next call)
  std::string reason;
};

// The output samples of a segment: every dt from *next (advanced past the
// samples emitted), in the problem's mode. dt <= 0 or no observer: none.
struct SegmentOutput {
  double dt = 0;
  double* next = nullptr;
  const Observer* observer = nullptr;
  bool on() const { return dt > 0 && observer && *observer; }
};

// Integrates problem's field from (t0, y0) until a terminal event or t_max.
// Roots of the stepper's functions that no event asks for are passed.
SegmentEnd RunSegment(Stepper& stepper, const SlipProblem& problem, double t0, const double* y0,
                      double t_max, const SegmentOutput& out);

}  // namespace stickslip
