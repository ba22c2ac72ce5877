// Every periodic orbit at one parameter point: steady sliding, the stick-slip
// orbit (the constant return map of Omega, one slip integration) and every
// pure-slip orbit, found as fixed points of the return map P of the section
// x' = 0 scanned over every amplitude a = x - xbar from steady sliding up to
// the amplitude whose trajectory first reaches the stick band. Inside a
// bistable band (subcritical Hopf, docs/theory.md, "Steady sliding and the Hopf point") the
// unstable pure-slip orbit lies between steady sliding and the stick-slip orbit. Where the energy
// bound excludes every orbit (Model::NoPeriodicOrbit) the scan integrates nothing and lists steady
// sliding alone.
#pragma once

#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "stickslip/names.hpp"
#include "stickslip/orbits/orbit.hpp"
#include "stickslip/orbits/orbit_status.hpp"

namespace stickslip {

struct OrbitScanOptions {
  // a_min's upper bound (exclusive).
  static constexpr double kAMinLimit = 0.1;
  OrbitOptions orbit;
  // Section amplitudes sampled: half on a geometric grid from a_min, half on
  // a uniform one, both up to a_max = 2 (mu_s + |v|).
  int samples = 64;
  double a_min = 1e-4;              // relative to mu_s + |v|, in (0, kAMinLimit)
  std::function<bool()> cancelled;  // polled by the flow; empty: never
  // Empty if valid, else one line naming the offending value.
  std::string ValidationError() const;
};

struct PeriodicOrbits {
  OrbitScanStatus status = OrbitScanStatus::kOk;
  std::string message;
  Equilibrium steady;  // steady sliding (xbar, 0) and its stability
  bool has_stick_slip = false;
  Orbit stick_slip;  // superstable (multiplier 0) when it exists
  // By increasing section amplitude; stable or not. Isolated orbits only:
  // where G vanishes identically within the integration noise (a center, as
  // for the coulomb law with beta = 0) none is listed.
  std::vector<Orbit> pure_slip;
  // Smallest sampled section amplitude whose trajectory sticks, located to
  // 1e-10 relative (inf: none up to a_max); pure-slip orbits lie below it.
  double a_stick = std::numeric_limits<double>::infinity();
  double a_max = 0;
  int returns = 0;  // return-map evaluations
  bool ok() const { return status == OrbitScanStatus::kOk; }
};

// Throws InvalidArgument if the options are invalid.
PeriodicOrbits FindPeriodicOrbits(const Model& model, const OrbitScanOptions& options);

}  // namespace stickslip
