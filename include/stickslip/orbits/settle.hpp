// The stick-slip attractor a run settles on, for any autonomous system
// (docs/theory.md, "Starting on the attractor"): the flow from a start runs
// for a transient with its switches recorded; the last stick exit z_L and
// the least r for which the r-th exit before it is of the same contact and
// within kSettleRecur of z_L give the section StickExit(contact, r) and a
// guess that Shooting::Find refines (the forced oscillator's "attractor
// reached from rest", on an event section). A system with a clock settles on
// its stroboscopic map.
#pragma once

#include <functional>
#include <string>

#include "stickslip/orbits/shooting.hpp"

namespace stickslip {

struct SettleOptions {
  ShootingOptions shooting;  ///< the run's flow and the refining Newton
  double transient = 3000;   ///< the run's length (> 0)
  int max_returns = 32;      ///< the longest recurrence looked for, in stick exits (clock turns)
  std::function<bool()> cancelled;
  std::string ValidationError() const;
};

struct SettledOrbit {
  bool found = false;
  std::string message;                      ///< why not, where not found
  PoincareSection section;                  ///< StickExit(contact, returns), or Stroboscopic(m)
  PeriodicOrbit orbit;                      ///< Shooting::Find's result (found: ok)
  FlowStatus run = FlowStatus::kTimeLimit;  ///< how the settling run ended
  bool recurred = false;  ///< a stick exit recurred (then not found: Newton failed)
  int stick_exits = 0;    ///< in the settling run (with a clock: to its last full turn)
};

/// The stick-slip orbit `system` settles on from `z0` (its mode Filippov's).
/// The run goes in kSettleChunks pieces and keeps the last max_returns + 1
/// stick exits only, so its memory is bounded by one piece's switches.
/// Not found, with a message, where the run fails, has no recurring stick
/// exit (steady sliding, a pure-slip motion, chaos, or not yet settled) or
/// Newton fails. A system with one clock settles on its stroboscopic map
/// instead: its state at every clock turn for the transient, the last
/// max_returns + 1 kept, the least m with a recurrence giving
/// Stroboscopic(m) (any periodic attractor, pure slip too; the clock of the
/// orbit's start reduced to 0 mod 2 pi). Throws InvalidArgument on invalid
/// options, a state of the wrong size or not finite, or more than one clock.
SettledOrbit SettleOnStickSlip(const System& system, const Eigen::VectorXd& z0,
                               const SettleOptions& options);

}  // namespace stickslip
