// Forced branches for the tests, on the one branch driver (orbit_branch.hpp)
// as ss_continue --force runs it: the stroboscopic section of m forcing
// periods of ForcedBelt, started from a guess (x, x') at theta = 0.
#pragma once

#include "forced_run.hpp"
#include "stickslip/continuation/orbit_branch.hpp"

namespace stickslip::testing_util {

/// The stroboscopic point (x, x') at theta = 0 (its mode a guess the
/// shooting corrects).
inline FlowPoint StrobePoint(double x, double xdot) {
  return {0, Eigen::Vector3d(x, xdot, 0), ModeSet(Mode::kSlipBelow)};
}

/// ContinueOrbits of the m-periodic orbit near (x, x') of p with `axis` at
/// `from`, toward `to`, on PoincareSection::Stroboscopic(model, z, m).
inline OrbitBranch StrobeBranch(ForcedBeltParams p, ParameterAxis axis, double from, double to,
                                double x, double xdot, int m, const OrbitBranchOptions& o) {
  axis.Set(p, from);
  const ForcedBelt model(p);
  const FlowPoint guess = StrobePoint(x, xdot);
  return ContinueOrbits(model, axis.index(), guess,
                        PoincareSection::Stroboscopic(model, guess.z, m), to, o);
}

/// 200 forcing periods from rest at p with the axis at `from`, then the
/// m = 1 branch (StrobeBranch) from that state to `to` with options `o`.
inline OrbitBranch Trace(ForcedBeltParams p, ParameterAxis axis, double from, double to,
                         const OrbitBranchOptions& o) {
  axis.Set(p, from);
  const ForcedBelt m(p);
  const FlowRun tr = RunForced(m, ForcedStart(m, 0, 0, p.base.v), 200 * m.period());
  return StrobeBranch(p, axis, from, to, tr.end.z[0], tr.end.z[1], 1, o);
}

inline OrbitBranch TraceOmega(const ForcedBeltParams& p, double from, double to,
                              const OrbitBranchOptions& o) {
  return Trace(p, Parameter::kOmega, from, to, o);
}

}  // namespace stickslip::testing_util
