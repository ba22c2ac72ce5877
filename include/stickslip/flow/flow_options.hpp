// The integration settings and outcomes of the one flow (flow.hpp): which
// integrator steps the smooth segments, its tolerances, and how a run ends.
#pragma once

#include <algorithm>
#include <string>

#include "stickslip/names.hpp"

namespace stickslip {

// The integrator of the smooth segments.
enum class Integrator {
  kTaylor,  // Taylor series, order and step from the tolerance (Jorba & Zou 2005)
  kCvode,   // SUNDIALS CVODE with the linear multistep Method below
};
template <>
struct EnumNames<Integrator> {
  static constexpr NamedValue<Integrator> kTable[] = {
      {Integrator::kTaylor, "taylor"},
      {Integrator::kCvode, "cvode"},
  };
};

// CVODE's linear multistep method (only with Integrator::kCvode).
enum class Method {
  kAdams,  // Adams-Moulton with fixed-point iteration: non-stiff, the default
  kBdf,    // BDF with Newton and a dense linear solver: for stiff problems
};
template <>
struct EnumNames<Method> {
  static constexpr NamedValue<Method> kTable[] = {
      {Method::kAdams, "adams"},
      {Method::kBdf, "bdf"},
  };
};

struct FlowOptions {
  // max_steps' lower bound (a stepper needs a few steps to start).
  static constexpr long kMinSteps = 10;
  double rtol = 1e-11;  // relative tolerance
  double atol = 1e-13;  // absolute tolerance
  Integrator integrator = Integrator::kTaylor;
  Method method = Method::kAdams;
  long max_steps = 200000;      // steps per call of the stepper (per output interval)
  long max_switches = 1000000;  // mode changes per run
  // Empty if valid, otherwise one line naming the offending option.
  std::string ValidationError() const;
  bool operator==(const FlowOptions& o) const {
    return rtol == o.rtol && atol == o.atol && integrator == o.integrator && method == o.method &&
           max_steps == o.max_steps && max_switches == o.max_switches;
  }
  bool operator!=(const FlowOptions& o) const { return !(*this == o); }
};

enum class FlowStatus {
  kTimeLimit,         // reached t_max
  kStick,             // a contact arrived where it sticks (stop_at_stick), before sticking
  kSection,           // a terminal section (the belt's x' = 0 downwards)
  kVelocityMax,       // a maximum of x' (the belt's StopRule::at_velocity_max)
  kIntegratorFailed,  // the stepper failed (e.g. step-size underflow); message says where
  kTooManySwitches,   // more than FlowOptions::max_switches mode changes
  kCancelled,         // the cancel hook returned true
  kStickExit,         // the requested stick exit (FlowRequest::stop_at_exit)
  kTooMuchWork,       // FlowRequest::max_steps steps before t_max
  kInconsistentMode,  // contacts switched at once and no mode is consistent (ConsistentMode)
  kAmbiguousMode,     // contacts switched at once and several modes are consistent
  kTooManyAtOnce,     // over kMaxEnumeratedAfterCycle at once, and pivoting cycled
  kContactOpen,       // a contact's normal force fell to 0 (System::NormalForce)
  kSwitchCount,       // FlowRequest::stop_after_switches switches (Simulate runs on from there)
};
template <>
struct EnumNames<FlowStatus> {
  static constexpr NamedValue<FlowStatus> kTable[] = {
      {FlowStatus::kTimeLimit, "time-limit"},
      {FlowStatus::kStick, "stick"},
      {FlowStatus::kSection, "section"},
      {FlowStatus::kVelocityMax, "velocity-max"},
      {FlowStatus::kIntegratorFailed, "integrator-failed"},
      {FlowStatus::kTooManySwitches, "too-many-switches"},
      {FlowStatus::kCancelled, "cancelled"},
      {FlowStatus::kStickExit, "stick-exit"},
      {FlowStatus::kTooMuchWork, "too-much-work"},
      {FlowStatus::kInconsistentMode, "inconsistent-mode"},
      {FlowStatus::kAmbiguousMode, "ambiguous-mode"},
      {FlowStatus::kTooManyAtOnce, "too-many-at-once"},
      {FlowStatus::kContactOpen, "contact-open"},
      {FlowStatus::kSwitchCount, "switch-count"},
  };
};

// The orders of the Taylor steps taken (CVODE's steps count none): order p,
// or p + TaylorField::ExtraOrder, or p again where those extra orders overflow.
struct TaylorOrders {
  long steps = 0;        // Taylor steps
  long sum = 0;          // the sum of their orders (mean: sum / steps)
  int min = 0, max = 0;  // over those steps; 0 without steps
  long fallbacks = 0;    // steps recomputed at p: their order p + extra overflowed
  [[gnu::noinline]] void Merge(const TaylorOrders& o) {
    fallbacks += o.fallbacks;
    if (o.steps == 0) return;
    min = steps == 0 ? o.min : std::min(min, o.min);
    max = std::max(max, o.max);
    steps += o.steps;
    sum += o.sum;
  }
};

}  // namespace stickslip
