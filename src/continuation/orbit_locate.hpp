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
struct TracePoint {
  Eigen::VectorXd u;
  OrbitRow row;
};

// Every LP, PD and NS point between a and b (one switching sequence; none
// otherwise), located on the chord to tol and appended to *found.
void TestPoints(Palc& palc, OrbitProblem& problem, const TracePoint& a, const TracePoint& b,
                double tol, std::vector<OrbitRow>* found, int depth = 0);

// The changes of the switching sequence from a to b (at most kBranchEdges),
// each located to tol and appended to *found, labelled (ClassifySliding),
// and the pieces of one sequence between them appended to *pieces. Where
// the chord fails or meets the branch far apart either side of an edge, the
// edge is found by natural steps in p (JumpAcross) within range = {lo, hi}:
// then true (the trace crossed a jump).
bool Sliding(Palc& palc, OrbitProblem& problem, const TracePoint& a, const TracePoint& b,
             const double range[2], double tol, std::vector<OrbitRow>* found,
             std::vector<std::pair<TracePoint, TracePoint>>* pieces);

// The label of a located change of the switching sequence from `before` to
// `after` (the orbits either side): GR, AD, CR, else SL, with a one-line
// description, set on *point (orbit_sliding.cpp). False where a run either
// side failed: the point stays an unclassified SL.
bool ClassifySliding(OrbitProblem& problem, const OrbitRow& before, const OrbitRow& after,
                     OrbitRow* point);

// ", sticks 0 -> 1, crossings 2 -> 1": the counts that differ from a to b.
std::string SequenceChange(const OrbitRow& a, const OrbitRow& b);

// Where the corrector failed beyond `last` (the parameter moving by dir =
// +-1, never past `limit`): natural steps of `step`, doubled, along last's
// switching sequence find a value with no orbit of it near; BisectEdge
// locates the edge. False, with *why, if none is found: then before->p is
// the edge where it was located with no orbit beyond, else NaN, and *after
// the farthest orbit of last's sequence (after->p != last.p: the caller may
// go on from it).
bool JumpAcross(OrbitProblem& problem, const OrbitRow& last, double dir, double step, double limit,
                double tol, OrbitRow* before, OrbitRow* after, std::string* why);

// Bisection in p between lo (an orbit) and hi (no orbit of lo's sequence
// near it) by Newton at fixed p from the secant predictor, to tol (1 + |p|):
// *before is the last orbit of lo's sequence, labelled (ClassifySliding),
// *after an orbit of another sequence at hi (Newton from *before, else after
// a settling run). False, with *why, if there is none.
bool BisectEdge(OrbitProblem& problem, OrbitRow lo, double hi, double tol, OrbitRow* before,
                OrbitRow* after, std::string* why);

// The point at an edge `before` with no periodic orbit of its period just
// beyond (the parameter moving by dir = +-1): CL where a contact opened in
// the search beyond (problem.Opened()), else labelled by the switching
// counts of one period from its state just past the edge.
// *classified (if given) is false where the run beyond failed (an
// unclassified SL).
OrbitRow EdgeWithoutOrbit(OrbitProblem& problem, const OrbitRow& before, double dir, double tol,
                          bool* classified = nullptr);
// The branch ends at that edge: its labelled row (when `before` was located)
// ends the rows and special points, with status contact-lost at CL, else
// sequence-ended; an edge not located or not classified (the run beyond it
// failed) keeps step-too-small, with `why` added to the message.
void EndAtEdge(OrbitProblem& problem, const OrbitRow& before, double dir, double tol,
               const std::string& why, OrbitBranch* out);

}  // namespace stickslip::orbit_detail
