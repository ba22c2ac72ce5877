// Private to src/: the seam between the event loop (event_driver.hpp) and the
// integrators of one mode. A stepper only steps: it integrates the state (and,
// with variational equations, Phi and the parameter column) on the smooth
// field of one mode of a system, and reports the roots of the segment's event
// functions (events.hpp) in CVODE's convention (CVodeGetRootInfo): +1 where
// g rises through 0, -1 where it falls, 0 for no root.
#pragma once

#include <cmath>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "integrate/events.hpp"
#include "numerics/tolerances.hpp"
#include "stickslip/flow/flow_options.hpp"
#include "stickslip/system/system.hpp"
#include "stickslip/system/taylor_field.hpp"

namespace stickslip {

// v.size() >= n, its entries kept (per-segment buffers grow, never shrink:
// alternating modes reuse them).
template <class T>
inline void AtLeast(std::vector<T>& v, size_t n) {
  if (v.size() < n) v.resize(n);
}

// A step end the stepper shows: each Taylor step's, CVODE's returns only.
struct StepHook {
  void (*fn)(void* context, double t, const double* y) = nullptr;
  void* context = nullptr;
  void operator()(double t, const double* y) const { fn(context, t, y); }
};

// One mode of a system: the events, hooks and cancel hook (the loop's part),
// and what the steppers need of the system.
struct SegmentProblem {
  const System* system = nullptr;
  // Changes whenever the system's values may have (the Taylor field is bound
  // again); -1: always bind.
  long system_epoch = -1;
  ModeSet mode;
  // A key of the mode, its events and the layout: a stepper Reset with the
  // same key (>= 0) and system epoch as at its last Reset keeps its binding
  // and sizes, and only restarts (-1: never assume so).
  long setup = -1;
  int contacts = 1;
  double rtol = 0, atol = 0;
  TaylorLayout layout;                            // state, Phi, column; aux rows are the field's
  const std::function<bool()>* cancel = nullptr;  // polled after every step, if set
  // The segment's events: `events`, or the list `shared` points to (the
  // flow's per-mode lists, used in place: no copy or swap per segment).
  EventList events;
  const EventList* shared = nullptr;
  const EventList& Events() const { return shared ? *shared : events; }
  EventHook on_event{};  // every non-terminal event a stepper passes
  StepHook on_step{};    // every step end (not one cut at a terminal root)
  // Clocks (System::clocks, the last state rows) as exact functions of t:
  // theta = rate t + offset (no drift from summing steps: theta = Omega t
  // exactly for a forcing started at theta = Omega t0). One per clock.
  const double* clock_rate = nullptr;
  const double* clock_offset = nullptr;
  // At rest to within the integration noise, the mode's equilibrium: its
  // components with a derivative in the state (DerivativeOf) are positions.
  bool has_rest = false;
  std::vector<int> derivative_of;  // DerivativeOf(i) per state component
  double rest_speed = 0;           // the largest contact speed |s_i|
  // Whether the state rows y (coefficient 0) and their rates (coefficient 1,
  // rate[i]) lie in the noise band of rest: |x'| ~ atol, |x''| ~ rtol scale.
  bool AtRest(const double* y, const double* rate) const {
    return AtRestBy([y](int i) { return y[i]; }, [rate](int i) { return rate[i]; });
  }
  // The same with y(i) and rate(i) as callables (a stepper's rows).
  template <class Y, class R>
  bool AtRestBy(Y y, R rate) const {
    double scale = 1.0 + rest_speed;
    for (int i = 0; i < layout.tangent; ++i)
      if (derivative_of[i] >= 0) scale += std::abs(y(i));
    const double band_v = Tolerances::RestBandVelocity(scale, atol);
    const double band_a = Tolerances::RestBandAcceleration(scale, rtol, atol);
    for (int i = 0; i < layout.tangent; ++i)
      if (std::abs(rate(i)) > (derivative_of[i] >= 0 ? band_v : band_a)) return false;
    return true;
  }
};

enum class StepOutcome {
  kReached,      // reached tout or the stop time
  kRoot,         // stopped at a root of a terminal event (CVODE: of any g); RootInfo says which
  kTooMuchWork,  // max_steps steps without reaching tout
  kFailed,       // an error; last_error() says which
  kCancelled,    // the cancel hook returned true after a step
};

class Stepper {
 public:
  virtual ~Stepper() = default;
  // Restart at (t0, y0) on problem's field; y0 has size() entries (the
  // layout's rows up to the auxiliary ones).
  virtual void Reset(const SegmentProblem& problem, double t0, const double* y0) = 0;
  virtual void SetStopTime(double t) = 0;
  // Integrate towards tout; *t is where it stopped, with state y().
  virtual StepOutcome Advance(double tout, double* t) = 0;
  virtual const double* y() const = 0;
  // One entry per event function of the problem.
  virtual void RootInfo(int* roots_found) const = 0;
  // The stepper's own time (also after a failure).
  virtual double CurrentTime() = 0;
  // Where the stepper last (re)started: Reset's t0, or a restart of its own.
  virtual double SegmentStart() const = 0;
  virtual long steps() const = 0;  // since the last Reset
  // Their orders, since the last Reset (none: not a Taylor stepper).
  virtual TaylorOrders orders() const { return {}; }
  virtual int size() const = 0;
  virtual const std::string& last_error() const = 0;
};

// The stepper options.integrator names for a system, for the layout's rows.
// parameter: the column's parameter index (Taylor only).
std::unique_ptr<Stepper> MakeStepper(const FlowOptions& options, const System& system,
                                     bool variational, std::optional<int> parameter);

}  // namespace stickslip
