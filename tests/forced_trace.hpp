// A forced branch for the tests: 200 forcing periods from rest at p with the
// axis at `from`, then ContinueForced (m = 1) from that state to `to` with options `o`.
#pragma once

#include "forced_run.hpp"
#include "stickslip/continuation/forced_branch.hpp"

namespace stickslip::testing_util {

inline OrbitBranch Trace(ForcedBeltParams p, ParameterAxis axis, double from, double to,
                         const OrbitBranchOptions& o) {
  axis.Set(p, from);
  const ForcedBelt m(p);
  const FlowRun tr = RunForced(m, ForcedStart(m, 0, 0, p.base.v), 200 * m.period());
  return ContinueForced(p, axis, from, to, tr.end.z[0], tr.end.z[1], 1, o);
}

inline OrbitBranch TraceOmega(const ForcedBeltParams& p, double from, double to,
                              const OrbitBranchOptions& o) {
  return Trace(p, Parameter::kOmega, from, to, o);
}

}  // namespace stickslip::testing_util
