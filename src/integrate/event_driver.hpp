// Private to src/: the one event loop of a smooth integration segment. A
// stepper only steps; the driver runs it to the segment's stop time, emits
// the output samples, and dispatches its roots to the problem's events
// (events.hpp): a terminal event ends the segment, a non-terminal one calls
// its hook and the segment goes on (heyoka's model).
#pragma once

#include <functional>

#include "integrate/stepper.hpp"

namespace stickslip {

struct SegmentEnd {
  enum Kind {
    kEvent,        // terminal events on the functions with roots[g] != 0
    kTime,         // reached the stop time
    kTooMuchWork,  // max_steps steps without reaching an output or the stop
    kFailed,       // the stepper failed, or roots repeat without progress; `reason`
    kCancelled,    // the cancel hook returned true
  } kind = kTime;
  // kEvent: the terminal functions that fired, with their directions (the
  // first listed in g, direction).
  int g = -1, direction = 0;
  double t = 0;
  double t_end = 0;           // the stop time in force when it ended
  const double* y = nullptr;  // the stepper's state at t (until its next call)
  const char* reason = "";    // kFailed: why (the stepper's, until its next call)
};

// The output samples of a segment: at origin + k dt from k = *next (advanced
// past the samples emitted). A product, not a running sum: sample n is
// origin + n dt to rounding however long the run.
struct SegmentOutput {
  double dt = 0;
  double origin = 0;
  long* next = nullptr;
  void (*emit)(void* context, double t, const double* y) = nullptr;
  void* context = nullptr;
  bool on() const { return dt > 0 && emit; }
  double at() const { return origin + static_cast<double>(*next) * dt; }
};

// The first k with origin + k dt at or after t (to OutputAtStart's rounding).
long FirstSample(double origin, double dt, double t);

// Integrates problem's field from (t0, y0) until a terminal event or t_max.
// Roots that no event asks for are passed. *roots (one per function) holds
// the terminal roots of a kEvent end (after another end: the last roots
// the stepper reported).
SegmentEnd RunSegment(Stepper& cv, const SegmentProblem& problem, double t0, const double* y0,
                      double t_max, const SegmentOutput& out, std::vector<int>* roots);

}  // namespace stickslip
