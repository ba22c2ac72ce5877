#include "stickslip/continuation/continuation.hpp"

#include <algorithm>
#include <cmath>

#include "continuation/branch_tracers.hpp"
#include "numerics/numbers.hpp"
#include "numerics/tolerances.hpp"
#include "stickslip/errors.hpp"
#include "stickslip/orbits/orbit_scan.hpp"

namespace stickslip {

const char* SpecialLabel(SpecialKind k) { return Name(k); }

std::string ContinuationOptions::ValidationError(const Params& base) const {
  if (std::string err = AxisError(param, base.law); !err.empty()) return err;
  if (!std::isfinite(from)) return "from = " + Num(from) + " is not a finite number";
  if (!std::isfinite(to)) return "to = " + Num(to) + " is not a finite number";
  if (from == to) return "from = to = " + Num(from) + ": the range is empty";
  if (!(max_step > 0 && max_step <= kMaxStepLimit))
    return "max_step = " + Num(max_step) + " must be in (0, " + Num(kMaxStepLimit) + "]";
  if (!(min_step > 0)) return "min_step = " + Num(min_step) + " must be > 0";
  if (!(max_step > min_step))
    return "max_step = " + Num(max_step) + " must be > min_step = " + Num(min_step);
  if (!(locate_tol > 0 && locate_tol < Tolerances::kLocateTolMax))
    return "locate_tol = " + Num(locate_tol) + " must be in (0, " + Num(Tolerances::kLocateTolMax) +
           ")";
  if (max_points < 2) return "max_points = " + Num(max_points) + " must be >= 2";
  for (double p : {from, to}) {
    const std::string err = stickslip::ValidationError(param.At(base, p));
    if (!err.empty()) return "at " + param.name() + " = " + Num(p) + ": " + err;
  }
  return orbit.ValidationError();
}

namespace {

// The driver: traces a branch, switches at each grazing point it reaches,
// and carries on along the other kind of orbit until the branch ends.
void Trace(BranchContext& ctx, BranchStart s) {
  while (s.phase != BranchStart::kNone && !ctx.Stop()) {
    const bool ss = s.phase == BranchStart::kStickSlip;
    ctx.Enter(ss ? BranchContext::Phase::kStickSlip : BranchContext::Phase::kPureSlip);
    const BranchEnd end = ss ? TraceStickSlip(ctx, s) : TracePureSlip(ctx, s);
    if (end.kind != BranchEnd::kGrazing) break;
    ctx.Enter(BranchContext::Phase::kSwitching);
    s = SwitchAtGrazing(ctx, end);
  }
  ctx.NextBranch();
}

BranchStart StickSlipStart(double p, double dir, const Orbit& o, bool skip_first) {
  BranchStart s;
  s.phase = BranchStart::kStickSlip;
  s.p = p;
  s.dir = dir;
  s.has_orbit = true;
  s.orbit = o;
  s.skip_first = skip_first;
  return s;
}

// The periodic orbits at `from`: the stick-slip orbit if the slip phase
// returns to Omega, and every pure-slip orbit the scan of the section x' = 0
// finds (inside a bistable band the unstable one lies between steady sliding
// and stick-slip). Each starts a branch unless one has reached it already.
void TraceFromStart(BranchContext& ctx) {
  const double from = ctx.options().from;
  ctx.Enter(BranchContext::Phase::kDiscovery);
  // Where the energy bound excludes every orbit there is nothing to find
  // (and the slip integration would be stiff: --from 100).
  if (Model(ctx.At(from)).NoPeriodicOrbit()) return;
  Orbit o;
  OrbitResult r;
  if (ctx.StickSlipAt(from, &o, &r)) Trace(ctx, StickSlipStart(from, ctx.dir(), o, false));
  if (ctx.Stop()) return;
  ctx.Enter(BranchContext::Phase::kDiscovery);
  OrbitScanOptions so;
  so.orbit = ctx.options().orbit;
  so.cancelled = ctx.options().cancelled;
  const PeriodicOrbits found = FindPeriodicOrbits(Model(ctx.At(from)), so);
  ctx.counts().return_maps += found.returns;
  if (found.status == OrbitScanStatus::kFailed) ctx.Fail(ctx.Where(from), found.message);
  for (const Orbit& ps : found.pure_slip) {
    const double a = ps.start[0] - found.steady.x;
    if (ctx.Stop() || ps.extrema.xdot_max >= ctx.At(from).v) continue;
    if (ctx.HasPureSlipPoint(from, a)) continue;
    BranchStart s;
    s.phase = BranchStart::kPureSlip;
    s.p = from;
    s.a = a;
    s.dir = ctx.dir();
    Trace(ctx, s);
    ctx.Enter(BranchContext::Phase::kDiscovery);
  }
}

ContinuationResult Run(BranchContext& ctx) {
  // Hopf points first: pure-slip branches end on them.
  ctx.Enter(BranchContext::Phase::kEquilibrium);
  std::vector<BranchPoint> eq_rows = TraceEquilibrium(ctx);
  const int eq_id = 0;
  ctx.SetBranch(1);
  TraceFromStart(ctx);
  // Steady sliding follows (or comes first, if nothing starts at `from`). It is
  // exact and already computed: kept even in a partial result, with its Hopf
  // points.
  ctx.Reserve(eq_rows.size());
  for (auto& pt : eq_rows) {
    pt.branch = eq_id;
    ctx.Add(pt);
  }
  // Hopf points that no branch has reached yet start their own.
  for (size_t i = 0; i < ctx.hopf().size() && !ctx.Stop(); ++i) {
    if (ctx.hopf()[i].second) continue;
    BranchStart s;
    s.phase = BranchStart::kPureSlip;
    s.p = ctx.hopf()[i].first;
    s.from_hopf = true;
    Trace(ctx, s);
  }
  // Stick-slip orbits exist wherever the slip phase from (x0, v) returns to
  // Omega. One first-return integration per grid point finds any that the
  // branches so far did not reach; each is followed both ways. None is looked
  // for where the energy bound excludes every orbit (Model::NoPeriodicOrbit):
  // there the slip field is stiff (cubic law: mu' ~ 3 k3 v^2) and the search
  // would run to max_return_time.
  for (const BranchPoint& g : eq_rows) {
    if (ctx.Stop()) break;
    ctx.Enter(BranchContext::Phase::kDiscovery);
    if (ctx.CoveredByStickSlip(g.p) || Model(ctx.At(g.p)).NoPeriodicOrbit()) continue;
    Orbit o;
    OrbitResult r;
    if (!ctx.StickSlipAt(g.p, &o, &r)) continue;
    // The point at g.p is on the first of the two.
    for (double d : {-ctx.dir(), ctx.dir()}) Trace(ctx, StickSlipStart(g.p, d, o, d == ctx.dir()));
  }
  ctx.Stop();
  ContinuationResult res = ctx.Finish();
  const double dir = ctx.dir();
  std::stable_sort(
      res.special.begin(), res.special.end(),
      [&](const SpecialPoint& x, const SpecialPoint& y) { return (x.p - y.p) * dir < 0; });
  return res;
}

}  // namespace

ContinuationResult Continue(const Params& base, const ContinuationOptions& options) {
  const std::string err = options.ValidationError(base);
  if (!err.empty()) throw InvalidArgument(err);
  BranchContext ctx(base, options);
  ContinuationResult r = Run(ctx);
  const double rtol = options.orbit.flow.rtol;
  if (rtol > kLoosestTrustedRtol)
    r.warnings.push_back("rtol = " + Num(rtol) + " is looser than " + Num(kLoosestTrustedRtol) +
                         ", the loosest tolerance the branch's structure is promised at: "
                         "special points may be far off");
  return r;
}

}  // namespace stickslip
