// The one event loop (event_driver.hpp).
#include "integrate/event_driver.hpp"

#include <algorithm>
#include <cmath>

#include "numerics/stall.hpp"

namespace stickslip {
namespace {

void Emit(const SegmentOutput& out, double t, const double* y) {
  out.emit(out.context, t, y);
  ++*out.next;
}

// The events at a root: non-terminal hooks in the order of the functions;
// the roots rf[i] of terminal ones are kept, the others set to 0 (in place).
// Returns the first terminal one.
int Dispatch(const SegmentProblem& p, int* rf, const double* y, int* direction) {
  int first = -1;
  const EventList& ev = p.Events();
  for (int i = 0; i < ev.functions(); ++i) {
    const int r = rf[i];
    rf[i] = 0;
    if (r == 0) continue;
    if (p.on_event.fn && ev.Passes(i, r)) p.on_event(i, y);
    if (ev.Stops(i, r)) {
      rf[i] = r;
      if (first < 0) first = i, *direction = r;
    }
  }
  return first;
}

// Whether a root at the stepper's (re)start is an event: only a terminal
// event that counts at the start (Event::at_start).
bool CountsAtStart(const SegmentProblem& p, const int* rf) {
  const EventList& ev = p.Events();
  for (int i = 0; i < ev.functions(); ++i)
    if (rf[i] != 0 && ev.AtStart(i, rf[i])) return true;
  return false;
}

}  // namespace

long FirstSample(double origin, double dt, double t) {
  const double tol = Tolerances::OutputAtStart(t);
  long k = static_cast<long>(std::max(0.0, std::ceil((t - tol - origin) / dt)));
  while (k > 0 && origin + (k - 1) * dt >= t - tol) --k;  // ceil's rounding, either way
  while (origin + k * dt < t - tol) ++k;
  return k;
}

SegmentEnd RunSegment(Stepper& cv, const SegmentProblem& problem, double t0, const double* y0,
                      double t_max, const SegmentOutput& out, std::vector<int>* roots) {
  cv.Reset(problem, t0, y0);
  const size_t nf = static_cast<size_t>(problem.Events().functions());
  // The stepper's root flags in *roots itself (Dispatch keeps the terminal
  // ones): no buffer of its own per segment.
  if (roots->size() != nf) roots->resize(nf);
  std::fill(roots->begin(), roots->end(), 0);
  int* rfp = roots->data();
  SegmentEnd end;
  // A finite stop time (CVODE's), extended in chunks until t_max.
  end.t_end = std::min(t_max, t0 + Tolerances::kStopTimeChunk);
  cv.SetStopTime(end.t_end);
  // A segment that starts at an output time (a switch there, to rounding) has
  // that sample already: the switch's.
  const bool sampling = out.on();
  while (sampling && out.at() <= t0 + Tolerances::OutputAtStart(t0)) ++*out.next;
  // Each root function fires once per instant (two repeats per function).
  RootRepeats repeats(2 * std::max(static_cast<int>(nf), 3));
  auto done = [&](SegmentEnd::Kind kind, double t) {
    end.kind = kind;
    end.t = t;
    end.y = cv.y();
    return end;
  };
  for (;;) {
    const double tout = sampling ? std::min(out.at(), end.t_end) : end.t_end;
    double t = t0;
    const StepOutcome flag = cv.Advance(tout, &t);
    if (flag == StepOutcome::kCancelled || (problem.cancel && (*problem.cancel)()))
      return done(SegmentEnd::kCancelled, t);
    if (flag == StepOutcome::kTooMuchWork) return done(SegmentEnd::kTooMuchWork, t);
    if (flag == StepOutcome::kFailed) {
      end.reason = cv.last_error().c_str();
      return done(SegmentEnd::kFailed, cv.CurrentTime());
    }
    if (flag == StepOutcome::kRoot) {
      cv.RootInfo(rfp);
      if (repeats.Stuck(t)) {
        end.reason = "events repeat at this time without progress";
        return done(SegmentEnd::kFailed, t);
      }
      // A root exactly at an output time: report the sample, or the next
      // call would ask for tout = t.
      if (sampling && t >= out.at()) Emit(out, t, cv.y());
      // A start on a root surface holds only to rounding: a root there is not
      // an event, unless an event says it counts at the start.
      const double start = cv.SegmentStart();
      if (t - start <= Tolerances::EventAtStart(start) && !CountsAtStart(problem, rfp)) continue;
      end.g = Dispatch(problem, rfp, cv.y(), &end.direction);
      if (end.g >= 0) return done(SegmentEnd::kEvent, t);
      continue;
    }
    if (t >= end.t_end && end.t_end < t_max) {  // the next chunk
      end.t_end = std::min(t_max, end.t_end + Tolerances::kStopTimeChunk);
      cv.SetStopTime(end.t_end);
      continue;
    }
    if (t >= end.t_end) return done(SegmentEnd::kTime, t);
    if (sampling) Emit(out, t, cv.y());  // an output time
  }
}

}  // namespace stickslip
