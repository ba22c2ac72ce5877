// Across a corner or a jump of an orbit branch by natural steps in the
// parameter (orbit_locate.hpp, JumpAcross).
#include <cmath>
#include <string>

#include "numerics/numbers.hpp"
#include "numerics/tolerances.hpp"
#include "orbit_locate.hpp"

namespace stickslip::orbit_detail {

using Eigen::VectorXd;

namespace {

// The orbit at parameter p by damped Newton from `from`'s state (p held).
bool OrbitAt(OrbitProblem& problem, const OrbitRow& from, double p, OrbitRow* out,
             std::string* why) {
  if (!problem.FindAt(p, from.start, why)) return false;
  *out = problem.Row();
  return true;
}

}  // namespace

bool JumpAcross(OrbitProblem& problem, const OrbitRow& last, double dir, double step, double limit,
                double tol, OrbitRow* before, OrbitRow* after, std::string* why) {
  if ((limit - last.p) * dir <= 0) {
    *why = "no room beyond " + Num(last.p, 12) + " before " + Num(limit, 12);
    return false;
  }
  double h = step;
  OrbitRow far;
  bool found = false;
  for (int k = 0; k < Tolerances::kBranchJumpDoublings && !found; ++k, h *= 2) {
    double p = last.p + dir * h;
    if ((p - limit) * dir > 0) p = limit;
    found = OrbitAt(problem, last, p, &far, why);
    if (p == limit) break;
  }
  if (!found) {
    *why = "no orbit beyond " + Num(last.p, 12) + " up to " + Num(limit, 12) + " (" + *why + ")";
    return false;
  }
  *after = far;
  if (SameStructure(far, last)) {  // a corner of one sequence: no edge
    *before = last;
    before->label = SpecialKind::kNone;
    return true;
  }
  BisectEdge(problem, last, far, tol, before);
  return true;
}

void BisectEdge(OrbitProblem& problem, const OrbitRow& last, const OrbitRow& far, double tol,
                OrbitRow* before) {
  // Bisect the edge of last's sequence: lo keeps it, hi_p is beyond (an
  // orbit of another sequence there, or none of last's).
  OrbitRow lo = last, hi = far, mid;
  double hi_p = far.p;
  std::string w;
  for (int it = 0;
       it < Tolerances::kBranchBisectionCap && std::abs(hi_p - lo.p) > tol * (1 + std::abs(lo.p));
       ++it) {
    const double p = 0.5 * (lo.p + hi_p);
    OrbitRow beyond = hi;  // no orbit of last's sequence at p: the edge lies before it
    if (OrbitAt(problem, lo, p, &mid, &w)) {
      if (SameStructure(mid, last)) {
        lo = mid;
        continue;
      }
      beyond = mid;
    } else if (OrbitAt(problem, hi, p, &mid, &w) && !SameStructure(mid, last)) {
      beyond = mid;
    }
    hi = beyond, hi_p = p;
  }
  *before = lo;
  before->label = SpecialKind::kSliding;
  before->description = "the switching sequence changes" + SequenceChange(lo, hi);
}

}  // namespace stickslip::orbit_detail
