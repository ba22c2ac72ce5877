// Private to src/forced/: locating a forced branch's special points between
// two accepted points. Bisection on the chord (Locate) for one sign change of
// a test; TestPoints for every sign change of every test function (LP, PD,
// NS) between two points of one stick structure, the step halved while a
// multiplier moves far across it (two crossings in one step, issue 35).
#pragma once

#include <functional>
#include <vector>

#include "forced_branch_problem.hpp"

namespace stickslip::forced_detail {

// The rows at the ends of the final bracket of a located sign change.
struct Bracket {
  ForcedBranchRow lo, hi, mid;
  double p_hi = 0;  // the parameter at the bracket's far end
};

// Bisection on the chord a -> b for the sign change of test(): each point is
// corrected onto the branch with the chord's direction held (Palc::Correct).
// fail_is_hi: a point where the corrector fails counts as b's side (the edge
// of a jump of the map, where the orbit of a's side ends).
bool Locate(Palc& palc, StrobeProblem& problem, const Eigen::VectorXd& a, const Eigen::VectorXd& b,
            const std::function<double()>& test, double tol, Bracket* out, bool fail_is_hi = false);

// The test functions of a row, from its multipliers mu1, mu2:
// 0 fold (mu1 - 1)(mu2 - 1), 1 flip (mu1 + 1)(mu2 + 1), 2 torus mu1 mu2 - 1.
double RowTest(const ForcedBranchRow& r, int i);

// An NS point's multipliers: a complex pair on the unit circle (|mu| within
// tol of 1). A real pair with mu1 mu2 = 1 (a neutral saddle, beside R2 where
// the pair splits on the real axis) zeroes the torus test too, and is none.
bool TorusPair(const ForcedBranchRow& r, double tol);

// A point on the branch: (x0, x', p) and its row.
struct BranchPoint {
  Eigen::VectorXd u;
  ForcedBranchRow row;
};
inline BranchPoint PointOf(const ForcedBranchRow& r) {
  return {Eigen::Vector3d(r.x0, r.xdot0, r.p), r};
}

// The largest distance a multiplier moves from a to b (the two pairings, the closer one).
double MultiplierMove(const ForcedBranchRow& a, const ForcedBranchRow& b);

// Every LP, PD and NS point between a and b (one stick structure; none
// otherwise), located on the chord to tol and appended to *found. The step
// is halved (at most kBranchSplitDepth times) while a multiplier moves more
// than kBranchMultiplierStep across it, and once where a multiplier lies
// within kBranchMultiplierStep of -1, +1 or the unit circle at either end.
void TestPoints(Palc& palc, StrobeProblem& problem, const BranchPoint& a, const BranchPoint& b,
                double tol, std::vector<ForcedBranchRow>* found, int depth = 0);

}  // namespace stickslip::forced_detail
