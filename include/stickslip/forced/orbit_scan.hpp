// Every periodic orbit of the forced oscillator at one parameter point
// (issue 20, item 2), as FindPeriodicOrbits (orbits/orbit_scan.hpp) does for
// the belt: for each period multiple m = 1..max_m, Newton on the stroboscopic
// map P^m from a grid of starts at phase 0, and on the exit-phase map (the
// circle map t_e -> t' of docs/theory.md, "One shooting") from every bracket of
// t'_s(t_e) - t_e - m T found by sampling the exit phase, s = 1..max_sticks
// exits. Found orbits are reduced to their least period and deduplicated by
// their stroboscopic points (an orbit of multiple m has m of them).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "stickslip/forced/orbit.hpp"
#include "stickslip/names.hpp"
#include "stickslip/orbits/orbit_scan.hpp"

namespace stickslip {

struct ForcedScanOptions {
  /// Upper bounds: min_m, max_m and max_sticks, grid, exit_samples.
  static constexpr int kMaxMultiple = 64, kMaxGrid = 100, kMaxExitSamples = 10000;
  ShootingOptions orbit{ForcedModel::FlowDefaults()};
  int min_m = 1;  ///< period multiples min_m..max_m
  int max_m = 4;
  int max_sticks = 4;     ///< exit-phase map: stick phases per orbit 1..max_sticks
  int grid = 5;           ///< stroboscopic starts: grid x grid over the box
  int exit_samples = 48;  ///< exit phases sampled per forcing period and exit side
  /// Half-width of the box of stroboscopic starts (x in [-r, r], x' in
  /// [-r max(1, Omega), ...]); 0: r = A / max(|1 - Omega^2|, 2 beta Omega, 0.2) + mu_s + v.
  double radius = 0;
  std::function<bool()> cancelled;  ///< polled between shots; empty: never
  /// Empty if valid, else one line naming the offending value.
  std::string ValidationError() const;
};

struct ForcedScanOrbit {
  PeriodicOrbit
      orbit;  ///< on the stroboscopic section of m periods: multipliers, stability, sticks
  int m = 1;  ///< its least period, in forcing periods
  std::vector<Vec2> points;    ///< its m stroboscopic points (x, x') at t = 0, T, ...
  bool from_exit_map = false;  ///< first found on the exit-phase map (else by strobe shooting)
};

struct ForcedOrbits {
  OrbitScanStatus status = OrbitScanStatus::kOk;  ///< kOk or kCancelled (the orbits so far kept)
  std::vector<ForcedScanOrbit> orbits;            ///< by m, then by x_max
  int shots = 0;                                  ///< Newton solves started
  int converged = 0;                              ///< of them converged (before deduplication)
  bool ok() const { return status == OrbitScanStatus::kOk; }
};

/// Throws InvalidArgument if the options are not valid.
ForcedOrbits FindForcedOrbits(const ForcedModel& model, const ForcedScanOptions& options);

}  // namespace stickslip
