// Private to src/forced/: the sliding bifurcations of a forced branch
// (branch.hpp, ForcedLabel): their classification from the orbits on either
// side, and the search across a jump of the stroboscopic map.
#pragma once

#include <string>

#include "stickslip/forced/branch.hpp"

namespace stickslip::forced_detail {

inline bool SameStructure(const ForcedBranchRow& a, const ForcedBranchRow& b) {
  return a.sticks == b.sticks && a.crossings == b.crossings;
}

/// The row of a converged stroboscopic orbit at parameter value p.
ForcedBranchRow RowOf(const ForcedOrbit& o, double p);

/// The label and one-line description of the structure change from `before`
/// to `after` (rows within the bracket of the located point), set on *point.
void ClassifySliding(const ForcedParams& base, ForcedAxis axis, const ForcedBranchOptions& o,
                     const ForcedBranchRow& before, const ForcedBranchRow& after,
                     ForcedBranchRow* point);

/// Bisection in the parameter between lo (an orbit) and hi (no orbit of lo's
/// structure near it), Newton from the last orbit found, to tol (1 + |p|);
/// *before is the orbit at the edge, *after one at hi (Newton from *before,
/// else a transient). False with *why if there is none.
bool BisectEdge(const ForcedParams& base, ForcedAxis axis, const ForcedBranchOptions& o,
                ForcedBranchRow lo, double hi, double tol, ForcedBranchRow* before,
                ForcedBranchRow* after, std::string* why);

/// The point at an edge `before` with no periodic orbit of its multiple m
/// just beyond (the parameter moving by dir = +-1): labelled by the stick
/// structure of one run of m periods from its state just past the edge.
ForcedBranchRow EdgeWithoutOrbit(const ForcedParams& base, ForcedAxis axis,
                                 const ForcedBranchOptions& o, const ForcedBranchRow& before,
                                 double dir);

/// Where the corrector failed after `last` (the parameter moving by
/// dir = +-1, never past `limit`): natural-parameter steps of `step`, doubled, find a value with
/// no orbit of last's structure near it; bisection locates the edge to
/// tol (1 + |p|); *before is the orbit at the edge, *after an orbit just beyond
/// (Newton from *before, else a transient). False with *why if none is found;
/// then, if the orbit of last's structure goes on past the failure, *after is
/// the farthest one found (after->p != last.p): the caller may go on from it.
bool JumpAcross(const ForcedParams& base, ForcedAxis axis, const ForcedBranchOptions& o,
                const ForcedBranchRow& last, double dir, double step, double limit, double tol,
                ForcedBranchRow* before, ForcedBranchRow* after, std::string* why);

}  // namespace stickslip::forced_detail
