// Across a corner or a jump of an orbit branch by natural steps in the
// parameter (orbit_locate.hpp): JumpAcross walks along one switching
// sequence, BisectEdge locates where it ends, EdgeWithoutOrbit labels an
// edge with no orbit of the same period beyond.
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

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

// The branch's orbit: its switching counts, and a period that does not jump
// from `from`'s (another orbit of the same counts nearby, as a chain's
// in-phase orbit beside its out-of-phase one, is not the branch's). The
// period may move by kBranchEdgePeriod plus twice the parameter's relative
// step (a period that scales like 1/p, as a forcing's 2 pi m / Omega).
bool OnBranch(const OrbitRow& orb, const OrbitRow& ref, const OrbitRow& from) {
  const double dp =
      from.p != 0 ? std::abs((orb.p - from.p) / from.p) : std::numeric_limits<double>::infinity();
  return SameStructure(orb, ref) && std::abs(orb.period - from.period) <=
                                        (Tolerances::kBranchEdgePeriod + 2 * dp) * from.period;
}

}  // namespace

bool BisectEdge(OrbitProblem& problem, OrbitRow lo, double hi, double tol, OrbitRow* before,
                OrbitRow* after, std::string* why) {
  const OrbitRow ref = lo;
  OrbitRow orb, prev = lo;
  bool have_prev = false;
  auto good = [&](double p, const OrbitRow& from) {
    std::string w;
    return OrbitAt(problem, from, p, &orb, &w) && OnBranch(orb, ref, from);
  };
  for (int it = 0;
       it < Tolerances::kBranchBisectionCap && std::abs(hi - lo.p) > tol * (1 + std::abs(lo.p));
       ++it) {
    const double mid = 0.5 * (lo.p + hi);
    // Newton from the secant predictor through the last two orbits: from lo
    // alone the first iterate near the edge can land past it and converge to
    // an orbit beyond, which would end the bisection early.
    OrbitRow guess = lo;
    if (have_prev) guess.start.z += (mid - lo.p) / (lo.p - prev.p) * (lo.start.z - prev.start.z);
    bool ok = good(mid, guess);
    // Not found: confirm by natural steps from lo (Newton can wander across
    // a jump of the map near the edge and converge elsewhere).
    for (int k = 1; k <= Tolerances::kBranchConfirmSteps && !ok; ++k) {
      if (!good(lo.p + (mid - lo.p) * k / Tolerances::kBranchConfirmSteps, k == 1 ? lo : guess))
        break;
      guess = orb;
      ok = k == Tolerances::kBranchConfirmSteps;
    }
    if (ok) {
      prev = lo, have_prev = true;
      lo = orb;
    } else {
      hi = mid;
    }
  }
  *before = lo;
  // The orbit beyond: Newton from the edge's orbit, else after settling there
  // (a contact opening there is what Opened() reports to EdgeWithoutOrbit).
  problem.ClearOpened();
  std::string w;
  bool found = OrbitAt(problem, lo, hi, &orb, &w) && !SameStructure(orb, ref);
  FlowPoint settled;
  if (!found && problem.Settle(hi, lo, Tolerances::kBranchSettlePeriods, &settled) &&
      problem.FindAt(hi, settled, &w)) {
    orb = problem.Row();
    found = !SameStructure(orb, ref);
  }
  if (!found) {
    *why = "no periodic orbit found beyond " + Num(lo.p, 15) +
           ", where the orbit's switching sequence ends";
    return false;
  }
  *after = orb;
  ClassifySliding(problem, lo, *after, before);
  return true;
}

bool JumpAcross(OrbitProblem& problem, const OrbitRow& last, double dir, double step, double limit,
                double tol, OrbitRow* before, OrbitRow* after, std::string* why) {
  before->p = NAN;
  *after = last;
  if ((limit - last.p) * dir <= 0) {
    *why = "no room beyond " + Num(last.p, 12) + " before " + Num(limit, 12);
    return false;
  }
  auto clamp = [&](double p) { return dir > 0 ? std::min(p, limit) : std::max(p, limit); };
  OrbitRow lo = last, orb;
  double hi = clamp(last.p + dir * step);
  for (int k = 0;; ++k) {  // the first value past the edge
    std::string w;
    if (!OrbitAt(problem, lo, hi, &orb, &w) || !OnBranch(orb, last, lo)) break;
    lo = orb;
    if (k == Tolerances::kBranchEdgeWalk || hi == limit) {
      *why = "an orbit of the same switching sequence goes on to " + Num(hi, 12);
      *after = lo;  // the farthest orbit found
      return false;
    }
    hi = clamp(hi + dir * step * (2 << k));
  }
  return BisectEdge(problem, lo, hi, tol, before, after, why);
}

namespace {

// Whether one period from `before`'s state just beyond the edge leaves a
// stick phase early: its first switch that differs from the orbit's (in
// kind, contact or time) is a stick exit of a contact that still sticks on
// the orbit then (a stick phase splits where its constraint force reaches
// the static limit inside it).
bool StickSplits(OrbitProblem& problem, const OrbitRow& before, const OrbitRow& beyond) {
  std::vector<FlowSwitch> on, off;
  if (!problem.Switches(before, &on) || !problem.Switches(beyond, &off)) return false;
  const double dt = Tolerances::kBranchSwitchTime * before.period;
  for (std::size_t i = 0; i < off.size(); ++i) {
    const bool differs = i >= on.size() || off[i].kind != on[i].kind ||
                         off[i].contact != on[i].contact || std::abs(off[i].t - on[i].t) > dt;
    if (!differs) continue;
    if (off[i].kind != SwitchKind::kStickOut) return false;
    const int c = off[i].contact;
    bool stuck = before.start.mode.sticks(c);  // on the orbit at off[i].t
    for (const FlowSwitch& e : on) {
      if (e.t > off[i].t - dt) break;
      if (e.contact == c) stuck = e.after.sticks(c);
    }
    return stuck;
  }
  return false;
}

}  // namespace

OrbitRow EdgeWithoutOrbit(OrbitProblem& problem, const OrbitRow& before, double dir, double tol,
                          bool* classified) {
  if (classified) *classified = true;
  OrbitRow beyond = before, point = before;
  beyond.p = before.p + dir * Tolerances::kBranchBeyondEdge * tol * (1 + std::abs(before.p));
  // Labelled by the switching counts of one period just beyond, from the
  // edge's state, where the system is valid there and the run ends well.
  if (problem.Opened()) {  // beyond the edge a contact opens: its normal force touches 0 there
    point.label = SpecialKind::kContactLoss;
    point.description =
        "contact loss: a normal force reaches 0 on the orbit; beyond it the "
        "contact opens";
    return point;
  }
  point.label = SpecialKind::kSliding;
  point.description = "the switching sequence changes (unclassified: the run beyond failed)";
  const bool known = problem.Counts(&beyond) && ClassifySliding(problem, before, beyond, &point);
  if (classified) *classified = known;
  if (StickSplits(problem, before, beyond)) {
    point.label = SpecialKind::kAdding;  // the slip that splits the stick is not short: a jump
    point.description =
        "adding-sliding: the stick force reaches the static limit inside a stick phase, which "
        "splits (the slip is not short: the map jumps)";
    if (classified) *classified = true;  // the split is a classification
  }
  point.description += "; no periodic orbit of the same period beyond";
  return point;
}

void EndAtEdge(OrbitProblem& problem, const OrbitRow& before, double dir, double tol,
               const std::string& why, OrbitBranch* out) {
  out->message += "; " + why;
  if (!std::isfinite(before.p)) return;  // not located: cut short (step-too-small)
  bool classified = true;
  out->special.push_back(EdgeWithoutOrbit(problem, before, dir, tol, &classified));
  out->rows.push_back(out->special.back());
  const OrbitRow& end = out->special.back();
  if (end.label == SpecialKind::kContactLoss) {
    out->status = BranchStatus::kContactLost;
    return;
  }
  if (!classified) return;  // the run beyond failed: cut short (step-too-small)
  // The sequence's natural end: the step's failure was its symptom.
  out->status = BranchStatus::kSequenceEnded;
  out->message = "the switching sequence ends at " + std::string(Name(end.label)) +
                 " (p = " + Num(end.p, 15) + "), with no periodic orbit of the same period beyond";
}

}  // namespace stickslip::orbit_detail
