#include "continuation/branch_context.hpp"

#include <algorithm>
#include <cmath>

#include "continuation/special_points.hpp"
#include "numerics/tolerances.hpp"
#include "stickslip/systems/belt/friction.hpp"

namespace stickslip {

BranchContext::BranchContext(const Params& base, const ContinuationOptions& o)
    : base_(base),
      o_(o),
      axis_(o.param),
      finder_(Model(axis_.At(base, o.from)), o.orbit),
      range_(std::abs(o.to - o.from)),
      lo_(std::min(o.from, o.to)),
      hi_(std::max(o.from, o.to)),
      dir_(o.to > o.from ? 1.0 : -1.0),
      column_(o.orbit.flow.integrator == Integrator::kTaylor &&
              ParameterColumnSupported(base.law, o.param)),
      phase_start_(std::chrono::steady_clock::now()) {
  finder_.set_floquet(false);
  // Room for the equilibrium grid (1 / max_step rows) and as many periodic
  // rows, capped: a dense branch then never copies its points as they come.
  // (A capacity, not a threshold: 16 rows for Hopf and grazing points, at most
  // 2^16 rows reserved, 7 MB of untouched address space.)
  const double rows = 2.0 * (std::ceil(1.0 / o.max_step) + 16);
  res_.points.reserve(static_cast<size_t>(std::min(rows, 65536.0)));
  if (o_.cancelled) finder_.flow().set_cancel(o_.cancelled);
  res_.param = o.param;
}

bool BranchContext::Stop() {
  if (o_.cancelled && o_.cancelled()) {
    res_.status = ContinuationStatus::kCancelled;
    res_.message =
        res_.points.empty() ? "cancelled before the first point" : "cancelled at " + Where(last_p_);
    return true;
  }
  return res_.status != ContinuationStatus::kOk;
}

void BranchContext::Fail(const std::string& where, const std::string& what) {
  if (res_.status != ContinuationStatus::kOk || Stop()) return;
  res_.status = ContinuationStatus::kFailed;
  res_.message = where + ": " + what;
}

void BranchContext::Add(const BranchPoint& pt) {
  if (!std::isfinite(pt.p) || !std::isfinite(pt.extrema.x_min) ||
      !std::isfinite(pt.extrema.x_max)) {
    Fail(Where(pt.p), "non-finite values in a computed point");
    return;
  }
  res_.points.push_back(pt);
  last_p_ = pt.p;
  if (pt.kind == PointKind::kStickSlip) {
    if (stick_slip_spans_.empty() || stick_slip_spans_.back().branch != pt.branch)
      stick_slip_spans_.push_back({pt.branch, pt.p, pt.p});
    Span& s = stick_slip_spans_.back();
    s.lo = std::min(s.lo, pt.p);
    s.hi = std::max(s.hi, pt.p);
  }
  if (o_.progress) o_.progress(pt);
}

BranchPoint BranchContext::FromOrbit(double p, const Orbit& o, double a) const {
  BranchPoint pt;
  pt.p = p;
  pt.kind = o.kind == OrbitKind::kStickSlip ? PointKind::kStickSlip : PointKind::kPureSlip;
  pt.branch = branch_;
  pt.period = o.period;
  pt.extrema = o.extrema;
  pt.t_stick = o.t_stick;
  pt.multiplier = o.multiplier;
  pt.stable = o.stable;
  pt.amplitude = o.kind == OrbitKind::kPureSlip ? a : o.extrema.HalfSpanX();
  pt.newton_stalled = o.newton_stalled;
  // Pure slip: the section point (xbar + a, 0) of G(a, p) (orbit.hpp).
  const bool ps = o.kind == OrbitKind::kPureSlip;
  pt.x_start = ps ? Model(At(p)).SteadySliding().x + a : o.start[0];
  pt.xdot_start = ps ? 0.0 : o.start[1];
  return pt;
}

bool BranchContext::StickSlipAt(double p, Orbit* orbit, OrbitResult* res) {
  finder_.set_model(Model(At(p)));
  finder_.set_floquet(o_.stick_slip_floquet);
  *res = finder_.StickSlip(/*first_return_only=*/true);
  finder_.set_floquet(false);
  ++res_.counts.orbit_solves;
  if (res->ok()) *orbit = res->orbit;
  return res->ok();
}

bool BranchContext::GrazingGapAt(double p, double* gap) { return GrazingGap(finder_, At(p), gap); }

bool BranchContext::PureSlipAtFixedP(double p, double a_guess, Orbit* orbit, double* a) {
  const Model m(At(p));
  finder_.set_model(m);
  const OrbitResult r = finder_.PureSlip(a_guess);
  ++res_.counts.orbit_solves;
  res_.counts.newton_iterations += r.iterations;
  if (!r.ok() || r.orbit.extrema.xdot_max >= m.v()) return false;
  *orbit = r.orbit;
  *a = r.orbit.start[0] - m.SteadySliding().x;
  // Newton that ends on the equilibrium itself found no orbit.
  return *a > Tolerances().on_equilibrium * (m.params().mu_s + m.v());
}

namespace {
// d xbar / dp of steady sliding xbar = mu(v): mu'(v) for v, else exact as a
// difference for beta (0) and the parameters mu depends on affinely.
double SteadySlidingDp(const ParameterAxis& axis, const Params& q) {
  const Friction f(q);
  if (axis.name() == "v") return f.DMu(q.v);
  const double d = std::max(1.0, std::abs(axis.Get(q)));
  return (Friction(axis.At(q, axis.Get(q) + d)).Mu(q.v) - f.Mu(q.v)) / d;
}
}  // namespace

OrbitStatus BranchContext::EvalG(double a, double p, double* g, double* ga, ReturnMap* map,
                                 double* gp) {
  // A corrector may wander out of the model's domain (v <= 0, say): no orbit.
  const Params q = At(p);
  const std::string err = stickslip::ValidationError(q);
  if (!err.empty()) {
    if (map) map->message = "outside the model's domain: " + err;
    return OrbitStatus::kNotConverged;
  }
  finder_.set_model(Model(q));
  ++res_.counts.return_maps;
  if (!(gp && ga && column_)) return finder_.Desingularised(a, g, ga, map);
  // G = (P(xbar + a; p) - xbar - a) / a, so dG/dp = (P_p + (P' - 1) xbar_p) / a.
  ReturnMap local;
  ReturnMap& rm = map ? *map : local;
  finder_.flow().set_parameter_column(axis_);
  struct ColumnOff {  // also when Desingularised throws
    BeltFlow& flow;
    ~ColumnOff() { flow.clear_parameter_column(); }
  } off{finder_.flow()};
  const OrbitStatus s = finder_.Desingularised(a, g, ga, &rm);
  if (s == OrbitStatus::kOk && rm.has_dpdp)
    *gp = (rm.dpdp + (rm.dpdx - 1.0) * SteadySlidingDp(axis_, q)) / a;
  return s;
}

bool BranchContext::NearHopf(double p, double slack) const {
  const double d = std::max(Tolerances::kNearHopf * range_, slack);
  for (const auto& h : hopf_)
    if (std::abs(h.first - p) <= d) return true;
  return false;
}

void BranchContext::AddHopfEnd(double p_near, bool stable) {
  int best = -1;
  for (size_t i = 0; i < hopf_.size(); ++i)
    if (best < 0 || std::abs(hopf_[i].first - p_near) < std::abs(hopf_[best].first - p_near))
      best = i;
  if (best < 0) return;
  hopf_[best].second = true;
  const double p = hopf_[best].first;
  Orbit o;  // amplitude zero; lambda = +-i, so period 2 pi and multiplier 1
  o.kind = OrbitKind::kPureSlip;
  o.period = 2 * M_PI;
  o.extrema = Extrema::Point(Model(At(p)).SteadySliding().x, 0.0);
  o.t_stick = 0.0;
  o.multiplier = 1.0;
  o.stable = stable;
  Add(FromOrbit(p, o, 0.0));
}

bool BranchContext::GrazingVisited(double p) const {
  for (const SpecialPoint& sp : res_.special)
    if (sp.kind == SpecialKind::kGrazing &&
        std::abs(sp.p - p) <= Tolerances::kSameGrazing * o_.locate_tol)
      return true;
  return false;
}

bool BranchContext::CoveredByStickSlip(double p) const {
  const double tol = Tolerances().same_p * std::max(1.0, range_);
  for (const Span& s : stick_slip_spans_)
    if (p >= s.lo - tol && p <= s.hi + tol) return true;
  return false;
}

bool BranchContext::HasPureSlipPoint(double p, double a) const {
  for (const BranchPoint& pt : res_.points)
    if (pt.kind == PointKind::kPureSlip && pt.p == p &&
        std::abs(pt.amplitude - a) <= Tolerances().same_amplitude * std::max(1.0, a))
      return true;
  return false;
}

void BranchContext::Enter(Phase phase) {
  const auto now = std::chrono::steady_clock::now();
  const double dt = std::chrono::duration<double>(now - phase_start_).count();
  ContinuationTimes& t = res_.seconds;
  double* slot[] = {&t.equilibrium, &t.stick_slip, &t.pure_slip, &t.switching, &t.discovery};
  *slot[static_cast<int>(phase_)] += dt;
  t.total += dt;
  phase_ = phase;
  phase_start_ = now;
}

ContinuationResult BranchContext::Finish() {
  Enter(phase_);
  res_.counts.integrator_steps = finder_.flow().total_steps();
  return std::move(res_);  // no copy of a long result (a cancel returns at once)
}

}  // namespace stickslip
