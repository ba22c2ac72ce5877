// One trajectory of any friction system (system.hpp), streamed for drawing:
// a row every dt (the flow's dense output: a Taylor step's polynomial, or
// CVODE's interpolant) and at every switch, and optionally a Poincare
// section, stroboscopic (every `period`, e.g. a forcing's 2 pi / Omega) or
// at the stick exits (the exit-phase map of docs/theory.md, "One shooting").
// Rows go to the caller as they come; the library holds none of them.
#pragma once

#include <Eigen/Dense>
#include <functional>
#include <string>
#include <vector>

#include "stickslip/flow/flow.hpp"
#include "stickslip/names.hpp"

namespace stickslip {

enum class SimulationSection {
  kStrobe,  ///< every t = n period, n an integer (the run stops there exactly)
  kExit,    ///< every stick exit of any contact
  kNone,
};
template <>
struct EnumNames<SimulationSection> {
  static constexpr NamedValue<SimulationSection> kTable[] = {
      {SimulationSection::kStrobe, "strobe"},
      {SimulationSection::kExit, "exit"},
      {SimulationSection::kNone, "none"},
  };
};

struct SimulationOptions {
  FlowOptions flow;
  double t_end = 100;  ///< > start.t
  double dt = 0.01;    ///< > 0: a row at every start.t + k dt (and at every switch)
  SimulationSection section = SimulationSection::kNone;
  double period = 0;         ///< kStrobe: > 0, the section's spacing in t
  std::vector<int> extrema;  ///< components whose extremes Simulation::lo, hi hold
  /// Bound of rows + section points, those at switches included: past it
  /// the run stops with kRowLimit.
  long max_rows = 10000000;
  std::function<bool()> cancelled;  ///< polled after every step; empty: never
  /// Empty if valid, else one line naming the offending value.
  std::string ValidationError() const;
};

/// Where the rows go: row(t, z, mode) by time (a switch's row carries the
/// mode after it), section(n, t, z, mode) with n counting from 0. z has
/// System::dimension() entries and lives only for the call.
struct SimulationSink {
  std::function<void(double t, const double* z, const ModeSet& mode)> row;
  std::function<void(long n, double t, const double* z, const ModeSet& mode)> section;
};

enum class SimulationStatus {
  kComplete,
  kContactOpen,  ///< a contact's normal force reached 0: the run ends there
  kFailed,       ///< the flow failed, or a state was not finite (message says where)
  kCancelled,    ///< cancelled() returned true; the rows so far were given
  kRowLimit,     ///< rows + section points passed max_rows (message says when)
};
template <>
struct EnumNames<SimulationStatus> {
  static constexpr NamedValue<SimulationStatus> kTable[] = {
      {SimulationStatus::kComplete, "complete"},  {SimulationStatus::kContactOpen, "contact-open"},
      {SimulationStatus::kFailed, "failed"},      {SimulationStatus::kCancelled, "cancelled"},
      {SimulationStatus::kRowLimit, "row-limit"},
  };
};

struct Simulation {
  SimulationStatus status = SimulationStatus::kComplete;
  std::string message;
  FlowPoint end;                             ///< the last point reached (all finite)
  FlowStatus flow = FlowStatus::kTimeLimit;  ///< how the last flow run ended
  int opened = -1;                           ///< kContactOpen: the contact
  long rows = 0, section_points = 0, steps = 0;
  int switches = 0, sticks = 0, exits = 0, crossings = 0;
  double t_stick = 0;      ///< time with some contact sticking
  Eigen::VectorXd lo, hi;  ///< extremes of SimulationOptions::extrema
  /// Complete, or ended where a contact opens (a physical end, not a failure).
  bool ok() const {
    return status == SimulationStatus::kComplete || status == SimulationStatus::kContactOpen;
  }
};

/// Integrates from `start` (its mode is trusted) to options.t_end, giving
/// every row and section point to `sink`. Throws InvalidArgument if the
/// options are not valid or t_end is not after start.t.
Simulation Simulate(const System& system, const FlowPoint& start, const SimulationOptions& options,
                    const SimulationSink& sink);

}  // namespace stickslip
