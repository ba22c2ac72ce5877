// One trajectory of the forced friction oscillator, sampled for drawing
// (issue 20, item 1): a row every dt and at every switch, and a Poincare
// section, stroboscopic (the forcing phase Omega t = 0 mod 2 pi) or at the
// stick exits (the exit-phase map of docs/theory.md, "One shooting").
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "stickslip/forced/flow.hpp"
#include "stickslip/names.hpp"

namespace stickslip {

enum class ForcedSection {
  kStrobe,  ///< every t = n 2 pi / Omega (cos Omega t = 1)
  kExit,    ///< every stick exit
};
template <>
struct EnumNames<ForcedSection> {
  static constexpr NamedValue<ForcedSection> kTable[] = {
      {ForcedSection::kStrobe, "strobe"},
      {ForcedSection::kExit, "exit"},
  };
};

struct ForcedSimulationOptions {
  FlowOptions flow = ForcedModel::FlowDefaults();
  double t_end = 100;  ///< > start.t
  double dt = 0.01;    ///< > 0: a row at every multiple of dt (and at every switch)
  ForcedSection section = ForcedSection::kStrobe;
  /// Bound of rows + section points, those at switches included (held in
  /// memory): past it the run stops with kRowLimit.
  long max_rows = 10000000;
  std::function<bool()> cancelled;  ///< polled between rows; empty: never
  /// Empty if valid, else one line naming the offending value.
  std::string ValidationError() const;
};

/// A row of a trajectory: time, state and mode (kStick has x' = v).
struct ForcedPoint {
  double t = 0, x = 0, xdot = 0;
  Mode mode = Mode::kSlipBelow;
};

/// A point of the section: n counts the section's points from 0.
struct ForcedSectionPoint {
  long n = 0;
  ForcedPoint p;
};

enum class ForcedSimulationStatus {
  kComplete,
  kFailed,     ///< the flow failed or ran out of steps (message says where)
  kCancelled,  ///< cancelled() returned true; the rows so far are kept
  kRowLimit,   ///< rows + section points passed max_rows (message says when)
};
template <>
struct EnumNames<ForcedSimulationStatus> {
  static constexpr NamedValue<ForcedSimulationStatus> kTable[] = {
      {ForcedSimulationStatus::kComplete, "complete"},
      {ForcedSimulationStatus::kFailed, "failed"},
      {ForcedSimulationStatus::kCancelled, "cancelled"},
      {ForcedSimulationStatus::kRowLimit, "row-limit"},
  };
};

struct ForcedSimulation {
  ForcedSimulationStatus status = ForcedSimulationStatus::kComplete;
  std::string message;
  std::vector<ForcedPoint> rows;  ///< by time; an event row has x' = v and the mode after it
  std::vector<ForcedSectionPoint> section;
  Extrema extrema = Extrema::Empty();  ///< running extremes of x and x'
  long steps = 0;
  int sticks = 0, exits = 0, crossings = 0;
  bool ok() const { return status == ForcedSimulationStatus::kComplete; }
};

/// Integrates from `start` (its mode is trusted) to options.t_end.
/// Throws InvalidArgument if the options are not valid.
ForcedSimulation SimulateForced(const ForcedModel& model, const FlowPoint& start,
                                const ForcedSimulationOptions& options);

}  // namespace stickslip
