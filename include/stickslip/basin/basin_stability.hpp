// Exact basin stability: the fraction of a box of starts in the plane (x, x')
// that reaches each attractor. bSTAB (Stender & Hoffmann 2021) and pyBasin
// estimate it by Monte Carlo; here the basins are bounded by the unstable
// pure-slip orbits (docs/theory.md, "Basins"), closed curves nested
// about (xbar, 0), so each fraction is an area: the orbits, densely sampled
// from the flow's dense output, clipped to the box (clipped_area.hpp).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "stickslip/basin/basin.hpp"
#include "stickslip/basin/clipped_area.hpp"
#include "stickslip/systems/belt/parameter_axis.hpp"

namespace stickslip {

/// One attractor's share of the box.
struct BasinShare {
  Fate fate = Fate::kUndecided;  // kUndecided: a region no attractor bounds
  int orbit = -1;                // kPureSlip: index into PeriodicOrbits::pure_slip
  double fraction = 0;           // of the box's area, in [0, 1]
  /// "steady-sliding", "stick-slip", "pure-slip" (the first stable one),
  /// "pure-slip-2", ... or "undecided".
  std::string Name() const;
};

/// The shares (attractors inward to outward, the box's remainder last) and,
/// per pure-slip orbit, the fraction of the box it encloses.
struct BasinStability {
  std::vector<BasinShare> shares;
  std::vector<double> enclosed;
  /// The summed fraction of a fate (0 where it has no share).
  double Of(Fate f) const;
};

/// ExactBasinStability's smallest `samples` per orbit period.
constexpr int kMinBasinStabilitySamples = 16;

/// Between two consecutive nested invariant curves (steady sliding innermost,
/// the stick-slip orbit or nothing outermost) every start goes to whichever of
/// the two attracts. Throws InvalidArgument on an empty box or orbits that
/// are not ok; Error if an orbit's run fails. `samples` per orbit period.
BasinStability ExactBasinStability(const Model& model, const PeriodicOrbits& orbits, const Box& box,
                                   const FlowOptions& flow, int samples = 4000);

/// The curve of basin stability against one parameter, n points from `from`
/// to `to` (ends included), in a fixed box: at each point the periodic
/// orbits are found afresh (orbit_scan.hpp).
struct BasinStabilityCurve {
  ParameterAxis param = Parameter::kV;  // the parameter along the curve
  BasinStatus status = BasinStatus::kOk;
  std::string message;  // kFailed / kCancelled: where
  std::vector<double> p;
  std::vector<BasinStability> at;
};
BasinStabilityCurve BasinStabilityAlong(const Params& base, const ParameterAxis& axis, double from,
                                        double to, int n, const Box& box,
                                        const OrbitScanOptions& scan);

}  // namespace stickslip
