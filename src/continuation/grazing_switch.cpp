// Branch switching at a grazing point (di Bernardo et al. 2008; seed case 1):
// the grazing orbit is both the stick-slip orbit with a stick phase of length
// zero and a pure-slip orbit of the smooth slip flow.
#include <algorithm>
#include <cmath>

#include "continuation/branch_tracers.hpp"
#include "continuation/special_points.hpp"

namespace stickslip {

namespace {

// The grazing row: the limit of the stick-slip orbits, whose stick phase
// shrinks to zero at the exit point (or, inside the stick band, to the stick
// from the touch to the exit point). One row, the same from either side.
BranchPoint GrazingRow(const BranchContext& ctx, const Model& m, const SpecialPoint& sp,
                       const FlowResult& run) {
  Orbit o;
  o.kind = OrbitKind::kStickSlip;
  o.period = sp.period;
  // x' from its minimum up to the belt, where the orbit grazes.
  o.extrema = Extrema{sp.extrema.x_min, sp.extrema.x_max, run.extrema.xdot_min, m.v()};
  o.t_stick = sp.period - run.t;
  o.multiplier = 0.0;
  o.stable = true;
  o.start = m.ExitPoint();
  return ctx.FromOrbit(sp.p, o, 0.0);
}

// From pure slip into stick slip: stick-slip orbits exist where the gap is positive.
BranchStart IntoStickSlip(BranchContext& ctx, const BranchEnd& end, const FlowResult& run) {
  const double p_gr = end.p;
  const double d = std::max(Tolerances::kStickProbe * ctx.LocalScale(p_gr),
                            Tolerances::kStickProbeTol * ctx.options().locate_tol);
  const double side = p_gr + d <= ctx.hi() ? 1.0 : -1.0;  // probe inside the range
  double gap_probe = 0;
  if (!ctx.GrazingGapAt(p_gr + side * d, &gap_probe)) {
    ctx.Fail("grazing point at " + ctx.Where(p_gr), "the grazing test function failed beside it");
    return {};
  }
  const double dir = gap_probe > 0 ? side : -side;
  if (dir != end.dir)
    ctx.AddSpecial(
        FoldPoint(p_gr, run, "non-smooth fold at GR: the stick-slip and pure-slip branches meet"));
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
  const double a_gr = run.extrema.x_max - Model(ctx.At(p_gr)).SteadySliding().x;
  const double scale = ctx.LocalScale(p_gr);
  const double d = std::max({Tolerances::kSlipProbe * scale,
                             Tolerances::kSlipProbeTol * ctx.options().locate_tol,
                             Tolerances::kSlipProbeRtol * ctx.options().orbit.flow.rtol * scale});
  for (double side : {end.dir, -end.dir}) {
    const double q = p_gr + side * d;
    if (q < ctx.lo() || q > ctx.hi()) continue;
    Orbit o;
    double a = 0;
    if (ctx.PureSlipAtFixedP(q, a_gr, &o, &a)) {
      if (side != end.dir)
        ctx.AddSpecial(FoldPoint(
            p_gr, run, "non-smooth fold at GR: the stick-slip and pure-slip branches meet"));
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

bool GrazingAhead(BranchContext& ctx, double p, double dp_sign, double step, double* p_gr) {
  double gap0 = 0;
  if (!ctx.GrazingGapAt(p, &gap0)) return false;
  double q = p;
  for (int k = 0; k < Tolerances::kSearchSteps; ++k) {
    double q2 = p + dp_sign * step * std::pow(Tolerances::kSearchGrow, k);
    q2 = std::min(ctx.hi(), std::max(ctx.lo(), q2));
    double gap2 = 0;
    const bool ok = ctx.GrazingGapAt(q2, &gap2);
    if (ok && gap0 * gap2 < 0) {
      const RootResult r = LocateGrazing(ctx.finder(), ctx.base(), ctx.axis(), p, q2, gap0, gap2,
                                         ctx.options().locate_tol);
      *p_gr = r.x;
      return r.ok;
    }
    if (q2 == q) break;  // at the range end
    q = q2;
  }
  return false;
}

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
    ctx.Fail("grazing orbit at " + ctx.Where(end.p), Name(s));
    return {};
  }
  const bool from_ss = end.came_from == PointKind::kStickSlip;
  const Model m(ctx.At(end.p));
  const SpecialPoint gr = GrazingPoint(m, end.p, run);
  ctx.AddSpecial(gr);
  ctx.Add(GrazingRow(ctx, m, gr, run));
  // Touching the belt inside the stick band, the orbit disappears: nothing
  // to switch to (coulomb law with damping: slip is a damped linear oscillator).
  if (ctx.Stop() || GrazesInsideStickBand(m, run)) return {};
  return from_ss ? IntoPureSlip(ctx, end, run) : IntoStickSlip(ctx, end, run);
}

}  // namespace stickslip
