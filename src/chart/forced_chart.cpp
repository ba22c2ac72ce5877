// The forced chart (stickslip/chart/forced_chart.hpp): seeds from
// one-parameter runs (ContinueForced) on lines across the rectangle, each
// seed's curve traced both ways by chart_trace.hpp on forced_curve.hpp's
// system, codimension-two points from sign changes along the curves.
#include "stickslip/chart/forced_chart.hpp"

#include <chrono>
#include <cmath>
#include <functional>

#include "chart/chart_trace.hpp"
#include "chart/forced_chart_seeds.hpp"
#include "chart/forced_curve.hpp"
#include "numerics/numbers.hpp"
#include "numerics/tolerances.hpp"
#include "stickslip/errors.hpp"
#include "stickslip/forced/orbit_scan.hpp"

namespace stickslip {

namespace {

using Eigen::VectorXd;

// Points of one stretch of a curve, at one section phase.
struct Stretch {
  double phase = 0;
  std::vector<VectorXd> u;
};

// Goes on from u (the end of a stretch stopped near the section's stick) at a
// new section phase, along `dir` in the plane; up to kRestarts times.
CurveEnd GoOn(ForcedCurveProblem& problem, const TraceOptions& t, VectorXd u, Eigen::Vector2d dir,
              std::vector<Stretch>* out, int* evaluations, std::string* bad) {
  constexpr int kRestarts = 20;
  for (int k = 0; k < kRestarts; ++k) {
    std::string why;
    if (!problem.Rephase(&u, &why)) return {CurveEndKind::kStartFailed, why};
    VectorXd d = VectorXd::Zero(4);
    d[2] = dir[0] / t.plane.width1(), d[3] = dir[1] / t.plane.width2();
    const int fixed = std::abs(d[2]) >= std::abs(d[3]) ? 3 : 2;
    const TraceResult r = TraceOneWay(problem, t, u, fixed, d);
    *evaluations += r.evaluations;
    if (r.u.size() < 2)
      return r.ends.last.kind == CurveEndKind::kNone
                 ? CurveEnd{CurveEndKind::kStartFailed, "no step after rephasing"}
                 : r.ends.last;
    out->push_back({problem.phase(), r.u});
    if (!r.stopped) return r.ends.last;
    if (!bad->empty()) {
      out->back().u.pop_back();
      return {CurveEndKind::kStopped, *bad};
    }
    const VectorXd& a = r.u[r.u.size() - 2];
    u = r.u.back();
    dir = Eigen::Vector2d(u[2] - a[2], u[3] - a[3]);
  }
  return {CurveEndKind::kStopped, "section near the stick phase after every rephasing"};
}

// The rows of the traced stretches, each sampled at its section phase.
std::vector<ForcedCurvePoint> Points(ForcedCurveProblem& problem, const std::vector<Stretch>& all,
                                     CurveKind kind) {
  std::vector<ForcedCurvePoint> points;
  std::string why;
  for (const Stretch& st : all) {
    problem.set_phase(st.phase);
    for (const VectorXd& u : st.u) {
      ForcedCurveSample smp;
      if (!problem.Sample(u, &smp, &why)) continue;
      ForcedCurvePoint p;
      p.p1 = u[2], p.p2 = u[3], p.x0 = u[0], p.xdot0 = u[1], p.phase = st.phase;
      p.sticks = smp.sticks, p.crossings = smp.crossings;
      p.extrema = smp.extrema;
      Multipliers(smp.jacobian, p.multipliers);
      p.flag = kind == CurveKind::kTorus ? p.multipliers[0].imag() == 0 : smp.crossing;
      points.push_back(p);
    }
  }
  return points;
}

// GR: the margin (crossing or grazing) nearer zero at the seed u0.
void ChooseMargin(ForcedCurveProblem& problem, const VectorXd& u0) {
  ForcedCurveSample a, b;
  std::string why;
  problem.set_crossing(false);
  const bool graze = problem.Sample(u0, &b, &why);
  problem.set_crossing(true);
  const bool cross = problem.Sample(u0, &a, &why);
  problem.set_crossing(cross && (!graze || std::abs(a.margin) <= std::abs(b.margin)));
}

// The tracer's stop test: true near the section's stick phase (the section
// moves on), or at an accepted point whose residual is not small (a Newton
// update that shrank on a kink of the map, not on a root: *bad says so).
std::function<bool(const VectorXd&)> StopTest(ForcedCurveProblem& problem, double v,
                                              std::string* bad) {
  const double near = Tolerances().forced_section_near_stick;
  const double max_residual = Tolerances().curve_residual;
  return [&problem, v, near, max_residual, bad](const VectorXd& u) {
    ForcedCurveSample smp;
    std::string w;
    if (!problem.Sample(u, &smp, &w)) return !(*bad = w).empty();
    const double res = std::max(
        {std::abs(smp.end[0] - u[0]), std::abs(smp.end[1] - u[1]), std::abs(problem.TestOf(smp))});
    if (!(res <= max_residual))
      return !(*bad = "residual " + Num(res, 3) +
                      " at an accepted point (the map is not smooth there)")
                  .empty();
    return std::abs(u[1] - v) < near;
  };
}

ForcedCurve Trace(const ForcedParams& base, const ForcedChartOptions& o, const ForcedSeed& s,
                  std::string* message) {
  const auto t0 = std::chrono::steady_clock::now();
  ForcedCurve curve;
  curve.kind = s.kind, curve.m = s.m, curve.seed = s.where;
  ForcedCurveProblem problem(base, o.plane, s.kind, s.m, o.flow);
  VectorXd u0(4);
  u0 << s.x0, s.xdot0, s.p1, s.p2;
  std::string why;
  if (!problem.Rephase(&u0, &why)) {
    curve.ends.first = {CurveEndKind::kNoStart, why};
    *message = curve.ends.Text();
    return curve;
  }
  if (s.kind == CurveKind::kGrazing) ChooseMargin(problem, u0);
  TraceOptions t;
  t.plane = o.plane;
  t.i1 = 2;
  t.max_step = o.max_step;
  t.tol = Tolerances::From(o.flow.rtol, o.flow.atol).ForcedCurveCorrector();
  t.cancelled = o.cancelled;
  std::string bad;
  t.stop = StopTest(problem, base.base.v, &bad);
  t.refine_ends = true;
  t.same_branch = [&problem](const PalcPoint& a, const PalcPoint& b, const VectorXd& scale) {
    return problem.SameBranch(a, b, scale);
  };
  TraceResult r = TraceBothWays(problem, t, u0, s.fixed);
  curve.ends = r.ends;
  // A way stopped on a bad point: the point dropped, the end says why (the
  // back way cannot be told from the forward one here: both are checked).
  std::string bad_first, bad_last;
  auto bad_at = [&](const VectorXd& u) {
    bad.clear();
    t.stop(u);
    return bad;
  };
  if (r.ends.first.kind == CurveEndKind::kStopped && !r.u.empty() &&
      !(bad_first = bad_at(r.u.front())).empty())
    r.u.erase(r.u.begin()), curve.ends.first = {CurveEndKind::kStopped, bad_first};
  if (r.ends.last.kind == CurveEndKind::kStopped && !r.u.empty() &&
      !(bad_last = bad_at(r.u.back())).empty())
    r.u.pop_back(), curve.ends.last = {CurveEndKind::kStopped, bad_last};
  bad.clear();
  curve.evaluations = r.evaluations;
  const double phase = problem.phase();
  std::vector<Stretch> back, fwd;
  // TraceBothWays gives the back way reversed, then the forward way.
  if (r.ends.first.kind == CurveEndKind::kStopped && bad_first.empty() && r.u.size() >= 2) {
    const VectorXd &a = r.u[1], &b = r.u[0];
    curve.ends.first =
        GoOn(problem, t, b, {b[2] - a[2], b[3] - a[3]}, &back, &curve.evaluations, &bad);
  }
  if (r.ends.last.kind == CurveEndKind::kStopped && bad_last.empty() && r.u.size() >= 2) {
    problem.set_phase(phase);
    const VectorXd &a = r.u[r.u.size() - 2], &b = r.u.back();
    curve.ends.last =
        GoOn(problem, t, b, {b[2] - a[2], b[3] - a[3]}, &fwd, &curve.evaluations, &bad);
  }
  std::vector<Stretch> all;
  for (auto it = back.rbegin(); it != back.rend(); ++it)
    all.push_back({it->phase, std::vector<VectorXd>(it->u.rbegin(), it->u.rend())});
  all.push_back({phase, r.u});
  all.insert(all.end(), fwd.begin(), fwd.end());
  auto cut = [](const CurveEnd& e) {
    return e.kind == CurveEndKind::kMaxPoints || e.kind == CurveEndKind::kStepTooSmall ||
           e.kind == CurveEndKind::kStartFailed || e.kind == CurveEndKind::kNoStart ||
           e.kind == CurveEndKind::kStopped || e.kind == CurveEndKind::kBranchJump ||
           e.kind == CurveEndKind::kSliding;
  };
  *message = cut(curve.ends.first) || cut(curve.ends.last) ? curve.ends.Text() : "";
  curve.points = Points(problem, all, s.kind);
  curve.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return curve;
}

}  // namespace

ForcedCurve TraceForcedCurve(const ForcedParams& base, const ForcedChartOptions& options,
                             CurveKind kind, int m, double x0, double xdot0, double p1, double p2,
                             std::string* message) {
  const std::string e = options.ValidationError(base);
  if (!e.empty()) throw InvalidArgument(e);
  if (kind == CurveKind::kHopf)
    throw InvalidArgument("kind HB: a forced orbit's curves are LP, PD, NS and GR");
  ForcedSeed s{kind, m, x0, xdot0, p1, p2, 3, "given"};
  return Trace(base, options, s, message);
}

void FindCodim2(const ForcedParams& base, const ForcedChartOptions& o, const ForcedCurve& c,
                int index, std::vector<ForcedCodim2>* out);  // forced_codim2.cpp
void FindDoubleGrazing(const std::vector<ForcedCurve>& curves, const Plane& pl,
                       std::vector<ForcedCodim2>* out);

ForcedChartResult ForcedChart(const ForcedParams& base, const ForcedChartOptions& o) {
  const std::string e = o.ValidationError(base);
  if (!e.empty()) throw InvalidArgument(e);
  const auto t0 = std::chrono::steady_clock::now();
  ForcedChartResult r;
  auto cancelled = [&o] { return o.cancelled && o.cancelled(); };
  if (o.curves) {
    const Plane& pl = o.plane;
    for (int line = 0; line < o.seed_lines && !cancelled(); ++line) {
      const double f = (line + 0.5) / o.seed_lines;
      for (const bool along1 : {true, false}) {
        const double c = along1 ? pl.from2 + f * pl.width2() : pl.from1 + f * pl.width1();
        for (const ForcedSeed& s : SeedsOnLine(base, o, along1, c, &r.seed_runs)) {
          if (cancelled() || NearForcedCurve(r.curves, s, pl)) continue;
          std::string why;
          ForcedCurve curve = Trace(base, o, s, &why);
          auto failed = [](const CurveEnd& e) {
            return e.kind == CurveEndKind::kStartFailed || e.kind == CurveEndKind::kNoStart;
          };
          // The seed did not correct onto a curve (e.g. a sliding point of
          // stick-slip orbits, no boundary of non-stop motion): counted, not drawn.
          if (curve.points.size() < 2 || (failed(curve.ends.first) && failed(curve.ends.last))) {
            ++r.seeds_not_traced;
            continue;
          }
          // A curve of stick-slip orbits often ends inside the rectangle where
          // the map stops being smooth (a sliding point): its ends say so.
          r.cut_curves += !why.empty();
          FindCodim2(base, o, curve, static_cast<int>(r.curves.size()), &r.codim2);
          r.curves.push_back(std::move(curve));
        }
      }
    }
  }
  FindDoubleGrazing(r.curves, o.plane, &r.codim2);
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (o.n1 > 0 && !cancelled()) {
    const auto t1 = std::chrono::steady_clock::now();
    bool cut = false;
    r.grid = ForcedResponseGrid(base, o, &cut);
    r.grid_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t1).count();
    if (r.grid.failed > 0 && r.status == ChartStatus::kOk)
      r.status = ChartStatus::kPartial, r.message = r.grid.failure;
  }
  if (cancelled()) r.status = ChartStatus::kCancelled, r.message = "cancelled";
  return r;
}

}  // namespace stickslip
