// Every periodic orbit of a system with a clock at one parameter point
// (docs/theory.md, "Every orbit at a parameter point"), on the one shooting
// (shooting.hpp): for each period multiple m = min_m..max_m,
//  - Newton on the stroboscopic map P^m from a grid of starts at phase 0 on
//    a plane of two state components (the others at the centre's values);
//  - Newton on the exit-phase map from every bracket of t'_s(t_e) - t_e - m T,
//    the time of the s-th next stick exit against the exit time t_e, sampled
//    over one clock period for each contact and slip side, s = 1..max_sticks
//    (stick collapses the state, so the exits of a one-mass system form a
//    circle map; with more masses the exits through the centre are sampled).
// Found orbits are reduced to their least period and deduplicated by their
// stroboscopic points (an orbit of multiple m has m of them).
// FindAutonomousOrbits is the same scan for a system with no clock: runs
// from steady sliding disturbed along each of its modes (and from given
// states) settle for a transient, then Newton on each contact's stick-exit
// section from the run's last exits; orbits are kept once, compared on
// their stick exits (any point of the orbit may be its section point).
#pragma once

#include <array>
#include <functional>
#include <string>
#include <vector>

#include "stickslip/orbits/orbit_status.hpp"
#include "stickslip/orbits/shooting.hpp"

namespace stickslip {

struct OrbitSearchOptions {
  /// Upper bounds: min_m, max_m and max_sticks, grid, exit_samples.
  static constexpr int kMaxMultiple = 64, kMaxGrid = 100, kMaxExitSamples = 10000;
  ShootingOptions orbit;
  int min_m = 1;  ///< period multiples min_m..max_m
  int max_m = 4;
  int max_sticks = 4;     ///< exit-phase map: stick exits per orbit 1..max_sticks (0: none)
  int grid = 5;           ///< stroboscopic starts: grid x grid over the plane's box
  int exit_samples = 48;  ///< exit phases sampled per clock period, contact and side
  /// The plane of stroboscopic starts: two state components (not the clock).
  std::array<int, 2> plane{0, 1};
  /// The state the box is centred on and that fills the other components
  /// (its clock is set to 0); empty: 0.
  Eigen::VectorXd center;
  /// The box's half-widths in the plane's components; 0: the extent of a run
  /// of 10 clock periods from the centre, times 1.5 (at least 1e-3 (1 + |c|)).
  std::array<double, 2> half_width{0, 0};
  std::function<bool()> cancelled;  ///< polled between shots; empty: never
  /// Empty if valid, else one line naming the offending value.
  std::string ValidationError() const;
};

/// One orbit a search found.
struct FoundOrbit {
  PeriodicOrbit orbit;  ///< on the stroboscopic section of m periods
  int m = 1;            ///< its least period, in clock periods
  /// Its m stroboscopic points (the state at t = 0, T, ..., clock at 0).
  std::vector<Eigen::VectorXd> points;
  bool from_exit_map = false;  ///< first found on the exit-phase map (else by strobe shooting)
};

struct FoundOrbits {
  OrbitScanStatus status = OrbitScanStatus::kOk;  ///< kOk or kCancelled (the orbits so far kept)
  std::string message;                            ///< kFailed: the box's run, where it failed
  std::vector<FoundOrbit> orbits;                 ///< by m, then by the plane's first maximum
  std::array<double, 2> half_width{0, 0};         ///< the box scanned
  int shots = 0;                                  ///< Newton solves started
  int converged = 0;                              ///< of them converged (before deduplication)
  bool ok() const { return status == OrbitScanStatus::kOk; }
};

/// Throws InvalidArgument if the options are not valid for the system (a
/// plane component out of range or the clock, a centre of the wrong size or
/// not finite) or the system has not exactly one clock.
FoundOrbits FindOrbits(const System& system, const OrbitSearchOptions& options);

struct AutonomousSearchOptions {
  /// Upper bounds: amplitudes, starts, max_returns.
  static constexpr int kMaxAmplitudes = 16, kMaxStarts = 256, kMaxReturns = 64;
  static constexpr double kMaxAmplitude = 10;
  /// Steady sliding is sought in every pure-slip mode up to this many
  /// contacts (as SteadySliding), beyond in "all below" only.
  static constexpr int kRestModeContacts = 6;
  ShootingOptions orbit;
  /// Starts at steady sliding + a scale d, d each mode's direction (the real
  /// and imaginary parts of a complex eigenvector, a real eigenvector) at
  /// max norm 1; each a in (0, kMaxAmplitude].
  std::vector<double> amplitudes{0.01, 0.1, 0.3};
  double scale = 0;                     ///< 0: max(1, |steady sliding|) (max norm)
  double transient = 300;               ///< each start's run, in time units (> 0)
  int max_returns = 16;                 ///< the longest recurrence looked for, in stick exits
  std::vector<Eigen::VectorXd> starts;  ///< given states, run after the modal starts
  std::function<bool()> cancelled;      ///< polled between runs and shots; empty: never
  std::string ValidationError() const;
};

/// Where a scan's run started.
struct ScanStart {
  Eigen::VectorXd z;
  int mode = -1;           ///< the rest point's eigenvalue (largest real part first); -1: given
  bool imaginary = false;  ///< the imaginary part of its eigenvector (else the real part)
  double amplitude = 0;    ///< times the scale (given: 0)
};

/// One orbit of an autonomous system.
struct AutonomousOrbit {
  PeriodicOrbit orbit;      ///< on `section`, at its least number of returns
  PoincareSection section;  ///< StickExit(contact, returns)
  std::vector<int> sticks;  ///< stick phases per period, per contact
  /// Its stick exits over one period from the start (the start first), with
  /// their contacts.
  std::vector<Eigen::VectorXd> points;
  std::vector<int> point_contacts;
  int start = 0;  ///< AutonomousOrbits::starts' index of the run it was first found from
};

struct AutonomousOrbits {
  OrbitScanStatus status = OrbitScanStatus::kOk;  ///< kOk or kCancelled (the orbits so far kept)
  std::string message;                            ///< the first failed run's, if any
  std::vector<AutonomousOrbit> orbits;            ///< by period
  std::vector<ScanStart> starts;                  ///< every run's start, modal ones first
  int failed = 0;     ///< runs that ended before their transient (integrator failures)
  int shots = 0;      ///< Newton solves started
  int converged = 0;  ///< of them converged (before deduplication)
  bool ok() const { return status == OrbitScanStatus::kOk; }
};

/// Throws InvalidArgument if the options are not valid, a given start has
/// the wrong size or is not finite, or the system has a clock.
AutonomousOrbits FindAutonomousOrbits(const System& system, const AutonomousSearchOptions& options);

}  // namespace stickslip
