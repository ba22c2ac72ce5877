// The steady-sliding and stick-slip branch tracers.
#include <algorithm>
#include <cmath>

#include "continuation/branch_tracers.hpp"
#include "continuation/special_points.hpp"
#include "numerics/tolerances.hpp"

namespace stickslip {

namespace {

BranchPoint EquilibriumPoint(const Equilibrium& e, double p) {
  BranchPoint pt;
  pt.p = p;
  pt.kind = PointKind::kEquilibrium;
  pt.period = kNan;
  pt.extrema = Extrema::Point(e.x, 0.0);
  pt.t_stick = kNan;
  pt.multiplier = e.max_real();
  pt.stable = e.stable();
  pt.amplitude = 0.0;
  pt.x_start = e.x;
  return pt;
}

// The largest relative change of the orbit's extent and period.
double Change(const Orbit& prev, const Orbit& next) {
  const double scale = std::max(0.1, prev.extrema.x_max - prev.extrema.x_min);
  return std::max({std::abs(next.extrema.x_max - prev.extrema.x_max) / scale,
                   std::abs(next.extrema.x_min - prev.extrema.x_min) / scale,
                   std::abs(next.extrema.xdot_min - prev.extrema.xdot_min) / scale,
                   std::abs(next.period - prev.period) / prev.period});
}

}  // namespace

// Steady sliding x = mu(v) is explicit; its Hopf points are the roots of
// HopfDamping, located by Brent's method.
std::vector<BranchPoint> TraceEquilibrium(BranchContext& ctx) {
  const ContinuationOptions& o = ctx.options();
  const int n = static_cast<int>(std::ceil(1.0 / o.max_step));
  std::vector<BranchPoint> rows;
  double p_prev = o.from, d_prev = HopfDamping(ctx.At(o.from));
  rows.reserve(n + 9);  // the grid and a few Hopf points: no reallocation
  // Polls the cancel hook per row: a fine grid (1 / max_step rows) takes long.
  for (int i = 0; i <= n && !ctx.Stop(); ++i) {
    const double p = i == n ? o.to : o.from + (o.to - o.from) * i / n;
    // One model per row: its steady sliding gives the row and HopfDamping's d.
    const Equilibrium e = Model(ctx.At(p)).SteadySliding();
    const double d = e.damping;
    if (i > 0 && d_prev * d < 0) {
      const RootResult r = LocateHopf(ctx.base(), ctx.axis(), p_prev, p, d_prev, d, o.locate_tol);
      if (r.ok) {
        rows.push_back(EquilibriumPoint(Model(ctx.At(r.x)).SteadySliding(), r.x));
        ctx.AddHopf(r.x);
        ctx.AddSpecial(HopfPoint(ctx.At(r.x), r.x));
      }
    }
    rows.push_back(EquilibriumPoint(e, p));
    p_prev = p;
    d_prev = d;
  }
  return rows;
}

BranchEnd TraceStickSlip(BranchContext& ctx, const BranchStart& start) {
  const ContinuationOptions& o = ctx.options();
  // Steps scale with the range, within LocalScale's bounds around p.
  auto h_max = [&](double p) { return o.max_step * ctx.LocalScale(p); };
  auto h_min = [&](double p) { return o.min_step * ctx.LocalScale(p); };
  const double end = start.dir > 0 ? ctx.hi() : ctx.lo();
  const BranchEnd stopped{BranchEnd::kStopped};
  double p = start.p, h = h_max(p);
  Orbit prev;
  OrbitResult res;
  if (start.has_orbit) {
    prev = start.orbit;
  } else if (!ctx.StickSlipAt(p, &prev, &res)) {
    ctx.Fail("stick-slip orbit at " + ctx.Where(p), res.message);
    return stopped;
  }
  if (!start.skip_first) ctx.Add(ctx.FromOrbit(p, prev, 0));
  int count = 1;
  while (true) {
    if (ctx.Stop()) return stopped;
    if (std::abs(end - p) <= Tolerances::kAtRangeEnd * std::max(1.0, std::abs(p)))
      return {BranchEnd::kRangeEnd};
    if (++count > o.max_points) {
      ctx.Fail("stick-slip branch at " + ctx.Where(p),
               "more than max_points = " + std::to_string(o.max_points) + " points");
      return stopped;
    }
    double q = p + start.dir * h;
    if ((q - end) * start.dir > 0) q = end;
    Orbit next;
    if (ctx.StickSlipAt(q, &next, &res)) {
      const double change = Change(prev, next);
      if (change > Tolerances::kHalveAbove * o.max_step && h > 4 * h_min(p)) {
        h *= 0.5;
        ++ctx.counts().rejected_steps;
        continue;
      }
      ctx.Add(ctx.FromOrbit(q, next, 0));
      p = q;
      prev = next;
      if (change < Tolerances::kGrowBelow * o.max_step)
        h = std::min(Tolerances::kGrow * h, h_max(p));
      continue;
    }
    if (res.status == OrbitStatus::kMissed) {
      // The slip phase no longer reaches the belt speed: GR lies in (p, q).
      double gap_in = 0;
      RootResult gr;
      if (ctx.GrazingGapAt(p, &gap_in))
        gr = LocateGrazing(ctx.finder(), ctx.base(), ctx.axis(), p, q, gap_in, res.gap,
                           o.locate_tol);
      if (!gr.ok) {
        ctx.Fail("locating the grazing point between " + ctx.Where(p) + " and " + Num(q),
                 "the grazing test function has no root there");
        return stopped;
      }
      return {BranchEnd::kGrazing, gr.x, start.dir, PointKind::kStickSlip};
    }
    if (h > 2 * h_min(p)) {
      h *= 0.5;
      ++ctx.counts().rejected_steps;
      continue;
    }
    ctx.Fail("stick-slip orbit at " + ctx.Where(q), res.message);
    return stopped;
  }
}

}  // namespace stickslip
