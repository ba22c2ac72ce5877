// Branch switching at a grazing point (di Bernardo et al. 2008; seed case 1):
// the grazing orbit is both the stick-slip orbit with a stick phase of length
// zero and a pure-slip orbit of the smooth slip flow.
#include <algorithm>
#include <cmath>

#include "branch_tracers.hpp"
#include "stickslip/special_points.hpp"

namespace stickslip {

namespace {

// The grazing row on the branch that reached it.
BranchPoint GrazingRow(const BranchContext& ctx, const BranchEnd& end, const FlowResult& run,
                       int branch) {
  const Model m(ctx.At(end.p));
  const bool from_ss = end.came_from == PointKind::kStickSlip;
  const double mult_ps = run.jacobian.determinant();
  BranchPoint gr;
  gr.p = end.p;
  gr.kind = end.came_from;
  gr.branch = branch;
  gr.period = run.t;
  gr.x_min = run.x_min;
  gr.x_max = run.x_max;
  gr.xdot_min = run.xdot_min;
  gr.xdot_max = m.v();
  gr.t_stick = 0.0;
  gr.multiplier = from_ss ? 0.0 : mult_ps;
  gr.stable = from_ss || std::abs(mult_ps) < 1.0;
  gr.amplitude = from_ss ? 0.5 * (run.x_max - run.x_min) : run.x_max - m.SteadySliding().x;
  return gr;
}

// From pure slip into stick slip: stick-slip orbits exist where the gap is positive.
BranchStart IntoStickSlip(BranchContext& ctx, const BranchEnd& end, const FlowResult& run) {
  const double p_gr = end.p;
  const double d = std::max(tuning::kStickProbe * ctx.range(),
                            tuning::kStickProbeTol * ctx.options().locate_tol);
  const double side = p_gr + d <= ctx.hi() ? 1.0 : -1.0;  // probe inside the range
  double gap_probe = 0;
  if (!ctx.GrazingGapAt(p_gr + side * d, &gap_probe)) {
    ctx.Fail("grazing point at " + ctx.Where(p_gr), "the grazing test function failed beside it");
    return {};
  }
  const double dir = gap_probe > 0 ? side : -side;
  if (dir != end.dir)
    ctx.AddSpecial(
        FoldPoint(p_gr, run, "non-smooth fold at GR: the pure-slip branch turns into stick-slip"));
  // Step off GR by one small step so the first orbit is a clear stick-slip orbit.
  BranchStart next;
  OrbitResult r;
  const double q = p_gr + dir * d;
  if ((dir > 0 && q > ctx.hi()) || (dir < 0 && q < ctx.lo()) ||
      !ctx.StickSlipAt(q, &next.orbit, &r))
    return {};
  next.phase = BranchStart::kStickSlip;
  next.p = q;
  next.dir = dir;
  next.has_orbit = true;
  return next;
}

// From stick slip into pure slip: the side where a pure-slip orbit exists.
BranchStart IntoPureSlip(BranchContext& ctx, const BranchEnd& end, const FlowResult& run) {
  const double p_gr = end.p;
  const double a_gr = run.x_max - Model(ctx.At(p_gr)).SteadySliding().x;
  const double d =
      std::max(tuning::kSlipProbe * ctx.range(), tuning::kSlipProbeTol * ctx.options().locate_tol);
  for (double side : {end.dir, -end.dir}) {
    const double q = p_gr + side * d;
    if (q < ctx.lo() || q > ctx.hi()) continue;
    Orbit o;
    double a = 0;
    if (ctx.PureSlipAtFixedP(q, a_gr, &o, &a)) {
      if (side != end.dir)
        ctx.AddSpecial(FoldPoint(
            p_gr, run, "non-smooth fold at GR: the stick-slip branch turns into pure slip"));
      BranchStart next;
      next.phase = BranchStart::kPureSlip;
      next.p = q;
      next.a = a;
      next.dir = side;
      return next;
    }
  }
  // The grazing orbit is a pure-slip orbit of the smooth slip flow, so a
  // pure-slip branch leaves it on one side unless that side is out of range.
  const double q_in = p_gr + end.dir * d;
  if (q_in >= ctx.lo() && q_in <= ctx.hi())
    ctx.Fail("grazing point at " + ctx.Where(p_gr),
             "no pure-slip orbit found on either side of it");
  return {};
}

}  // namespace

BranchStart SwitchAtGrazing(BranchContext& ctx, const BranchEnd& end) {
  // A grazing point already passed closes a loop of branches (a pure-slip
  // branch joining two grazing points): the branch ends here.
  if (ctx.GrazingVisited(end.p)) return {};
  OrbitFinder& finder = ctx.finder();
  finder.set_model(Model(ctx.At(end.p)));
  finder.set_floquet(true);
  double gap = 0;
  FlowResult run;
  const OrbitStatus s = finder.GrazingGap(&gap, &run);
  finder.set_floquet(false);
  if (s != OrbitStatus::kOk) {
    ctx.Fail("grazing orbit at " + ctx.Where(end.p), OrbitStatusName(s));
    return {};
  }
  const bool from_ss = end.came_from == PointKind::kStickSlip;
  ctx.AddSpecial(GrazingPoint(end.p, run, from_ss));
  ctx.Add(GrazingRow(ctx, end, run, ctx.branch()));
  if (ctx.Stop()) return {};
  return from_ss ? IntoPureSlip(ctx, end, run) : IntoStickSlip(ctx, end, run);
}

}  // namespace stickslip
