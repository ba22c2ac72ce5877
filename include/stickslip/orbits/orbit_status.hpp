// How a search for a periodic orbit ended (orbit.hpp, shooting.hpp): one
// status for every system and section.
#pragma once

#include "stickslip/names.hpp"

namespace stickslip {

/// How an orbit search ended; every value but kOk is a numerical outcome.
enum class OrbitStatus {
  kOk,
  kNoReturn,          // no return to Omega / the section within max_return_time
  kIntegratorFailed,  // CVODE failed; message says where
  kSticks,            // shooting: the trajectory sticks, so no pure-slip orbit here
  kNotConverged,      // Newton did not converge in max_newton steps
  kCollapsed,         // Newton ran into the equilibrium (amplitude -> 0)
  kMissed,            // StickSlip(first_return_only): the first return misses Omega
  kCancelled,         // the flow's cancel hook fired
  kSingular,          // shooting: DP - I is singular (a multiplier at 1)
  kAperiodic,         // a batch row: no section point recurs within max_m periods
  kContactOpen,       // a contact's normal force reached 0 (the flow's contact-open)
  kModeChanged,       // an event section's return is in another mode than the start
};
template <>
struct EnumNames<OrbitStatus> {
  static constexpr NamedValue<OrbitStatus> kTable[] = {
      {OrbitStatus::kOk, "ok"},
      {OrbitStatus::kNoReturn, "no-return"},
      {OrbitStatus::kIntegratorFailed, "integrator-failed"},
      {OrbitStatus::kSticks, "sticks"},
      {OrbitStatus::kNotConverged, "not-converged"},
      {OrbitStatus::kCollapsed, "collapsed"},
      {OrbitStatus::kMissed, "missed"},
      {OrbitStatus::kCancelled, "cancelled"},
      {OrbitStatus::kSingular, "singular"},
      {OrbitStatus::kAperiodic, "aperiodic"},
      {OrbitStatus::kContactOpen, "contact-open"},
      {OrbitStatus::kModeChanged, "mode-changed"},
  };
};

/// How a scan for every orbit at a parameter point ended (orbit_scan.hpp,
/// orbit_search.hpp).
enum class OrbitScanStatus {
  kOk,
  kFailed,     // an integration failed; message says where
  kCancelled,  // cancelled() returned true
};
template <>
struct EnumNames<OrbitScanStatus> {
  static constexpr NamedValue<OrbitScanStatus> kTable[] = {
      {OrbitScanStatus::kOk, "ok"},
      {OrbitScanStatus::kFailed, "failed"},
      {OrbitScanStatus::kCancelled, "cancelled"},
  };
};

}  // namespace stickslip
