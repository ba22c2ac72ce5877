// Private to src/continuation/: locating an orbit branch's special points
// between two accepted points (orbit_branch.hpp). Locate bisects one sign
// change of a test on the chord; TestPoints finds every sign change of every
// multiplier test (LP, PD, NS) between two points of one switching sequence,
// the step halved while a multiplier moves far across it (two crossings in
// one step); Sliding locates the changes of the switching sequence.
#pragma once

#include <functional>
#include <vector>

#include "orbit_problem.hpp"

namespace stickslip::orbit_detail {

// The rows at the ends of the final bracket of a located sign change, and
// the corrected point at its middle.
struct Bracket {
  OrbitRow lo, hi, mid;
};

// Bisection on the chord a -> b for the sign change of test(): each point is
// corrected onto the branch with the chord's direction held (Palc::Correct).
// fail_is_hi: a point where the corrector fails counts as b's side (the edge
// of a jump of the map, where the orbits of a's side end).
bool Locate(Palc& palc, OrbitProblem& problem, const Eigen::VectorXd& a, const Eigen::VectorXd& b,
            const std::function<double()>& test, double tol, Bracket* out, bool fail_is_hi = false);

// A point on the branch: u and its row.
struct BranchPoint {
  Eigen::VectorXd u;
  OrbitRow row;
};

// Every LP, PD and NS point between a and b (one switching sequence; none
// otherwise), located on the chord to tol and appended to *found.
void TestPoints(Palc& palc, OrbitProblem& problem, const BranchPoint& a, const BranchPoint& b,
                double tol, std::vector<OrbitRow>* found, int depth = 0);

// The changes of the switching sequence from a to b (at most kBranchEdges),
// each located to tol and appended to *found as an SL point, and the pieces
// of one sequence between them appended to *pieces.
void Sliding(Palc& palc, OrbitProblem& problem, const BranchPoint& a, const BranchPoint& b,
             double tol, std::vector<OrbitRow>* found,
             std::vector<std::pair<BranchPoint, BranchPoint>>* pieces);

// The edge of last's switching sequence between last and far (an orbit of
// another sequence), bisected in p to tol by damped Newton at fixed p:
// *before is the last orbit of last's sequence, labelled SL.
void BisectEdge(OrbitProblem& problem, const OrbitRow& last, const OrbitRow& far, double tol,
                OrbitRow* before);

}  // namespace stickslip::orbit_detail

namespace stickslip::orbit_detail {

// ", sticks 0 -> 1, crossings 2 -> 1": the counts that differ from a to b.
std::string SequenceChange(const OrbitRow& a, const OrbitRow& b);

// Where the corrector failed beyond `last` (a corner sharper than a right
// angle, or a jump of the map where a stick phase of finite length is born):
// the orbit at p = last.p + dir h by damped Newton at fixed p from last's state, h
// doubled from `step` up to `limit`; then the edge of last's switching
// sequence bisected in p to tol. *before: the last orbit of last's sequence,
// labelled SL; *after: the first orbit beyond it. False, with *why, if no
// orbit is found before limit.
bool JumpAcross(OrbitProblem& problem, const OrbitRow& last, double dir, double step, double limit,
                double tol, OrbitRow* before, OrbitRow* after, std::string* why);

// The edge of last's switching sequence between last and far (an orbit of
// another sequence), bisected in p to tol by damped Newton at fixed p:
// *before is the last orbit of last's sequence, labelled SL.
void BisectEdge(OrbitProblem& problem, const OrbitRow& last, const OrbitRow& far, double tol,
                OrbitRow* before);

}  // namespace stickslip::orbit_detail
