// Exact simulation of the forced friction oscillator (issue 20, item 1):
// Taylor steps on each slip field with cos/sin recurrences, stick phases whose
// exit is a root in t of |x + 2 beta v - A cos(Omega t)| = mu_s, events as
// roots of the step polynomials (none missed: Bernstein bounds, isolation,
// Newton), and the state transition matrix with saltation at every switch.
#pragma once

#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "stickslip/flow/flow.hpp"
#include "stickslip/integrate/extrema.hpp"
#include "stickslip/model/forced.hpp"
#include "stickslip/names.hpp"

namespace stickslip {

/// A point of the forced flow: time, state and mode (kStick has x' = v).
struct ForcedPoint {
  double t = 0, x = 0, xdot = 0;
  Mode mode = Mode::kSlipBelow;
};
/// The mode of (x, x') at time t: slip by the sign of x' - v; on x' = v stick
/// inside the band, else the slip side the force points to.
ForcedPoint ForcedStart(const ForcedModel& m, double t, double x, double xdot);

struct ForcedOptions {
  double rtol = 1e-12, atol = 1e-12;  ///< Taylor order and step (Jorba & Zou 2005)
  long max_steps = 1000000;           ///< Taylor and stick steps per Run
  long max_events = 100000;           ///< switches per Run
  /// Slip phases by Taylor series, or by CVODE (`method`) as an independent
  /// check (no extremes inside steps: ForcedRequest::extremes must be false).
  Integrator integrator = Integrator::kTaylor;
  Method method = Method::kAdams;
  /// Empty if valid, else one line naming the offending value.
  std::string ValidationError() const;
};

enum class ForcedEventKind { kStickIn, kStickOut, kCrossing, kTouch };
template <>
struct EnumNames<ForcedEventKind> {
  static constexpr NamedValue<ForcedEventKind> kTable[] = {
      {ForcedEventKind::kStickIn, "stick-in"},
      {ForcedEventKind::kStickOut, "stick-out"},
      {ForcedEventKind::kCrossing, "crossing"},
      {ForcedEventKind::kTouch, "touch"},
  };
};

struct ForcedEvent {
  ForcedEventKind kind;
  double t, x;  ///< x' = v at every event
  Mode before, after;
};

enum class ForcedStatus {
  kReached,      ///< t_end reached (or the requested stick exit)
  kTooMuchWork,  ///< max_steps or max_events before t_end
  kFailed,       ///< non-finite series, step underflow, or switching that does not advance t
};
template <>
struct EnumNames<ForcedStatus> {
  static constexpr NamedValue<ForcedStatus> kTable[] = {
      {ForcedStatus::kReached, "reached"},
      {ForcedStatus::kTooMuchWork, "too-much-work"},
      {ForcedStatus::kFailed, "failed"},
  };
};

struct ForcedRun {
  ForcedStatus status = ForcedStatus::kReached;
  std::string message;  ///< what failed and at which t, when not kReached
  ForcedPoint end;
  /// d(x, x')(end) / d(x, x')(start), saltation included (a start in stick
  /// has no x' direction: its second column is 0).
  Mat2 jacobian = Mat2::Identity();
  Extrema extrema = Extrema::Empty();  ///< running extremes of x and x'
  int sticks = 0, exits = 0, crossings = 0;
  long steps = 0;  ///< Taylor steps in slip, polynomial steps in stick
};

/// What one Run records and where it stops.
struct ForcedRequest {
  double t_end = 0;
  bool variational = false;  ///< compute ForcedRun::jacobian
  /// Extremes inside steps too (roots of x' and x''); else only at step ends and events.
  bool extremes = true;
  int stop_at_exit = 0;  ///< > 0: stop at that stick exit (end.mode is the slip mode)
  /// false: a slip start's field goes on across x' = v (no events, no stick):
  /// the smooth extension a grazing orbit is continued on (as the belt's
  /// grazing gap, docs/theory.md "Continuation"). A slip start only.
  bool switching = true;
  std::vector<ForcedEvent>* events = nullptr;  ///< appended to when not null
  /// Step ends (and events) for drawing, appended to when not null.
  std::vector<ForcedPoint>* samples = nullptr;
};

class ForcedFlow {
 public:
  /// Throws InvalidArgument if the options are not valid.
  ForcedFlow(const ForcedModel& model, const ForcedOptions& options);
  const ForcedModel& model() const { return model_; }
  const ForcedOptions& options() const { return options_; }

  /// Integrates from `start` (its mode is trusted: x' = v for kStick) to
  /// request.t_end >= start.t.
  ForcedRun Run(const ForcedPoint& start, const ForcedRequest& request) const;

 private:
  ForcedModel model_;
  ForcedOptions options_;
  // The one flow on ForcedModel with its request and result, one per thread
  // (forced_flow.cpp), kept between Runs.
  struct Scratch {
    std::unique_ptr<Flow> flow;
    FlowRequest request;
    FlowRun run;
  };
  static Scratch& Cache(const ForcedModel& model, const ForcedOptions& o);
};

}  // namespace stickslip
