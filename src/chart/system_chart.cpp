// The chart of any system (stickslip/chart/system_chart.hpp):
// seeds from one-parameter runs on lines across the rectangle
// (system_chart_seeds.hpp), each seed's curve traced both ways by
// chart_trace.hpp on orbit_curve.hpp's or steady_hopf_curve.hpp's problem.
#include "stickslip/chart/system_chart.hpp"

#include <chrono>
#include <cmath>

#include "chart/steady_hopf_curve.hpp"
#include "chart/system_chart_seeds.hpp"
#include "chart/system_chart_trace.hpp"
#include "numerics/numbers.hpp"
#include "numerics/tolerances.hpp"
#include "stickslip/errors.hpp"

namespace stickslip {

using Eigen::VectorXd;

namespace {

double Seconds(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// A point of an HB curve onto the test's zero by Newton steps in one plane
// coordinate, the other held: the one on the rectangle's border if u lies on
// it, else the one with the smaller gradient component. Steps are kept while
// the test shrinks (the corrector leaves points within its tolerance on the
// update; here the rest point costs no run).
void Polish(SteadyHopfProblem& problem, const SystemPlane& pl, VectorXd* u) {
  constexpr int kSteps = 3;
  for (int k = 0; k < kSteps; ++k) {
    VectorXd f;
    Eigen::MatrixXd jac;
    std::string why;
    if (!problem.Evaluate(*u, &f, &jac, &why) || f[0] == 0) return;
    const bool on1 = (*u)[0] == pl.from1 || (*u)[0] == pl.to1;
    const bool on2 = (*u)[1] == pl.from2 || (*u)[1] == pl.to2;
    const double w1 = pl.to1 - pl.from1, w2 = pl.to2 - pl.from2;
    int i = std::abs(jac(0, 0)) * w1 >= std::abs(jac(0, 1)) * w2 ? 0 : 1;  // the one moved
    if (on1 != on2) i = on1 ? 1 : 0;
    if (!(jac(0, i) != 0)) return;
    VectorXd v = *u;
    v[i] -= f[0] / jac(0, i);
    SteadyState s;
    double test = 0;
    if (!pl.Contains(v[0], v[1]) || !problem.Sample(v, &s, &test, &why) ||
        !(std::abs(test) < std::abs(f[0])))
      return;
    *u = v;
  }
}

}  // namespace

TraceOptions TraceFor(const SystemChartOptions& o, int i1) {
  TraceOptions t;
  t.plane.from1 = o.plane.from1, t.plane.to1 = o.plane.to1;
  t.plane.from2 = o.plane.from2, t.plane.to2 = o.plane.to2;
  t.i1 = i1;
  t.max_step = o.max_step;
  const FlowOptions& flow = o.branch.shooting.flow;
  t.tol = Tolerances::From(flow.rtol, flow.atol).SystemCurveCorrector();
  t.cancelled = o.cancelled;
  return t;
}

int SystemChart::points() const {
  int n = 0;
  for (const SystemCurve& c : curves) n += static_cast<int>(c.points.size());
  return n;
}

std::string SystemPlane::ValidationError(const System& s) const {
  const int np = s.parameters();
  if (p1 < 0 || p1 >= np || p2 < 0 || p2 >= np)
    return "a chart's axes are parameter indices in [0, " + std::to_string(np - 1) + "]";
  if (p1 == p2) return "the two axes are both " + s.ParameterName(p1);
  for (int j : {p1, p2})  // an axis the system does not depend on: every curve flat in it
    if (std::string e = s.ParameterError(j); !e.empty()) return e;
  for (double x : {from1, to1, from2, to2})
    if (!std::isfinite(x)) return "a range end is not finite";
  if (!(from1 < to1)) return "the first range is empty or inverted: from >= to";
  if (!(from2 < to2)) return "the second range is empty or inverted: from2 >= to2";
  if (to1 - from1 < kMinRelativeWidth * std::max(std::abs(from1), std::abs(to1)) ||
      to2 - from2 < kMinRelativeWidth * std::max(std::abs(from2), std::abs(to2)))
    return "a range is narrower than " + Num(kMinRelativeWidth) + " max(|from|, |to|)";
  constexpr int kEdge = 17;
  for (int k = 0; k < kEdge; ++k) {
    const double f = static_cast<double>(k) / (kEdge - 1);
    const double x1 = from1 + f * (to1 - from1), x2 = from2 + f * (to2 - from2);
    const double pts[4][2] = {{x1, from2}, {x1, to2}, {from1, x2}, {to1, x2}};
    for (const auto& pt : pts) {
      const std::string e = SystemAt(s, *this, pt[0], pt[1])->ValidationError();
      if (!e.empty())
        return "at " + s.ParameterName(p1) + " = " + Num(pt[0], 6) + ", " + s.ParameterName(p2) +
               " = " + Num(pt[1], 6) + ": " + e;
    }
  }
  return {};
}

std::string SystemChartOptions::ValidationError(const System& s) const {
  if (s.clocks() > 1) return "a chart takes systems with at most one clock";
  std::string e = plane.ValidationError(s);
  if (e.empty()) e = branch.ValidationError();
  if (e.empty()) e = IntRangeError("seed_lines", seed_lines, 0, kMaxSeedLines);
  if (e.empty()) e = IntRangeError("settle_points", settle_points, 2, kMaxSettlePoints);
  if (e.empty()) e = IntRangeError("max_m", max_m, 1, kMaxMultiple);
  if (!e.empty()) return e;
  if (!(max_step >= 1.0 / kMaxCurvePoints && max_step <= kMaxStepLimit))
    return "max_step = " + Num(max_step) + " must lie in [1/" + std::to_string(kMaxCurvePoints) +
           ", " + Num(kMaxStepLimit) + "]";
  if (!(transient > 0 && std::isfinite(transient)))
    return "transient = " + Num(transient) + " must be finite and > 0";
  if (!std::isfinite(disturbance)) return "disturbance must be finite";
  return {};
}

SystemCurve TraceHopfCurve(const System& system, const SystemChartOptions& o, double p1, double p2,
                           int fixed) {
  if (const std::string e = o.ValidationError(system); !e.empty()) throw InvalidArgument(e);
  if (fixed != 0 && fixed != 1) throw InvalidArgument("fixed must be 0 (p1) or 1 (p2)");
  const auto t0 = std::chrono::steady_clock::now();
  SystemCurve curve;
  curve.kind = CurveKind::kHopf;
  SteadyHopfProblem problem(system, o.plane.p1, o.plane.p2);
  const TraceResult r = TraceBothWays(problem, TraceFor(o, 0), Eigen::Vector2d(p1, p2), fixed);
  curve.ends = r.ends;
  curve.evaluations = r.evaluations;
  for (VectorXd u : r.u) {
    if (o.cancelled && o.cancelled()) {  // the points beyond are not sampled
      curve.ends.last = {CurveEndKind::kCancelled, ""};
      break;
    }
    Polish(problem, o.plane, &u);
    SystemCurvePoint p;
    SteadyState s;
    std::string why;
    if (!problem.Sample(u, &s, &p.test, &why)) continue;
    p.p1 = u[0], p.p2 = u[1];
    p.orbit.p = u[0];
    p.orbit.start.z = s.z;
    double test = 0, omega = 0;  // the pair nearest the imaginary axis: its frequency
    SteadyHopfProblem::Test(s, &test, &omega);
    p.orbit.period = 2 * M_PI / omega;
    curve.points.push_back(std::move(p));
  }
  curve.seconds = Seconds(t0);
  return curve;
}

}  // namespace stickslip
