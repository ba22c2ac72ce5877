// Private to src/: the one event loop of a smooth integration segment. A
// stepper only steps; the driver runs it to the segment's stop time, emits
// the output samples, and dispatches its roots to the problem's events
// (events.hpp): a terminal event ends the segment, a non-terminal one calls
// its hook and the segment goes on (heyoka's model). The loop is a template
// on the stepper and its problem (a SegmentProblem): the belt's steppers
// (stepper.hpp: Taylor, CVODE, behind Stepper) and the forced oscillator's
// (forced/forced_stepper.hpp) run through this one loop.
#pragma once

#include <algorithm>
#include <cmath>

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
  const char* reason = "";    // kFailed: why (the stepper's, until its next call)
};

// The output samples of a segment: every dt from *next (advanced past the
// samples emitted), in the problem's mode. dt <= 0 or no observer: none.
struct SegmentOutput {
  double dt = 0;
  double* next = nullptr;
  const Observer* observer = nullptr;
  bool on() const { return dt > 0 && observer && *observer; }
};

namespace event_detail {
// Each root function fires once per instant: roots that keep coming at one t,
// to rounding (steps of zero or rounding length, each resetting the stepper's
// step count), would loop for ever, so they are a failure that says where.
struct RootRepeats {
  double t = NAN;  // where the run of repeats began
  int count = 0;
  bool Stuck(double t_root) {
    const bool same = std::abs(t_root - t) <= Tolerances::RootRepeat(t);
    count = same ? count + 1 : 0;
    if (!same) t = t_root;
    return count > 2 * kNumRoots;
  }
};
inline void Emit(const SegmentOutput& out, Mode mode, double t, const double* y) {
  (*out.observer)(Sample{t, Vec2(y[0], y[1]), mode});
  *out.next += out.dt;
}
// The events at a root: non-terminal hooks in the order of the functions,
// until the first terminal event (it ends the segment: returns its g).
inline int Dispatch(const SegmentProblem& p, const int* rf, const double* y, int* direction) {
  for (int i = 0; i < kNumRoots; ++i) {
    if (rf[i] == 0) continue;
    if (p.on_event.fn && p.Passes(i, rf[i])) p.on_event(i, y);
    if (p.Stops(i, rf[i])) {
      *direction = rf[i];
      return i;
    }
  }
  return -1;
}
// Whether a root at the stepper's (re)start is an event: only a terminal
// event that counts at the start (Event::at_start).
inline bool CountsAtStart(const SegmentProblem& p, const int* rf) {
  for (int i = 0; i < kNumRoots; ++i)
    if (rf[i] != 0 && p.events.AtStart(i, rf[i])) return true;
  return false;
}
}  // namespace event_detail

// Integrates problem's field from (t0, y0) until a terminal event or t_max.
// Roots of the stepper's functions that no event asks for are passed. S has
// Stepper's calls (stepper.hpp) with Reset taking a P; P is a SegmentProblem.
template <class S, class P>
SegmentEnd RunSegment(S& cv, const P& problem, double t0, const double* y0, double t_max,
                      const SegmentOutput& out) {
  using namespace event_detail;
  const SegmentProblem& events = problem;
  cv.Reset(problem, t0, y0);
  SegmentEnd end;
  // A finite stop time (CVODE's), extended in chunks until t_max.
  end.t_end = std::min(t_max, t0 + Tolerances::kStopTimeChunk);
  cv.SetStopTime(end.t_end);
  // A segment that starts at an output time (a switch there, to rounding) has
  // that sample already: the switch's.
  const bool sampling = out.on();
  while (sampling && *out.next <= t0 + Tolerances::OutputAtStart(t0)) *out.next += out.dt;
  RootRepeats repeats;
  auto done = [&](SegmentEnd::Kind kind, double t) {
    end.kind = kind;
    end.t = t;
    end.y = cv.y();
    return end;
  };
  for (;;) {
    const double tout = sampling ? std::min(*out.next, end.t_end) : end.t_end;
    double t = t0;
    const StepOutcome flag = cv.Advance(tout, &t);
    if (flag == StepOutcome::kCancelled || (events.cancel && (*events.cancel)()))
      return done(SegmentEnd::kCancelled, t);
    if (flag == StepOutcome::kTooMuchWork) return done(SegmentEnd::kTooMuchWork, t);
    if (flag == StepOutcome::kFailed) {
      end.reason = cv.last_error().c_str();
      return done(SegmentEnd::kFailed, cv.CurrentTime());
    }
    if (flag == StepOutcome::kRoot) {
      int rf[kNumRoots];
      cv.RootInfo(rf);
      if (repeats.Stuck(t)) {
        end.reason = "events repeat at this time without progress";
        return done(SegmentEnd::kFailed, t);
      }
      // A root exactly at an output time: report the sample, or the next
      // call would ask for tout = t.
      if (sampling && t >= *out.next) Emit(out, events.mode, t, cv.y());
      // A start on a root surface holds only to rounding: a root there is not
      // an event, unless an event says it counts at the start.
      const double start = cv.SegmentStart();
      if (t - start <= Tolerances::EventAtStart(start) && !CountsAtStart(events, rf)) continue;
      end.g = Dispatch(events, rf, cv.y(), &end.direction);
      if (end.g >= 0) return done(SegmentEnd::kEvent, t);
      continue;
    }
    if (t >= end.t_end && end.t_end < t_max) {  // the next chunk
      end.t_end = std::min(t_max, end.t_end + Tolerances::kStopTimeChunk);
      cv.SetStopTime(end.t_end);
      continue;
    }
    if (t >= end.t_end) return done(SegmentEnd::kTime, t);
    if (sampling) Emit(out, events.mode, t, cv.y());  // an output time
  }
}

// The belt's steppers, behind Stepper (event_driver.cpp).
extern template SegmentEnd RunSegment<Stepper, SlipProblem>(Stepper&, const SlipProblem&, double,
                                                            const double*, double,
                                                            const SegmentOutput&);

}  // namespace stickslip
