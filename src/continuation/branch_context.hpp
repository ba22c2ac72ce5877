// Internal to the continuation: the state every branch tracer shares (the
// parameter axis, the orbit finder, the result so far with its counts and
// timings, the Hopf points found). Its step constants: Tolerances (tolerances.hpp).
#pragma once

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "numerics/numbers.hpp"
#include "numerics/tolerances.hpp"
#include "stickslip/continuation/continuation.hpp"
#include "stickslip/systems/belt/parameter_axis.hpp"

namespace stickslip {

// Where a branch starts and what it is.
struct BranchStart {
  enum Phase { kStickSlip, kPureSlip, kNone } phase = kNone;
  double p = 0;
  double a = 0;    // pure slip: section amplitude
  double dir = 1;  // direction of travel in p (stick slip), or sign of the first dp (pure slip)
  bool from_hopf = false;   // pure slip: starts at the Hopf point p with a = 0
  bool skip_first = false;  // stick slip: the start point is already on a branch
  bool has_orbit = false;   // stick slip: `orbit` is the orbit at p
  Orbit orbit;
};

// How a branch tracer ended.
struct BranchEnd {
  enum Kind {
    kRangeEnd,  // reached an end of the range (or closed a loop)
    kHopf,      // shrank onto a Hopf point, recorded as its last point
    kGrazing,   // reached the grazing point p travelling in direction dir
    kStopped,   // failed or cancelled: the result's status says which
  } kind = kRangeEnd;
  double p = 0, dir = 1;
  PointKind came_from = PointKind::kStickSlip;
};

class BranchContext {
 public:
  enum class Phase { kEquilibrium, kStickSlip, kPureSlip, kSwitching, kDiscovery };

  BranchContext(const Params& base, const ContinuationOptions& o);

  const ContinuationOptions& options() const { return o_; }
  const ParameterAxis& axis() const { return axis_; }
  const Params& base() const { return base_; }
  double range() const { return range_; }
  // The scale of p-steps near p: the range, but within [kMinScale, 1] times
  // max(1, |p|), so that a range far wider than the branch (--to 1e6) does not
  // set the steps, nor a tiny one (1e-10) the corrector's tolerance in p.
  double LocalScale(double p) const {
    const double s = std::max(1.0, std::abs(p));
    return std::max(std::min(range_, s), Tolerances::kMinScale * s);
  }
  double lo() const { return lo_; }
  double hi() const { return hi_; }
  double dir() const { return dir_; }
  Params At(double p) const { return axis_.At(base_, p); }
  std::string Where(double p) const { return axis_.name() + " = " + Num(p); }
  OrbitFinder& finder() { return finder_; }
  ContinuationCounts& counts() { return res_.counts; }
  const std::vector<SpecialPoint>& special() const { return res_.special; }

  // True once the run is failed or cancelled (polls the cancel hook).
  bool Stop();
  // Records the first failure; later ones are dropped.
  void Fail(const std::string& where, const std::string& what);
  void Add(const BranchPoint& pt);
  // Room for n more points: one reallocation instead of many.
  void Reserve(size_t n) { res_.points.reserve(res_.points.size() + n); }
  void AddSpecial(const SpecialPoint& sp) { res_.special.push_back(sp); }
  // A periodic point of the current branch; a: pure slip's section amplitude.
  BranchPoint FromOrbit(double p, const Orbit& o, double a) const;

  bool StickSlipAt(double p, Orbit* orbit, OrbitResult* res);
  bool GrazingGapAt(double p, double* gap);
  // A pure-slip orbit by shooting at fixed p that stays below the belt.
  bool PureSlipAtFixedP(double p, double a_guess, Orbit* orbit, double* a);
  // G(a, p) and dG/da; outside the model's domain no orbit (kNotConverged).
  // With gp (and ga) and column(): dG/dp from the flow's parameter column in
  // the same run, set where the run carried it (map->has_dpdp).
  OrbitStatus EvalG(double a, double p, double* g, double* ga, ReturnMap* map,
                    double* gp = nullptr);
  // Whether EvalG can give dG/dp from the parameter column: Taylor, and a
  // parameter the law depends on affinely (ParameterColumnSupported).
  bool column() const { return column_; }

  void AddHopf(double p) { hopf_.emplace_back(p, false); }
  const std::vector<std::pair<double, bool>>& hopf() const { return hopf_; }
  // A located Hopf point within max(kNearHopf * range, slack) of p.
  bool NearHopf(double p, double slack = 0) const;
  // The branch ends on the Hopf point nearest p_near, amplitude 0, period 2 pi.
  void AddHopfEnd(double p_near, bool stable);
  // A grazing point recorded within kSameGrazing * locate_tol of p.
  bool GrazingVisited(double p) const;
  // p lies between stick-slip points of one branch already traced.
  bool CoveredByStickSlip(double p) const;
  // A pure-slip point of section amplitude a at exactly p is already on a branch.
  bool HasPureSlipPoint(double p, double a) const;

  void NextBranch() { ++branch_; }
  void SetBranch(int b) { branch_ = b; }
  // Time from now on is charged to `phase`.
  void Enter(Phase phase);
  ContinuationResult Finish();

 private:
  Params base_;
  ContinuationOptions o_;
  ParameterAxis axis_;
  OrbitFinder finder_;
  double range_, lo_, hi_, dir_;
  ContinuationResult res_;
  std::vector<std::pair<double, bool>> hopf_;  // located Hopf points, reached by a branch
  // Per branch with stick-slip points: its id and the p interval they cover.
  struct Span {
    int branch;
    double lo, hi;
  };
  std::vector<Span> stick_slip_spans_;
  int branch_ = 0;
  double last_p_ = 0;
  bool column_;
  Phase phase_ = Phase::kEquilibrium;
  std::chrono::steady_clock::time_point phase_start_;
};

}  // namespace stickslip
