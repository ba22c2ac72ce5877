#include "chart/forced_curve.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "flow/cached_flow.hpp"
#include "numerics/numbers.hpp"
#include "numerics/tolerances.hpp"

namespace stickslip {

FlowRequest ForcedCurveProblem::Request(double t_end, std::vector<FlowSwitch>* events) const {
  FlowRequest rq;
  rq.t_max = t_end;
  rq.variational = true;
  rq.switching = !smooth();
  rq.extrema = {0, 1};
  rq.max_steps = flow_.max_steps;
  rq.switches = events;
  return rq;
}

FlowPoint ForcedCurveProblem::Start(const ForcedModel& m, double t, double x, double xdot) const {
  if (!smooth()) return ForcedStart(m, t, x, xdot);
  // Without switching the start's slip side is its field (x' = v: below).
  return ForcedStart(m, t, x, xdot, xdot > m.v() ? Mode::kSlipAbove : Mode::kSlipBelow);
}

bool ForcedCurveProblem::Sample(const Eigen::VectorXd& u, ForcedCurveSample* s,
                                std::string* why) const {
  const ForcedModel model(plane_.At(base_, u[2], u[3]));
  std::vector<FlowSwitch> events;
  const double t0 = phase_ / model.omega();
  const FlowRun r =
      CachedFlow(model, flow_)
          .Run(Start(model, t0, u[0], u[1]), Request(t0 + m_ * model.period(), &events));
  if (!Reached(r)) {
    *why = r.message;
    return false;
  }
  s->end = Vec2(r.end.z[0], r.end.z[1]);
  s->jacobian = r.jacobian;
  s->extrema = RunExtrema(r);
  s->sticks = r.sticks, s->crossings = r.crossings;
  const Mat2& M = s->jacobian;
  s->lp = (M - Mat2::Identity()).determinant();
  s->pd = (M + Mat2::Identity()).determinant();
  s->ns = M.determinant() - 1;
  // GR (header): arrivals at x' = v, a crossing's margin |force| - mu_s > 0, a
  // stick-in's <= 0; without any, the distance of the velocity's extreme to v.
  const double mu_s = model.static_limit();
  double cross = HUGE_VAL;
  bool any = false;
  for (const FlowSwitch& e : events)
    if (e.kind == SwitchKind::kCrossing || e.kind == SwitchKind::kStickIn) {
      cross = std::min(cross, std::abs(model.StickForce(e.t, e.z[0])) - mu_s);
      any = true;
    }
  if (crossing_) {
    s->crossing = true;
    s->margin = any ? cross : HUGE_VAL;
  } else {
    s->crossing = false;
    // The slip field of the section point's side, continued across x' = v
    // (smooth()): the gap is smooth through 0, negative past the grazing.
    const Extrema& x = s->extrema;
    s->margin = u[1] <= model.v() ? model.v() - x.xdot_max : x.xdot_min - model.v();
  }
  if (!std::isfinite(s->margin) && kind_ == CurveKind::kGrazing) {
    *why = "the orbit does not reach x' = v (no crossing, no stick)";
    return false;
  }
  return true;
}

bool ForcedCurveProblem::Rephase(Eigen::VectorXd* u, std::string* why) {
  const ForcedModel model(plane_.At(base_, (*u)[2], (*u)[3]));
  struct Sample {
    double t, x, xdot;
    Mode mode;
  };
  std::vector<Sample> samples;
  const double t0 = phase_ / model.omega();
  const FlowPoint start = Start(model, t0, (*u)[0], (*u)[1]);
  samples.push_back({start.t, start.z[0], start.z[1], start.mode[0]});
  FlowRequest rq = Request(t0 + m_ * model.period(), nullptr);
  rq.variational = false;
  rq.step_observer = [&](double t, const double* z, const ModeSet& md) {
    samples.push_back({t, z[0], z[1], md[0]});
  };
  const FlowRun run = CachedFlow(model, flow_).Run(start, rq);
  if (!Reached(run)) return *why = run.message, false;
  const Sample* best = nullptr;
  for (const Sample& p : samples)
    if (p.mode != Mode::kStick &&
        (!best || std::abs(p.xdot - model.v()) > std::abs(best->xdot - model.v())))
      best = &p;
  if (!best) return *why = "the orbit sticks at every sample", false;
  phase_ = std::fmod(best->t * model.omega(), 2 * M_PI);
  (*u)[0] = best->x, (*u)[1] = best->xdot;
  return true;
}

CurveEnd ForcedCurveProblem::SameBranch(const PalcPoint& last, const PalcPoint& next,
                                        const Eigen::VectorXd& scale) const {
  const Tolerances tol;
  // PALC puts next on the plane through last.u + ds t normal to t (scaled):
  // ds is next's offset along t, the rest is what the corrector moved.
  const Eigen::VectorXd d = (next.u - last.u).cwiseQuotient(scale);
  const double ds = last.tangent.dot(d), off = (d - ds * last.tangent).norm();
  if (!(off <= tol.forced_branch_offset * std::abs(ds)))
    return {CurveEndKind::kBranchJump, "the corrector moved " + Num(off / std::abs(ds), 3) +
                                           " steps off the predictor at " + plane_.p1.name() +
                                           " = " + Num(next.u[2], 6) + ", " + plane_.p2.name() +
                                           " = " + Num(next.u[3], 6)};
  ForcedCurveSample a, b;
  std::string why;
  if (!Sample(last.u, &a, &why) || !Sample(next.u, &b, &why))
    return {CurveEndKind::kBranchJump, why};
  const double res =
      std::max({std::abs(b.end[0] - next.u[0]), std::abs(b.end[1] - next.u[1]), std::abs(Test(b))});
  if (!(res <= tol.curve_residual))
    return {CurveEndKind::kSliding,
            "residual " + Num(res, 3) + " (the map is not smooth there: a sliding point)"};
  // (a GR curve is where the structure changes: its margin spans both sides)
  if (kind_ != CurveKind::kGrazing && (a.sticks != b.sticks || a.crossings != b.crossings))
    return {CurveEndKind::kSliding, "sticks " + std::to_string(a.sticks) + " -> " +
                                        std::to_string(b.sticks) + ", crossings " +
                                        std::to_string(a.crossings) + " -> " +
                                        std::to_string(b.crossings)};
  // A shorter period: the point comes back after d | m, d < m, periods.
  const ForcedModel model(plane_.At(base_, next.u[2], next.u[3]));
  const double t0 = phase_ / model.omega();
  for (int d = 1; d < m_; ++d) {
    if (m_ % d != 0) continue;
    FlowRequest rq = Request(t0 + d * model.period(), nullptr);
    rq.variational = false;
    const FlowRun r = CachedFlow(model, flow_).Run(Start(model, t0, next.u[0], next.u[1]), rq);
    if (Reached(r) && std::max(std::abs(r.end.z[0] - next.u[0]), std::abs(r.end.z[1] - next.u[1])) <
                          tol.forced_lower_period)
      return {CurveEndKind::kBranchJump,
              "the orbit has period " + std::to_string(d) + " < m = " + std::to_string(m_)};
  }
  return {};
}

double ForcedCurveProblem::Test(const ForcedCurveSample& s) const {
  switch (kind_) {
    case CurveKind::kFold:
      return s.lp;
    case CurveKind::kPeriodDoubling:
      return s.pd;
    case CurveKind::kTorus:
      return s.ns;
    case CurveKind::kGrazing:
      return s.margin;
    case CurveKind::kHopf:  // no forced curve (TraceForcedCurve refuses it)
      break;
  }
  return 0;
}

std::string ForcedCurveProblem::DomainError(const Eigen::VectorXd& u) const {
  if (!u.allFinite()) return "non-finite point";
  const std::string e = ValidationError(plane_.At(base_, u[2], u[3]));
  if (!e.empty()) return e;
  const double size = std::max(std::abs(u[0]), std::abs(u[1]));
  if (size > Tolerances::kForcedCurveAmplitude)
    return "|x| or |x'| = " + Num(size) + " beyond " + Num(Tolerances::kForcedCurveAmplitude);
  return {};
}

bool ForcedCurveProblem::Evaluate(const Eigen::VectorXd& u, Eigen::VectorXd* f,
                                  Eigen::MatrixXd* jac, std::string* why) {
  ForcedCurveSample s;
  if (!Sample(u, &s, why)) return false;
  f->resize(3);
  *f << s.end[0] - u[0], s.end[1] - u[1], Test(s);
  {
    // Central differences, step ~ cbrt(eps) of each unknown's scale.
    chord_.resize(3, 4);
    const double scale[4] = {1, 1, plane_.width1(), plane_.width2()};
    for (int k = 0; k < 4; ++k) {
      const double d = Tolerances().forced_curve_difference * std::max(scale[k], std::abs(u[k]));
      Eigen::VectorXd up = u, um = u;
      up[k] += d, um[k] -= d;
      ForcedCurveSample sp, sm;
      if (!DomainError(um).empty()) um = u;
      if (!Sample(up, &sp, why) || !Sample(um, &sm, why)) return false;
      const double span = up[k] - um[k];
      chord_(0, k) = (sp.end[0] - sm.end[0]) / span;
      chord_(1, k) = (sp.end[1] - sm.end[1]) / span;
      chord_(2, k) = (Test(sp) - Test(sm)) / span;
    }
  }
  *jac = chord_;
  jac->block(0, 0, 2, 2) = s.jacobian - Mat2::Identity();  // exact at every point
  return true;
}

}  // namespace stickslip
