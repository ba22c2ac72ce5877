// A forced branch in Omega for the tests: 200 forcing periods from rest at
// the start, then ContinueForced from that state to `to` with options `o`.
#pragma once

#include "stickslip/forced/branch.hpp"

namespace stickslip::testing_util {

inline ForcedBranch TraceOmega(ForcedParams p, double from, double to,
                               const ForcedBranchOptions& o) {
  p.omega = from;
  const ForcedModel m(p);
  ForcedRequest rq;
  rq.t_end = 200 * m.period();
  const ForcedRun tr = ForcedFlow(m, ForcedOptions()).Run(ForcedStart(m, 0, 0, p.base.v), rq);
  return ContinueForced(p, ForcedAxis::kOmega, from, to, tr.end.x, tr.end.xdot, o);
}

}  // namespace stickslip::testing_util
