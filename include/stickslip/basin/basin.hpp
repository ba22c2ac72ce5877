// Basins of attraction at one parameter point: a grid of starts in the plane
// (x, x'), each followed by the exact flow until it settles on an attractor
// (steady sliding, the stick-slip orbit, a stable pure-slip orbit) or a time
// cap passes. In the plane an unstable pure-slip orbit bounds the basin of
// steady sliding (docs/theory.md, "Basins"); the smallest disturbance
// that tips steady sliding into oscillation is its distance from (xbar, 0).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "stickslip/names.hpp"
#include "stickslip/orbits/orbit_scan.hpp"

namespace stickslip {

enum class Fate { kSteadySliding, kStickSlip, kPureSlip, kUndecided };
template <>
struct EnumNames<Fate> {
  static constexpr NamedValue<Fate> kTable[] = {
      {Fate::kSteadySliding, "steady-sliding"},
      {Fate::kStickSlip, "stick-slip"},
      {Fate::kPureSlip, "pure-slip"},
      {Fate::kUndecided, "undecided"},
  };
};

struct BasinOptions {
  // nx * ny's upper bound (the grid's starts).
  static constexpr long kMaxStarts = 4000000;
  // Bound of the box's corners: a finite box whose width cannot overflow.
  static constexpr double kMaxCorner = 1e6;
  OrbitScanOptions scan;  // the periodic orbits; scan.orbit.flow drives every run
  // The grid: nx by ny starts on [x_lo, x_hi] x [xdot_lo, xdot_hi], ends
  // included. With auto_range the box is the periodic orbits' (and the stick
  // band's) bounding box widened by a quarter on each side.
  bool auto_range = true;
  double x_lo = 0, x_hi = 0, xdot_lo = 0, xdot_hi = 0;
  int nx = 41, ny = 41;
  double t_cap = 2000;  // a start not settled by then is undecided
  // Settled on steady sliding: the section amplitude x - xbar at x' = 0 fell,
  // and is below settle times the innermost periodic orbit's amplitude. On a
  // stable pure-slip orbit: within settle of its amplitude (relative), closer
  // than at the last section crossing.
  double settle = 0.5;
  std::function<bool()> cancelled;                    // polled by the flow
  std::function<void(int done, int total)> progress;  // after every start
  // Empty if valid, else one line naming the offending value.
  std::string ValidationError() const;
};

struct BasinStart {
  double x = 0, xdot = 0;
  Fate fate = Fate::kUndecided;
  int orbit = -1;       // kPureSlip: index into orbits.pure_slip
  double t_settle = 0;  // time at which the fate was decided (or t_cap)
};

enum class BasinStatus {
  kOk,
  kFailed,     // an integration failed; message names the start
  kCancelled,  // cancelled() returned true; starts so far kept
};
template <>
struct EnumNames<BasinStatus> {
  static constexpr NamedValue<BasinStatus> kTable[] = {
      {BasinStatus::kOk, "ok"},
      {BasinStatus::kFailed, "failed"},
      {BasinStatus::kCancelled, "cancelled"},
  };
};

struct BasinResult {
  BasinStatus status = BasinStatus::kOk;
  std::string message;
  PeriodicOrbits orbits;
  double x_lo = 0, x_hi = 0, xdot_lo = 0, xdot_hi = 0;
  int nx = 0, ny = 0;
  std::vector<BasinStart> starts;  // row by row: xdot outer, x inner
  int count[4] = {0, 0, 0, 0};     // per Fate
  bool partial() const { return status != BasinStatus::kOk; }
};

// Throws InvalidArgument if the options are invalid.
BasinResult ClassifyBasins(const Model& model, const BasinOptions& options);

// One period of an orbit sampled at n + 1 points, start and end included
// (stick-slip: from the exit point (x0, v), the stick segment included).
std::vector<Vec2> OrbitCurve(const Model& model, const Orbit& orbit, const FlowOptions& flow,
                             int n);

// The smallest disturbance of steady sliding (xbar, 0) that reaches an orbit
// around it: along x' = 0 (min(x_max - xbar, xbar - x_min)), along x = xbar
// (the smaller |x'| where the orbit crosses it) and in energy
// E = ((x - xbar)^2 + x'^2) / 2 (its minimum along the orbit). For the
// unstable pure-slip orbit of a bistable band, any smaller disturbance
// returns to steady sliding.
struct Disturbance {
  double x = 0, xdot = 0, energy = 0;
  bool cancelled = false;  ///< `cancelled` fired: the values are not computed
};
// SmallestDisturbance's range of n (samples per period, streamed: memory
// does not grow with n).
constexpr int kMinDisturbanceSamples = 16, kMaxDisturbanceSamples = 100000000;
// Throws InvalidArgument if the orbit is not pure-slip or n is outside
// [kMinDisturbanceSamples, kMaxDisturbanceSamples]. Samples n points;
// `cancelled` is polled after every integration step.
Disturbance SmallestDisturbance(const Model& model, const Orbit& orbit, const FlowOptions& flow,
                                int n = 4000, std::function<bool()> cancelled = nullptr);

}  // namespace stickslip
