#include "chart/chart_trace.hpp"

#include <algorithm>
#include <cmath>

#include "numerics/tolerances.hpp"

namespace stickslip {

using Eigen::VectorXd;

namespace {

PalcOptions Options(const PalcProblem& problem, const TraceOptions& o) {
  PalcOptions p;
  p.ds = p.ds_max = o.max_step;
  p.ds_min = Tolerances().chart_min_step * o.max_step;
  p.tol = o.tol;
  p.max_newton = 12;
  p.max_points = kMaxCurvePoints;
  p.scale = VectorXd::Constant(problem.unknowns(), o.other_scale);
  p.scale[o.i1] = o.plane.width1();
  p.scale[o.i1 + 1] = o.plane.width2();
  p.cancelled = o.cancelled;  // also between rejected steps
  return p;
}

// The end of a way cut short by PALC (status other than kClosed).
CurveEndKind CutEnd(PalcStatus s) {
  switch (s) {
    case PalcStatus::kMaxPoints:
      return CurveEndKind::kMaxPoints;
    case PalcStatus::kStepTooSmall:
      return CurveEndKind::kStepTooSmall;
    case PalcStatus::kStartFailed:
      return CurveEndKind::kStartFailed;
    case PalcStatus::kStopped:
    case PalcStatus::kClosed:
      break;
  }
  return CurveEndKind::kStopped;
}

struct Leg {
  std::vector<VectorXd> u;
  CurveEnd end;
  std::string cut;  // the way ended early (a PALC failure): why
  int evaluations = 0;
  bool cancelled = false, stopped = false, closed = false;
  CurveEnd left;  // set when the same-branch check ended the way
};

// Replaces the last point (outside) by the border crossing of the last chord.
void Land(Palc& palc, const TraceOptions& o, std::vector<VectorXd>& u) {
  const VectorXd a = u[u.size() - 2], b = u.back();
  u.pop_back();
  const double lo[2] = {o.plane.from1, o.plane.from2}, hi[2] = {o.plane.to1, o.plane.to2};
  double s = 2;
  int k_cross = -1;
  double border = 0;
  for (int j = 0; j < 2; ++j) {
    const int k = o.i1 + j;
    for (double edge : {lo[j], hi[j]}) {
      const bool crosses = (edge == lo[j]) ? b[k] < edge : b[k] > edge;
      if (!crosses || b[k] == a[k]) continue;
      const double sk = (edge - a[k]) / (b[k] - a[k]);
      if (sk < s) s = sk, k_cross = k, border = edge;
    }
  }
  if (k_cross < 0) return;
  VectorXd pred = a + s * (b - a);
  pred[k_cross] = border;
  const PalcCorrection c = palc.CorrectFixed(pred, k_cross);
  if (c.ok && (c.u - pred).norm() < (b - a).norm()) u.push_back(c.u);
}

// A way that failed within two steps of the border (the rectangle's edge is the
// model's domain edge, e.g. beta = 0, where iterates beyond it cannot be
// evaluated): the border point along the last tangent, if it corrects.
bool LandAhead(Palc& palc, const TraceOptions& o, const PalcPoint& last, std::vector<VectorXd>& u) {
  const VectorXd dir = last.tangent.cwiseProduct(palc.options().scale);
  const double lo[2] = {o.plane.from1, o.plane.from2}, hi[2] = {o.plane.to1, o.plane.to2};
  double s = HUGE_VAL;
  int k_cross = -1;
  double border = 0;
  for (int j = 0; j < 2; ++j) {
    const int k = o.i1 + j;
    if (dir[k] == 0) continue;
    const double edge = dir[k] > 0 ? hi[j] : lo[j], sk = (edge - last.u[k]) / dir[k];
    if (sk >= 0 && sk < s) s = sk, k_cross = k, border = edge;
  }
  if (k_cross < 0 || s > 2 * o.max_step) return false;
  VectorXd pred = last.u + s * dir;
  pred[k_cross] = border;
  const PalcCorrection c = palc.CorrectFixed(pred, k_cross);
  if (!c.ok || !o.plane.Contains(c.u[o.i1], c.u[o.i1 + 1])) return false;
  u.push_back(c.u);
  return true;
}

// A way whose last point left the branch (leg->left): that point dropped;
// beyond the border, the border point along the last tangent instead; inside,
// the end moved up to where the branch ends, the last step bisected (a point
// that corrects and continues the branch, or not) to chart_end_bisection.
void EndOffBranch(Palc& palc, const TraceOptions& o, const std::vector<PalcPoint>& pts, Leg* leg) {
  leg->u.pop_back();
  leg->end = leg->left;
  leg->cut = leg->end.Text();
  if (pts.size() < 2) return;
  const PalcPoint& last = pts[pts.size() - 2];
  const VectorXd& scale = palc.options().scale;
  const VectorXd& b = pts.back().u;
  auto continues = [&](const VectorXd& u, CurveEnd* why) {
    PalcPoint p = last;
    p.u = u;
    *why = o.same_branch(last, p, scale);
    return why->kind == CurveEndKind::kNone;
  };
  CurveEnd why;
  if (!o.plane.Contains(b[o.i1], b[o.i1 + 1])) {
    if (LandAhead(palc, o, last, leg->u)) {
      if (continues(leg->u.back(), &why))
        leg->end = {CurveEndKind::kBorder, ""}, leg->cut.clear();
      else
        leg->u.pop_back();
    }
    return;
  }
  if (!o.refine_ends) return;
  double lo = 0, hi = last.tangent.dot((b - last.u).cwiseQuotient(scale));
  VectorXd best;
  while (hi - lo > Tolerances().chart_end_bisection) {
    const double s = 0.5 * (lo + hi);
    why = {};  // this point's reason only (outside the plane: none)
    const PalcCorrection c =
        palc.Correct(last.u + s * last.tangent.cwiseProduct(scale), last.tangent);
    if (c.ok && o.plane.Contains(c.u[o.i1], c.u[o.i1 + 1]) && continues(c.u, &why)) {
      lo = s, best = c.u;
    } else {
      hi = s;
      if (c.ok && why.kind != CurveEndKind::kNone) leg->end = why;
    }
  }
  if (best.size() > 0) leg->u.push_back(best);
  leg->cut = leg->end.Text();
}

// A step that seems to leave its branch (same_branch) is tried again in two
// halves: where the curve bends, the corrector's offset shrinks like the
// step squared and both halves continue; a jump to another branch stays.
CurveEnd LeftBranch(Palc& palc, const TraceOptions& o, const PalcPoint& last,
                    const PalcPoint& next) {
  const VectorXd& scale = palc.options().scale;
  CurveEnd why = o.same_branch(last, next, scale);
  if (why.kind != CurveEndKind::kBranchJump) return why;
  const double ds = last.tangent.dot((next.u - last.u).cwiseQuotient(scale));
  const PalcCorrection c =
      palc.Correct(last.u + 0.5 * ds * last.tangent.cwiseProduct(scale), last.tangent);
  if (!c.ok) return why;
  PalcPoint mid;
  mid.u = c.u;
  mid.tangent = palc.Tangent(c.jac, last.tangent);
  if (o.same_branch(last, mid, scale).kind == CurveEndKind::kNone &&
      o.same_branch(mid, next, scale).kind == CurveEndKind::kNone)
    return {};
  return why;
}

Leg Follow(Palc& palc, const TraceOptions& o, const VectorXd& u0, int fixed,
           const VectorXd& direction) {
  Leg leg;
  bool outside = false;
  const int before = palc.evaluations();
  auto monitor = [&](const std::vector<PalcPoint>& pts) {
    const VectorXd& u = pts.back().u;
    if (o.cancelled && o.cancelled()) return !(leg.cancelled = true);
    if (pts.size() > 1 && o.same_branch) {
      leg.left = LeftBranch(palc, o, pts[pts.size() - 2], pts.back());
      if (leg.left.kind != CurveEndKind::kNone) return false;
    }
    if (!o.plane.Contains(u[o.i1], u[o.i1 + 1])) return !(outside = true);
    if (pts.size() > 1 && o.stop && o.stop(u)) return !(leg.stopped = true);
    return true;
  };
  const PalcResult r = palc.Trace(u0, fixed, direction, monitor);
  if (r.status == PalcStatus::kStopped && r.message == "cancelled") leg.cancelled = true;
  for (const PalcPoint& p : r.points) leg.u.push_back(p.u);
  if (leg.left.kind != CurveEndKind::kNone) {
    EndOffBranch(palc, o, r.points, &leg);
  } else if (outside) {
    leg.end.kind = CurveEndKind::kBorder;
    if (leg.u.size() >= 2)
      Land(palc, o, leg.u);
    else
      leg.u.clear();
  } else if (leg.stopped) {
    leg.end.kind = CurveEndKind::kStopped;
  } else if (r.status == PalcStatus::kClosed) {
    leg.end.kind = CurveEndKind::kClosed;
    leg.closed = true;
  } else if (r.status == PalcStatus::kStepTooSmall && !r.points.empty() &&
             LandAhead(palc, o, r.points.back(), leg.u)) {
    leg.end.kind = CurveEndKind::kBorder;
  } else if (!leg.cancelled) {
    leg.end = {CutEnd(r.status), r.message};
    leg.cut = leg.end.Text();
  } else {
    leg.end.kind = CurveEndKind::kCancelled;
  }
  leg.evaluations = palc.evaluations() - before;
  return leg;
}

// Once the cancel hook holds (it stays set), an end that reads as a failure
// (a start, a step or a correction that failed on the cut-short run) is the cut.
void EndsCancelled(const TraceOptions& o, TraceResult* t) {
  if (!(o.cancelled && o.cancelled())) return;
  t->cancelled = true;
  for (CurveEnd* e : {&t->ends.first, &t->ends.last})
    if (e->kind == CurveEndKind::kNoStart || e->kind == CurveEndKind::kStartFailed ||
        e->kind == CurveEndKind::kStepTooSmall || e->kind == CurveEndKind::kMaxPoints)
      *e = {CurveEndKind::kCancelled, ""};
  if (t->ends.last.kind == CurveEndKind::kNone) t->ends.last.kind = CurveEndKind::kCancelled;
  t->cut.clear();
}

}  // namespace

TraceResult TraceOneWay(PalcProblem& problem, const TraceOptions& options, const VectorXd& u0,
                        int fixed, const VectorXd& direction) {
  Palc palc(problem, Options(problem, options));
  const Leg leg = Follow(palc, options, u0, fixed, direction);
  TraceResult t;
  t.u = leg.u;
  t.ends.first.kind = CurveEndKind::kStart;
  t.ends.last = leg.end;
  t.cut = leg.cut;
  t.evaluations = leg.evaluations;
  t.cancelled = leg.cancelled;
  t.stopped = leg.stopped;
  EndsCancelled(options, &t);
  return t;
}

TraceResult TraceBothWays(PalcProblem& problem, const TraceOptions& options, const VectorXd& u0,
                          int fixed) {
  Palc palc(problem, Options(problem, options));
  TraceResult t;
  // The tangent at the start orients the two ways.
  const PalcCorrection c = palc.CorrectFixed(u0, fixed);
  if (!c.ok) {
    t.ends.first = {CurveEndKind::kNoStart, c.why};
    t.cut = t.ends.Text();
    t.evaluations = palc.evaluations();
    EndsCancelled(options, &t);
    return t;
  }
  const VectorXd tangent = palc.Tangent(c.jac, VectorXd());
  // A start on the border: the way that leaves the rectangle at once is not taken.
  auto leaves = [&](const VectorXd& dir) {
    const VectorXd u = c.u + Tolerances().border_probe * dir.cwiseProduct(palc.options().scale);
    return !options.plane.Contains(u[options.i1], u[options.i1 + 1]);
  };
  Leg fwd, back;
  fwd.end.kind = back.end.kind = CurveEndKind::kBorder;
  if (!leaves(tangent)) fwd = Follow(palc, options, c.u, fixed, tangent);
  t.cancelled = fwd.cancelled;
  if (!fwd.closed && !leaves(-tangent)) {
    if (fwd.cancelled)
      back.end.kind = CurveEndKind::kCancelled;  // the way back not taken
    else
      back = Follow(palc, options, c.u, fixed, -tangent);
  }
  if (fwd.u.empty() && back.u.empty()) fwd.u.push_back(c.u);
  t.cancelled = t.cancelled || back.cancelled;
  t.u.assign(back.u.rbegin(), back.u.rend());
  if (!t.u.empty() && !fwd.u.empty()) t.u.pop_back();  // the shared start
  t.u.insert(t.u.end(), fwd.u.begin(), fwd.u.end());
  if (fwd.closed) {
    t.ends.first.kind = t.ends.last.kind = CurveEndKind::kClosed;
  } else {
    t.ends = {back.end, fwd.end};
    if (back.end.kind == CurveEndKind::kNone) t.ends.first.kind = CurveEndKind::kStart;
  }
  t.cut = back.cut.empty() ? fwd.cut : back.cut;
  t.evaluations = palc.evaluations();
  EndsCancelled(options, &t);
  return t;
}

bool NearCurve(const std::vector<Curve>& curves, CurveKind kind, const Plane& plane,
               const Eigen::Vector2d& x) {
  const Eigen::Vector2d scale(plane.width1(), plane.width2());
  for (const Curve& c : curves)
    if (c.kind == kind && NearPolyline(c.points, x, scale, Tolerances().near_curve)) return true;
  return false;
}

std::string CurveEnd::Text() const {
  return why.empty() ? std::string(Name(kind)) : std::string(Name(kind)) + ": " + why;
}

std::string CurveEnds::Text() const {
  if (first.kind == CurveEndKind::kClosed && last.kind == CurveEndKind::kClosed) return "closed";
  if (first.kind == CurveEndKind::kNoStart) return first.Text();
  return first.Text() + " / " + last.Text();
}

}  // namespace stickslip
