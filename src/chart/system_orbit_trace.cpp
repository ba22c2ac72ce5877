// One curve of a system's periodic orbits through the rectangle
// (TraceOrbitCurve, system_chart.hpp): orbit_curve.hpp's problem traced both
// ways by chart_trace.hpp. A system with a clock is cut on a stroboscopic
// section; where the orbit sticks at the section the map is not smooth, so
// the section starts in a slip phase (OrbitCurveProblem::Rephase) and moves
// on whenever the section point comes within Tolerances::
// curve_section_near_stick of a contact's surface: the curve is then
// continued in stretches, each at its own clock phase.
#include <chrono>
#include <cmath>
#include <memory>

#include "chart/orbit_curve.hpp"
#include "chart/system_chart_seeds.hpp"
#include "chart/system_chart_trace.hpp"
#include "chart/system_codim2.hpp"
#include "numerics/numbers.hpp"
#include "numerics/tolerances.hpp"
#include "stickslip/errors.hpp"

namespace stickslip {

using Eigen::VectorXd;

namespace {

CurveEnd SameSequence(OrbitCurveProblem& problem, const PalcPoint& last, const PalcPoint& next);

// Whether `next` continues the curve through `last`: a branch jump where the
// corrector moved far off the predictor (PALC puts next on the plane through
// last.u + ds t normal to t, scaled: ds is next's offset along t, the rest is
// what the corrector moved) or where the orbit has a shorter period; an SL
// point where the orbit's switching sequence changes (its counts of sticks
// and crossings, or the order of its modes).
CurveEnd SameCurve(OrbitCurveProblem& problem, const PalcPoint& last, const PalcPoint& next,
                   const VectorXd& scale) {
  const VectorXd d = (next.u - last.u).cwiseQuotient(scale);
  const double ds = last.tangent.dot(d), off = (d - ds * last.tangent).norm();
  const int i1 = problem.plane_index();
  if (!(off <= Tolerances().curve_branch_offset * std::abs(ds)))
    return {CurveEndKind::kBranchJump, "the corrector moved " + Num(off / std::abs(ds), 3) +
                                           " steps off the predictor at (" + Num(next.u[i1], 6) +
                                           ", " + Num(next.u[i1 + 1], 6) + ")"};
  return SameSequence(problem, last, next);
}

// The sequence half of SameCurve: SL where the switching sequence changes,
// a branch jump onto a shorter period.
CurveEnd SameSequence(OrbitCurveProblem& problem, const PalcPoint& last, const PalcPoint& next) {
  OrbitRow a, b;
  std::vector<ModeSet> ma, mb;
  double t = 0;
  std::string why;
  if (!problem.Sample(last.u, &a, &t, &why, &ma)) return {CurveEndKind::kStartFailed, why};
  if (!problem.Sample(next.u, &b, &t, &why, &mb))  // a return in another mode: SL
    return {problem.last_map_failure() == OrbitStatus::kModeChanged ? CurveEndKind::kSliding
                                                                    : CurveEndKind::kStartFailed,
            why};
  // (a GR curve is where the sequence changes: its margin spans both sides)
  const bool grazing = problem.kind() == CurveKind::kGrazing;
  if (!grazing && !orbit_detail::SameStructure(a, b))
    return {CurveEndKind::kSliding,
            "the switching sequence changes: sticks " + std::to_string(a.sticks) + " -> " +
                std::to_string(b.sticks) + ", crossings " + std::to_string(a.crossings) + " -> " +
                std::to_string(b.crossings)};
  if (!grazing && ma != mb)
    return {CurveEndKind::kSliding,
            "the order of the orbit's " + std::to_string(ma.size()) + " modes changes"};
  if (const int k = problem.ShorterPeriod(b); k > 0)
    return {CurveEndKind::kBranchJump, "the orbit closes after 1/" + std::to_string(k) +
                                           " of its period (a branch of a shorter period)"};
  return {};
}

// Why an accepted point u of a curve of orbits is no point of it, or "": its
// residual max(|P(u) - u|, |test|) exceeds `bound` (an update that shrank on
// a kink of the map, not at a root), or on an NS curve no complex pair lies
// on the unit circle (past R1 or R2 the test's zero is a neutral saddle). A
// steep test (an orbit of 2m periods with a stick phase: its value at a
// converged point is the corrector's last update times the gradient) may
// exceed `bound` up to kCurveTestSteps times, within kCurveTestSteps
// corrector tolerances `tol` of its zero; the map's residual may not.
std::string BadPoint(OrbitCurveProblem& problem, const VectorXd& u, double bound, double tol,
                     CurveKind kind, bool* saddle) {
  *saddle = false;
  OrbitCurveProblem::Residuals res;
  std::string why;
  if (!problem.ResidualsAt(u, &res, &why)) return why.empty() ? "the map failed" : why;
  const double steps = Tolerances::kCurveTestSteps;
  const bool steep = res.test <= steps * bound && res.distance <= steps * tol;
  if (!(res.map <= bound) || !(res.test <= bound || steep))
    return "residual " + Num(std::max(res.map, res.test), 3) +
           " at an accepted point (the map is not smooth there)";
  OrbitRow row;
  double test = 0;
  if (kind == CurveKind::kTorus && problem.Sample(u, &row, &test, &why) &&
      !orbit_detail::TorusPair(row, std::max(Tolerances::kBranchTorusPair, bound))) {
    *saddle = true;
    return "no complex pair on the unit circle: a neutral saddle (R1 or R2 lies before)";
  }
  return {};
}

class OrbitTracer {
 public:
  OrbitTracer(const System& system, const SystemChartOptions& o, CurveKind kind,
              const PoincareSection& section)
      : system_(system), o_(o), kind_(kind), section_(section), bo_(o.branch) {
    bo_.palc.cancelled = o.cancelled;  // also inside every run of the flow
    const FlowOptions& flow = o.branch.shooting.flow;
    bound_ = Tolerances::From(flow.rtol, flow.atol).CurveResidual();
    tol_ = Tolerances::From(flow.rtol, flow.atol).SystemCurveCorrector();
    clocked_ = section.kind == SectionKind::kTime && system.clocks() == 1;
  }
  bool clocked() const { return clocked_; }

  std::shared_ptr<OrbitCurveProblem> Problem(const FlowPoint& start, double p1, double p2) const {
    const auto at = SystemAt(system_, o_.plane, p1, p2);
    return std::make_shared<OrbitCurveProblem>(*at, o_.plane.p1, o_.plane.p2, start, section_,
                                               kind_, bo_, margin_);
  }

  // GR: the margin nearer 0 at the seed u0 (an arrival's, else the gap's).
  void ChooseMargin(const FlowPoint& start, const VectorXd& u0, int i1) {
    double g[2] = {HUGE_VAL, HUGE_VAL};
    for (const GrazingMargin m : {GrazingMargin::kArrival, GrazingMargin::kGap}) {
      margin_ = m;
      OrbitRow row;
      double test = 0;
      std::string why;
      if (Problem(start, u0[i1], u0[i1 + 1])->Sample(u0, &row, &test, &why))
        g[static_cast<int>(m)] = std::abs(test);
    }
    margin_ = g[0] <= g[1] ? GrazingMargin::kArrival : GrazingMargin::kGap;
  }

  // The tracer's settings on `problem`; a bad point is recorded in bad_, a
  // section point near a contact's surface sets near_.
  TraceOptions Options(const std::shared_ptr<OrbitCurveProblem>& problem, const VectorXd& u0) {
    const int i1 = problem->plane_index();
    TraceOptions t = TraceFor(o_, i1);
    t.other_scale = std::max(1.0, u0.head(i1).cwiseAbs().maxCoeff());
    t.refine_ends = true;
    OrbitCurveProblem* pr = problem.get();
    t.same_branch = [pr](const PalcPoint& a, const PalcPoint& b, const VectorXd& scale) {
      return SameCurve(*pr, a, b, scale);
    };
    t.stop = [this, pr](const VectorXd& u) {
      bool saddle = false;
      std::string why = BadPoint(*pr, u, bound_, tol_, kind_, &saddle);
      if (why.empty()) why = Creeps(u, pr->plane_index());
      if (!why.empty()) {
        bad_.push_back({u, why, saddle});
        return true;
      }
      return clocked_ && pr->SlipGap(u) < Tolerances().curve_section_near_stick;
    };
    return t;
  }

  // Why the curve creeps at u, or "": kCurveCreepSteps accepted points in a
  // row each less than kCurveCreepStep of the rectangle from the last (the
  // corrector's steps shrink on a kink of the map ahead).
  std::string Creeps(const VectorXd& u, int i1) {
    const double w1 = o_.plane.to1 - o_.plane.from1, w2 = o_.plane.to2 - o_.plane.from2;
    const bool small = last_.size() == u.size() &&
                       std::hypot((u[i1] - last_[i1]) / w1, (u[i1 + 1] - last_[i1 + 1]) / w2) <
                           Tolerances::kCurveCreepStep;
    creep_ = small ? creep_ + 1 : 0;
    last_ = u;
    if (creep_ < Tolerances::kCurveCreepSteps) return {};
    creep_ = 0;
    return "the curve creeps: " + std::to_string(Tolerances::kCurveCreepSteps) + " steps under " +
           Num(Tolerances::kCurveCreepStep) + " of the rectangle (a kink of the map ahead)";
  }

  // Drops a way's last point if it is bad, the end saying why; a neutral
  // saddle dropped goes to *saddle (for R1 and R2). True if it was bad.
  bool DropBad(OrbitCurveProblem& pr, std::vector<VectorXd>* u, bool back, CurveEnd* end,
               VectorXd* saddle = nullptr) const {
    if (u->empty() || end->kind != CurveEndKind::kStopped) return false;
    const VectorXd& at = back ? u->back() : u->front();
    const Bad* bad = nullptr;
    for (const Bad& b : bad_)
      if (b.u == at) bad = &b;
    if (!bad) return false;
    if (saddle && bad->saddle) *saddle = at;
    end->why = bad->why;
    // A residual on a kink where the switching sequence changes: an SL end.
    if (!bad->saddle && u->size() >= 2) {
      PalcPoint a, b;
      a.u = back ? (*u)[u->size() - 2] : (*u)[1], b.u = at;
      a.tangent = b.tangent = VectorXd::Zero(at.size());  // (no offset test here)
      const CurveEnd e = SameSequence(pr, a, b);
      if (e.kind == CurveEndKind::kSliding) end->kind = e.kind, end->why = e.why + "; " + bad->why;
    }
    if (back)
      u->pop_back();
    else
      u->erase(u->begin());
    return true;
  }

  // Goes on from u, where a way stopped near the section's stick, at a new
  // section start, along `dir` in the plane; up to kRestarts times.
  CurveEnd GoOn(std::shared_ptr<OrbitCurveProblem> pr, VectorXd u, Eigen::Vector2d dir,
                std::vector<CurveStretch>* out, int* evaluations, VectorXd* saddle) {
    constexpr int kRestarts = 20;
    const int i1 = pr->plane_index();
    for (int k = 0; k < kRestarts; ++k) {
      if (o_.cancelled && o_.cancelled()) return {CurveEndKind::kCancelled, ""};
      FlowPoint start;
      std::string why;
      if (!pr->Rephase(u, &start, &why))
        return o_.cancelled && o_.cancelled() ? CurveEnd{CurveEndKind::kCancelled, ""}
                                              : CurveEnd{CurveEndKind::kStartFailed, why};
      pr = Problem(start, u[i1], u[i1 + 1]);
      OrbitRow row;
      row.p = u[i1], row.start = start;
      u = pr->Unknowns(row, u[i1 + 1]);
      VectorXd d = VectorXd::Zero(u.size());
      d[i1] = dir[0] / (o_.plane.to1 - o_.plane.from1);
      d[i1 + 1] = dir[1] / (o_.plane.to2 - o_.plane.from2);
      // The first correction holds the coordinate the curve moves most in
      // (its line crosses the curve transversally).
      const int fixed = std::abs(d[i1]) >= std::abs(d[i1 + 1]) ? i1 : i1 + 1;
      TraceResult r = TraceOneWay(*pr, Options(pr, u), u, fixed, d);
      *evaluations += r.evaluations;
      if (DropBad(*pr, &r.u, true, &r.ends.last, saddle)) {
        out->push_back({pr, r.u});  // (one point: where a saddle beyond sits next to it)
        return r.ends.last;
      }
      if (r.u.size() < 2)
        return r.ends.last.kind == CurveEndKind::kNone
                   ? CurveEnd{CurveEndKind::kStartFailed, "no step after moving the section"}
                   : EndOf(*pr, r.ends.last);
      out->push_back({pr, r.u});
      if (!r.stopped) return EndOf(*pr, r.ends.last);
      const VectorXd& a = r.u[r.u.size() - 2];
      u = r.u.back();
      dir = Eigen::Vector2d(u[i1] - a[i1], u[i1 + 1] - a[i1 + 1]);
    }
    return {CurveEndKind::kStopped, "the section near a stick phase after every move"};
  }

  // A cut where a contact opens, or where the return's mode changed (the
  // switching sequence changes: an SL point), is an end of the curve.
  static CurveEnd EndOf(const OrbitCurveProblem& pr, CurveEnd e) {
    if (e.kind != CurveEndKind::kStepTooSmall && e.kind != CurveEndKind::kStartFailed) return e;
    const OrbitStatus why = pr.FailureOf(e.why);
    if (why == OrbitStatus::kContactOpen) e.kind = CurveEndKind::kContactLost;
    if (why == OrbitStatus::kModeChanged) e.kind = CurveEndKind::kSliding;
    return e;
  }

 private:
  const System& system_;
  const SystemChartOptions& o_;
  CurveKind kind_;
  PoincareSection section_;
  OrbitBranchOptions bo_;
  double bound_ = 0, tol_ = 0;
  bool clocked_ = false;
  GrazingMargin margin_ = GrazingMargin::kArrival;
  VectorXd last_;  // the last accepted point (Creeps)
  int creep_ = 0;
  struct Bad {
    VectorXd u;
    std::string why;
    bool saddle;
  };
  std::vector<Bad> bad_;
};

}  // namespace

SystemCurve TraceOrbitCurve(const System& system, const SystemChartOptions& o, CurveKind kind,
                            const FlowPoint& start, double p1, double p2,
                            const PoincareSection& section, int fixed) {
  if (const std::string e = o.ValidationError(system); !e.empty()) throw InvalidArgument(e);
  if (fixed != 0 && fixed != 1) throw InvalidArgument("fixed must be 0 (p1) or 1 (p2)");
  const auto t0 = std::chrono::steady_clock::now();
  SystemCurve curve;
  curve.kind = kind, curve.section = section;
  OrbitTracer tracer(system, o, kind, section);
  std::shared_ptr<OrbitCurveProblem> problem = tracer.Problem(start, p1, p2);
  const int i1 = problem->plane_index();
  OrbitRow seed;
  seed.p = p1, seed.start = start;
  VectorXd u0 = problem->Unknowns(seed, p2);
  if (tracer.clocked()) {  // the seed's section into a slip phase
    std::string why;
    if (!problem->Rephase(u0, &seed.start, &why)) {
      curve.ends.first = {CurveEndKind::kNoStart, why};
      return curve;
    }
    problem = tracer.Problem(seed.start, p1, p2);
    u0 = problem->Unknowns(seed, p2);
  }
  if (kind == CurveKind::kGrazing) {
    tracer.ChooseMargin(seed.start, u0, i1);
    problem = tracer.Problem(seed.start, p1, p2);
  }
  TraceResult r = TraceBothWays(*problem, tracer.Options(problem, u0), u0, i1 + fixed);
  curve.ends = r.ends;
  // A way stopped on a bad point: the point dropped, the end says why.
  VectorXd saddle[2];  // neutral saddles dropped beyond the first and last ends
  const bool bad_first = tracer.DropBad(*problem, &r.u, false, &curve.ends.first, &saddle[0]);
  const bool bad_last = tracer.DropBad(*problem, &r.u, true, &curve.ends.last, &saddle[1]);
  curve.evaluations = r.evaluations;
  std::vector<CurveStretch> back, fwd;
  // Stopped near the section's stick: on at a new section start, each way.
  if (curve.ends.first.kind == CurveEndKind::kStopped && !bad_first && r.u.size() >= 2 &&
      !r.cancelled) {
    const VectorXd &a = r.u[1], &b = r.u[0];
    curve.ends.first = tracer.GoOn(problem, b, {b[i1] - a[i1], b[i1 + 1] - a[i1 + 1]}, &back,
                                   &curve.evaluations, &saddle[0]);
  } else {
    curve.ends.first = OrbitTracer::EndOf(*problem, curve.ends.first);
  }
  if (curve.ends.last.kind == CurveEndKind::kStopped && !bad_last && r.u.size() >= 2 &&
      !r.cancelled) {
    const VectorXd &a = r.u[r.u.size() - 2], &b = r.u.back();
    curve.ends.last = tracer.GoOn(problem, b, {b[i1] - a[i1], b[i1 + 1] - a[i1 + 1]}, &fwd,
                                  &curve.evaluations, &saddle[1]);
  } else {
    curve.ends.last = OrbitTracer::EndOf(*problem, curve.ends.last);
  }
  curve.gap = problem->margin() == GrazingMargin::kGap && kind == CurveKind::kGrazing;
  Assemble(back, {problem, r.u}, fwd, saddle, o, &curve);
  curve.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return curve;
}

}  // namespace stickslip
