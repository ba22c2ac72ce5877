#include "stickslip/continuation.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <sstream>

#include "stickslip/errors.hpp"
#include "stickslip/numbers.hpp"
#include "stickslip/roots.hpp"

namespace stickslip {

const char* PointKindName(PointKind k) {
  switch (k) {
    case PointKind::kStickSlip:
      return "stick-slip";
    case PointKind::kPureSlip:
      return "pure-slip";
    case PointKind::kEquilibrium:
      return "equilibrium";
  }
  return "?";
}

const char* SpecialLabel(SpecialKind k) {
  switch (k) {
    case SpecialKind::kGrazing:
      return "GR";
    case SpecialKind::kHopf:
      return "HB";
    case SpecialKind::kFold:
      return "LP";
  }
  return "?";
}

const char* ContinuationStatusName(ContinuationStatus s) {
  switch (s) {
    case ContinuationStatus::kOk:
      return "ok";
    case ContinuationStatus::kFailed:
      return "failed";
    case ContinuationStatus::kCancelled:
      return "cancelled";
  }
  return "?";
}

std::string ContinuationOptions::ValidationError(const Params& base) const {
  if (!IsParameterName(param))
    return "unknown parameter '" + param +
           "' (expected one of beta, v, mu_s, mu_m, v_m, mu_k, "
           "v_s, delta)";
  const auto names = ParameterNames(base.law);
  if (std::find(names.begin(), names.end(), param) == names.end())
    return "parameter '" + param + "' does not apply to the " + LawName(base.law) + " law";
  if (!std::isfinite(from)) return "from = " + Num(from) + " is not a finite number";
  if (!std::isfinite(to)) return "to = " + Num(to) + " is not a finite number";
  if (from == to) return "from = to = " + Num(from) + ": the range is empty";
  if (!(max_step > 0 && max_step <= 0.5))
    return "max_step = " + Num(max_step) + " must be in (0, 0.5]";
  if (!(min_step > 0)) return "min_step = " + Num(min_step) + " must be > 0";
  if (!(max_step > min_step))
    return "max_step = " + Num(max_step) + " must be > min_step = " + Num(min_step);
  if (!(locate_tol > 0 && locate_tol < 1e-3))
    return "locate_tol = " + Num(locate_tol) + " must be in (0, 1e-3)";
  if (max_points < 2) return "max_points = " + Num(max_points) + " must be >= 2";
  for (double p : {from, to}) {
    Params q = base;
    SetParameter(q, param, p);
    const std::string err = stickslip::ValidationError(q);
    if (!err.empty()) return "at " + param + " = " + Num(p) + ": " + err;
  }
  return orbit.ValidationError();
}

namespace {

// Where a traced periodic branch is, and where it goes next.
struct Cursor {
  enum Phase { kStickSlip, kPureSlip, kDone } phase = kDone;
  double p = 0;
  double a = 0;    // pure slip: section amplitude
  double dir = 1;  // direction of travel in p (stick slip), or sign of the first dp (pure slip)
  bool from_hopf = false;
  bool skip_first = false;     // stick slip: the start point is already on a branch
  std::optional<Orbit> start;  // stick slip: the orbit at p, if the caller has it
};

class Tracer {
 public:
  Tracer(const Params& base, const ContinuationOptions& o)
      : base_(base),
        o_(o),
        finder_(Model(At(o.from)), o.orbit),
        range_(std::abs(o.to - o.from)),
        lo_(std::min(o.from, o.to)),
        hi_(std::max(o.from, o.to)),
        dir_(o.to > o.from ? 1.0 : -1.0) {
    finder_.set_floquet(false);
    if (o_.cancelled) finder_.flow().set_cancel(o_.cancelled);
  }

  ContinuationResult Run();

 private:
  Params At(double p) const {
    Params q = base_;
    SetParameter(q, o_.param, p);
    return q;
  }
  void SetP(double p) { finder_.set_model(Model(At(p))); }
  bool Stop() {
    if (o_.cancelled && o_.cancelled()) {
      res_.status = ContinuationStatus::kCancelled;
      res_.message = res_.points.empty() ? "cancelled before the first point"
                                         : "cancelled at " + o_.param + " = " + Num(last_p_);
      return true;
    }
    return res_.status != ContinuationStatus::kOk;
  }
  void Fail(const std::string& where, const std::string& what) {
    if (res_.status != ContinuationStatus::kOk || Stop()) return;
    res_.status = ContinuationStatus::kFailed;
    res_.message = where + ": " + what;
  }
  void Add(const BranchPoint& pt) {
    if (!std::isfinite(pt.p) || !std::isfinite(pt.x_min) || !std::isfinite(pt.x_max)) {
      Fail(o_.param + " = " + Num(pt.p), "non-finite values in a computed point");
      return;
    }
    res_.points.push_back(pt);
    last_p_ = pt.p;
    if (o_.progress) o_.progress(pt);
  }

  double Damping(double p) const { return Model(At(p)).SteadySliding().damping; }
  BranchPoint EquilibriumPoint(double p) const;
  std::vector<BranchPoint> TraceEquilibrium();

  BranchPoint FromOrbit(double p, const Orbit& o, double a) const;
  bool StickSlipAt(double p, Orbit* orbit, OrbitResult* res);
  void TraceStickSlip(Cursor& c);
  void TracePureSlip(Cursor& c);
  bool PureSlipAtFixedP(double p, double a_guess, Orbit* orbit, double* a);
  // G and its partial derivatives at (a, p).
  OrbitStatus EvalG(double a, double p, double* g, double* ga, ReturnMap* map);
  // dG/dp by a one-sided difference (forward, else backward); g = G(a, p).
  bool DGDp(double a, double p, double g, double h, double* gp);
  double GrazingGapAt(double p, bool* ok);
  bool LocateGrazing(double p_in, double p_out, double gap_in, double gap_out, double* p_gr);
  void SwitchAtGrazing(Cursor& c, double p_gr, double came_dir, PointKind came_from);
  void LocateFold(double a0, double p0, double a1, double p1, bool minimum);
  void FoldAt(double p, const FlowResult& run, const std::string& what);
  void AddHopfEnd(double p_near, bool stable);
  // A located Hopf point lies within 5 % of the range of p.
  bool NearHopf(double p) const {
    for (double h : hopf_)
      if (std::abs(h - p) <= 0.05 * range_) return true;
    return false;
  }
  bool GrazingFromPureSlip(Cursor& c, double p, double dp_sign, double step);
  void Trace(Cursor c);
  // p lies between stick-slip points of one branch already traced.
  bool CoveredByStickSlip(double p) const;

  Params base_;
  ContinuationOptions o_;
  OrbitFinder finder_;
  double range_, lo_, hi_, dir_;
  ContinuationResult res_;
  std::vector<double> hopf_;        // located Hopf points
  std::vector<bool> hopf_reached_;  // ended on by a traced branch
  int branch_ = 0;
  double last_p_ = 0;
};

BranchPoint Tracer::EquilibriumPoint(double p) const {
  const Equilibrium e = Model(At(p)).SteadySliding();
  BranchPoint pt;
  pt.p = p;
  pt.kind = PointKind::kEquilibrium;
  pt.period = kNan;
  pt.x_min = pt.x_max = e.x;
  pt.xdot_min = pt.xdot_max = 0.0;
  pt.t_stick = kNan;
  pt.multiplier = e.max_real();
  pt.stable = e.stable();
  pt.amplitude = 0.0;
  return pt;
}

// Steady sliding x = mu(v) is explicit; its Hopf points are the roots of
// 2 beta + mu'(v) (linearised seed eq. 3.5), located by Brent's method.
std::vector<BranchPoint> Tracer::TraceEquilibrium() {
  const int n = static_cast<int>(std::ceil(1.0 / o_.max_step));
  std::vector<BranchPoint> rows;
  double p_prev = o_.from, d_prev = Damping(o_.from);
  for (int i = 0; i <= n; ++i) {
    const double p = i == n ? o_.to : o_.from + (o_.to - o_.from) * i / n;
    const double d = Damping(p);
    if (i > 0 && d_prev * d < 0) {
      const RootResult r =
          FindRoot([&](double q) { return Damping(q); }, p_prev, p, d_prev, d, o_.locate_tol);
      if (r.ok) {
        rows.push_back(EquilibriumPoint(r.x));
        hopf_.push_back(r.x);
        hopf_reached_.push_back(false);
        const Model m(At(r.x));
        SpecialPoint sp;
        sp.kind = SpecialKind::kHopf;
        sp.p = r.x;
        sp.period = 2 * M_PI;  // lambda = +-i at the Hopf point
        sp.x_min = sp.x_max = m.SteadySliding().x;
        sp.xdot_min = 0;
        sp.multiplier_before = sp.multiplier_after = 1.0;
        const bool super = m.friction().D3Mu(m.v()) > 0;
        sp.description = std::string("Hopf point of steady sliding (2 beta + mu'(v) = 0), ") +
                         (super ? "supercritical (mu''' > 0)" : "subcritical (mu''' < 0)");
        res_.special.push_back(sp);
      }
    }
    rows.push_back(EquilibriumPoint(p));
    p_prev = p;
    d_prev = d;
  }
  return rows;
}

BranchPoint Tracer::FromOrbit(double p, const Orbit& o, double a) const {
  BranchPoint pt;
  pt.p = p;
  pt.kind = o.kind == OrbitKind::kStickSlip ? PointKind::kStickSlip : PointKind::kPureSlip;
  pt.branch = branch_;
  pt.period = o.period;
  pt.x_min = o.x_min;
  pt.x_max = o.x_max;
  pt.xdot_min = o.xdot_min;
  pt.xdot_max = o.xdot_max;
  pt.t_stick = o.t_stick;
  pt.multiplier = o.multiplier;
  pt.stable = o.stable;
  pt.amplitude = o.kind == OrbitKind::kPureSlip ? a : 0.5 * (o.x_max - o.x_min);
  return pt;
}

bool Tracer::StickSlipAt(double p, Orbit* orbit, OrbitResult* res) {
  SetP(p);
  finder_.set_floquet(o_.stick_slip_floquet);
  *res = finder_.StickSlip(/*first_return_only=*/true);
  finder_.set_floquet(false);
  if (res->ok()) *orbit = res->orbit;
  return res->ok();
}

double Tracer::GrazingGapAt(double p, bool* ok) {
  SetP(p);
  double gap = kNan;
  *ok = finder_.GrazingGap(&gap) == OrbitStatus::kOk;
  return gap;
}

bool Tracer::LocateGrazing(double p_in, double p_out, double gap_in, double gap_out, double* p_gr) {
  bool ok = true;
  auto f = [&](double p) {
    bool fine = false;
    const double g = GrazingGapAt(p, &fine);
    ok = ok && fine;
    return fine ? g : kNan;
  };
  const RootResult r = FindRoot(f, p_in, p_out, gap_in, gap_out, o_.locate_tol);
  *p_gr = r.x;
  return r.ok && ok;
}

// Stick-slip orbits are unique for given parameters, so this part of a branch
// is a graph over p: natural steps with an adaptive size.
void Tracer::TraceStickSlip(Cursor& c) {
  const double h_max = o_.max_step * range_, h_min = o_.min_step * range_;
  const double end = c.dir > 0 ? hi_ : lo_;
  double h = h_max, p = c.p;
  Orbit prev;
  OrbitResult res;
  if (c.start) {
    prev = *c.start;
  } else if (!StickSlipAt(p, &prev, &res)) {
    Fail("stick-slip orbit at " + o_.param + " = " + Num(p), res.message);
    return;
  }
  if (!c.skip_first) Add(FromOrbit(p, prev, 0));
  int count = 1;
  while (!Stop() && std::abs(end - p) > 1e-15 * std::max(1.0, std::abs(p))) {
    if (++count > o_.max_points) {
      Fail("stick-slip branch at " + o_.param + " = " + Num(p),
           "more than max_points = " + std::to_string(o_.max_points) + " points");
      return;
    }
    double q = p + c.dir * h;
    if ((q - end) * c.dir > 0) q = end;
    Orbit next;
    if (StickSlipAt(q, &next, &res)) {
      const double scale = std::max(0.1, prev.x_max - prev.x_min);
      const double change = std::max({std::abs(next.x_max - prev.x_max) / scale,
                                      std::abs(next.x_min - prev.x_min) / scale,
                                      std::abs(next.xdot_min - prev.xdot_min) / scale,
                                      std::abs(next.period - prev.period) / prev.period});
      if (change > 5 * o_.max_step && h > 4 * h_min) {
        h *= 0.5;
        continue;
      }
      Add(FromOrbit(q, next, 0));
      p = q;
      prev = next;
      if (change < 2 * o_.max_step) h = std::min(1.5 * h, h_max);
      continue;
    }
    if (res.status == OrbitStatus::kMissed) {
      // The slip phase no longer reaches the belt speed: GR lies in (p, q).
      bool ok = false;
      const double gap_in = GrazingGapAt(p, &ok);
      double p_gr = 0;
      if (!ok || !LocateGrazing(p, q, gap_in, res.gap, &p_gr)) {
        Fail("locating the grazing point between " + o_.param + " = " + Num(p) + " and " + Num(q),
             "the grazing test function has no root there");
        return;
      }
      SwitchAtGrazing(c, p_gr, c.dir, PointKind::kStickSlip);
      return;
    }
    if (h > 2 * h_min) {
      h *= 0.5;
      continue;
    }
    Fail("stick-slip orbit at " + o_.param + " = " + Num(q), res.message);
    return;
  }
  c.phase = Cursor::kDone;
}

OrbitStatus Tracer::EvalG(double a, double p, double* g, double* ga, ReturnMap* map) {
  // A corrector may wander out of the model's domain (v <= 0, say): no orbit.
  const std::string err = stickslip::ValidationError(At(p));
  if (!err.empty()) {
    if (map) map->message = "outside the model's domain: " + err;
    return OrbitStatus::kNotConverged;
  }
  SetP(p);
  return finder_.Desingularised(a, g, ga, map);
}

// The pure-slip orbit a converged return map describes.
Orbit PureSlipFromMap(const ReturnMap& map) {
  Orbit o;
  o.kind = OrbitKind::kPureSlip;
  o.period = map.period;
  o.x_min = map.flow.x_min;
  o.x_max = map.flow.x_max;
  o.xdot_min = map.flow.xdot_min;
  o.xdot_max = map.flow.xdot_max;
  o.multiplier = map.dpdx;
  o.stable = std::abs(map.dpdx) < 1;
  return o;
}

bool Tracer::DGDp(double a, double p, double g, double h, double* gp) {
  for (double step : {h, -h}) {
    double g2 = 0;
    if (EvalG(a, p + step, &g2, nullptr, nullptr) == OrbitStatus::kOk) {
      *gp = (g2 - g) / step;
      return true;
    }
  }
  return false;
}

bool Tracer::PureSlipAtFixedP(double p, double a_guess, Orbit* orbit, double* a) {
  const Model m(At(p));
  finder_.set_model(m);
  const OrbitResult r = finder_.PureSlip(a_guess);
  if (!r.ok() || r.orbit.xdot_max >= m.v()) return false;
  *orbit = r.orbit;
  *a = r.orbit.start[0] - m.SteadySliding().x;
  return true;
}

// At GR the stick phase has length zero and the orbit is the grazing orbit
// through (x0, v). Record GR, then carry on along the other kind of orbit.
void Tracer::SwitchAtGrazing(Cursor& c, double p_gr, double came_dir, PointKind came_from) {
  // A grazing point already passed closes a loop of branches (a pure-slip
  // branch joining two grazing points): the branch ends here.
  for (const SpecialPoint& sp : res_.special) {
    if (sp.kind == SpecialKind::kGrazing && std::abs(sp.p - p_gr) <= 1e3 * o_.locate_tol) {
      c.phase = Cursor::kDone;
      return;
    }
  }
  SetP(p_gr);
  finder_.set_floquet(true);
  double gap = 0;
  FlowResult run;
  const OrbitStatus s = finder_.GrazingGap(&gap, &run);
  finder_.set_floquet(false);
  if (s != OrbitStatus::kOk) {
    Fail("grazing orbit at " + o_.param + " = " + Num(p_gr), OrbitStatusName(s));
    return;
  }
  const Model m(At(p_gr));
  const double xbar = m.SteadySliding().x;
  // The pure-slip side's multiplier: the slip flow's Jacobian over the orbit
  // has the eigenvalues 1 and det (Liouville).
  const double mult_ps = run.jacobian.determinant();
  SpecialPoint sp;
  sp.kind = SpecialKind::kGrazing;
  sp.p = p_gr;
  sp.period = run.t;
  sp.x_min = run.x_min;
  sp.x_max = run.x_max;
  sp.xdot_min = run.xdot_min;
  sp.multiplier_before = came_from == PointKind::kStickSlip ? 0.0 : mult_ps;
  sp.multiplier_after = came_from == PointKind::kStickSlip ? mult_ps : 0.0;
  sp.description = "grazing-sliding: stick phase vanishes; multiplier jumps " +
                   Num(sp.multiplier_before) + " -> " + Num(sp.multiplier_after);
  res_.special.push_back(sp);

  BranchPoint gr;
  gr.p = p_gr;
  gr.kind = came_from;
  gr.branch = branch_;
  gr.period = run.t;
  gr.x_min = run.x_min;
  gr.x_max = run.x_max;
  gr.xdot_min = run.xdot_min;
  gr.xdot_max = m.v();
  gr.t_stick = 0.0;
  gr.multiplier = came_from == PointKind::kStickSlip ? 0.0 : mult_ps;
  gr.stable = came_from == PointKind::kStickSlip || std::abs(mult_ps) < 1.0;
  gr.amplitude =
      came_from == PointKind::kStickSlip ? 0.5 * (run.x_max - run.x_min) : run.x_max - xbar;
  Add(gr);
  if (Stop()) return;

  if (came_from == PointKind::kPureSlip) {
    // Stick-slip orbits exist where the gap is positive.
    const double d = std::max(1e-6 * range_, 10 * o_.locate_tol);
    const double side = p_gr + d <= hi_ ? 1.0 : -1.0;  // probe inside the range
    bool ok = false;
    const double gap_probe = GrazingGapAt(p_gr + side * d, &ok);
    if (!ok) {
      Fail("grazing point at " + o_.param + " = " + Num(p_gr),
           "the grazing test function failed beside it");
      return;
    }
    const double dir = gap_probe > 0 ? side : -side;
    if (dir != came_dir)
      FoldAt(p_gr, run, "non-smooth fold at GR: the pure-slip branch turns into stick-slip");
    c.phase = Cursor::kStickSlip;
    c.dir = dir;
    c.p = p_gr;
    // Step off GR by one small step so the first orbit is a clear stick-slip orbit.
    Orbit o;
    OrbitResult r;
    const double q = p_gr + dir * d;
    if ((dir > 0 && q > hi_) || (dir < 0 && q < lo_) || !StickSlipAt(q, &o, &r)) {
      c.phase = Cursor::kDone;
      return;
    }
    c.p = q;
    c.start = o;
    return;
  }
  // From stick-slip into pure slip: find the side where a pure-slip orbit exists.
  const double a_gr = run.x_max - xbar;
  for (double side : {came_dir, -came_dir}) {
    const double d = std::max(1e-4 * range_, 100 * o_.locate_tol);
    const double q = p_gr + side * d;
    if (q < lo_ || q > hi_) continue;
    Orbit o;
    double a = 0;
    if (PureSlipAtFixedP(q, a_gr, &o, &a)) {
      if (side != came_dir)
        FoldAt(p_gr, run, "non-smooth fold at GR: the stick-slip branch turns into pure slip");
      c.phase = Cursor::kPureSlip;
      c.p = q;
      c.a = a;
      c.dir = side;
      c.from_hopf = false;
      return;
    }
  }
  c.phase = Cursor::kDone;
  // The grazing orbit is a pure-slip orbit of the smooth slip flow, so a
  // pure-slip branch leaves it on one side unless that side is out of range.
  const double q_in = p_gr + came_dir * std::max(1e-4 * range_, 100 * o_.locate_tol);
  if (q_in >= lo_ && q_in <= hi_)
    Fail("grazing point at " + o_.param + " = " + Num(p_gr),
         "no pure-slip orbit found on either side of it");
}

void Tracer::FoldAt(double p, const FlowResult& run, const std::string& what) {
  SpecialPoint lp;
  lp.kind = SpecialKind::kFold;
  lp.p = p;
  lp.period = run.t;
  lp.x_min = run.x_min;
  lp.x_max = run.x_max;
  lp.xdot_min = run.xdot_min;
  lp.description = what;
  res_.special.push_back(lp);
}

// The pure-slip branch shrinks onto the Hopf point: end it there with
// amplitude zero and period 2 pi (lambda = +-i).
void Tracer::AddHopfEnd(double p_near, bool stable) {
  int best = -1;
  for (size_t i = 0; i < hopf_.size(); ++i)
    if (best < 0 || std::abs(hopf_[i] - p_near) < std::abs(hopf_[best] - p_near)) best = i;
  if (best < 0) return;
  hopf_reached_[best] = true;
  const double p = hopf_[best];
  BranchPoint pt;
  pt.p = p;
  pt.kind = PointKind::kPureSlip;
  pt.branch = branch_;
  pt.period = 2 * M_PI;
  pt.x_min = pt.x_max = Model(At(p)).SteadySliding().x;
  pt.xdot_min = pt.xdot_max = 0.0;
  pt.t_stick = 0.0;
  pt.multiplier = 1.0;
  pt.stable = stable;
  pt.amplitude = 0.0;
  Add(pt);
}

// p(a) on the pure-slip branch near a fold in p; its extremum is the LP.
void Tracer::LocateFold(double a0, double p0, double a1, double p1, bool minimum) {
  bool ok = true;
  auto p_of_a = [&](double a) {
    const double t = (a - a0) / (a1 - a0);
    double q0 = p0 + t * (p1 - p0), q1 = q0 + 1e-6 * range_;
    double g0 = 0, g1 = 0;
    if (EvalG(a, q0, &g0, nullptr, nullptr) != OrbitStatus::kOk ||
        EvalG(a, q1, &g1, nullptr, nullptr) != OrbitStatus::kOk) {
      ok = false;
      return q0;
    }
    for (int it = 0; it < 30 && std::abs(q1 - q0) > 1e-14 * range_; ++it) {  // secant
      if (g1 == g0) break;
      const double q2 = q1 - g1 * (q1 - q0) / (g1 - g0);
      q0 = q1;
      g0 = g1;
      q1 = q2;
      if (EvalG(a, q1, &g1, nullptr, nullptr) != OrbitStatus::kOk) {
        ok = false;
        break;
      }
    }
    return minimum ? q1 : -q1;
  };
  const RootResult r =
      FindMinimum(p_of_a, std::min(a0, a1), std::max(a0, a1), 1e-7 * std::max(1.0, std::abs(a1)));
  if (!ok || !r.ok) return;  // the fold stays bracketed only; not reported as located
  const double p = minimum ? r.fx : -r.fx;
  ReturnMap map;
  double g = 0;
  if (EvalG(r.x, p, &g, nullptr, &map) != OrbitStatus::kOk) return;
  FoldAt(p, map.flow, "fold of the pure-slip branch (smooth LP)");
}

// A pure-slip step sticks: the branch is at a grazing point ahead in p.
bool Tracer::GrazingFromPureSlip(Cursor& c, double p, double dp_sign, double step) {
  bool ok = false;
  const double gap0 = GrazingGapAt(p, &ok);
  if (!ok) return false;
  // Search only near the branch: the grazing point is within a few steps.
  double q = p;
  for (int k = 0; k < 12; ++k) {
    double q2 = p + dp_sign * step * std::pow(1.5, k);
    q2 = std::min(hi_, std::max(lo_, q2));
    const double gap2 = GrazingGapAt(q2, &ok);
    if (ok && gap0 * gap2 < 0) {
      double p_gr = 0;
      if (!LocateGrazing(p, q2, gap0, gap2, &p_gr)) return false;
      SwitchAtGrazing(c, p_gr, dp_sign, PointKind::kPureSlip);
      return true;
    }
    if (q2 == q) break;  // at the range end
    q = q2;
  }
  return false;
}

// Pseudo-arclength continuation of G(a, p) = 0 (Keller 1977) in scaled
// coordinates (a, p / |to - from|); the corrector is Newton on G and the
// arclength condition, with dG/dp by a forward difference once per step.
void Tracer::TracePureSlip(Cursor& c) {
  const double R = range_;
  const double ds_max = 2 * o_.max_step, ds_min = o_.min_step;
  const double a_end = 0.02;  // closer to the Hopf point, shooting loses accuracy
  double a = c.a, p = c.p, ta = 0, tp = 0, ds = ds_max;
  ReturnMap map;
  double g = 0, ga = 0, gp = 0;
  // Forward-difference step for dG/dp, balanced against the integration error.
  const double hp = std::max(1e-7, std::sqrt(o_.orbit.flow.rtol)) * std::max(R, std::abs(p));
  bool last_stable = true;
  double last_xdot_max = 0, last_v = 0;
  if (c.from_hopf) {
    ta = 1;
    tp = 0;
    ds = std::max(a_end * 1.5, ds_max);
    // Stability at the start is that of the first orbit; added after it is found.
  } else {
    if (EvalG(a, p, &g, &ga, &map) != OrbitStatus::kOk) {
      Fail("pure-slip orbit at " + o_.param + " = " + Num(p), map.message);
      return;
    }
    if (!DGDp(a, p, g, hp, &gp)) {
      Fail("pure-slip orbit at " + o_.param + " = " + Num(p), "dG/dp failed on both sides");
      return;
    }
    ta = -gp * R;
    tp = ga;
    const double n = std::hypot(ta, tp);
    ta /= n;
    tp /= n;
    if (tp * c.dir < 0) {
      ta = -ta;
      tp = -tp;
    }
    const Orbit o = PureSlipFromMap(map);
    last_stable = o.stable;
    last_xdot_max = o.xdot_max;
    last_v = Model(At(p)).v();
    Add(FromOrbit(p, o, a));
  }
  bool hopf_start_pending = c.from_hopf;
  const double p_hopf_start = p;
  // The branch's last point on a range end; false if no orbit converges there.
  auto land = [&](double end, double a_guess) {
    Orbit o;
    double a_end_pt = 0;
    if (!PureSlipAtFixedP(end, std::max(a_guess, 1e-3), &o, &a_end_pt)) return false;
    if (hopf_start_pending) AddHopfEnd(p_hopf_start, o.stable);
    Add(FromOrbit(end, o, a_end_pt));
    c.phase = Cursor::kDone;
    return true;
  };
  // A smaller step towards the end; false (and the branch failed) below min_step.
  auto shrink = [&](double end) {
    ds *= 0.5;
    if (ds >= ds_min) return true;
    Fail("pure-slip orbit at " + o_.param + " = " + Num(end), "no convergence at the range end");
    return false;
  };
  int count = 0;
  while (!Stop()) {
    if (++count > o_.max_points) {
      Fail("pure-slip branch at " + o_.param + " = " + Num(p),
           "more than max_points = " + std::to_string(o_.max_points) + " points");
      return;
    }
    double a_pred = a + ds * ta, p_pred = p + ds * tp * R;
    // The range ends inside this step: land on it exactly.
    if (p_pred > hi_ || p_pred < lo_) {
      const double end = p_pred > hi_ ? hi_ : lo_;
      if (std::abs(end - p) <= 1e-13 * R) {
        c.phase = Cursor::kDone;
        return;
      }
      if (land(end, a + (end - p) / (tp * R) * ta) || !shrink(end)) return;
      continue;
    }
    if (!hopf_start_pending && ta < 0 && a_pred < a_end) {
      if (!NearHopf(p)) {
        Fail("pure-slip branch at " + o_.param + " = " + Num(p),
             "the amplitude shrinks to zero away from any Hopf point");
        return;
      }
      AddHopfEnd(p, last_stable);
      c.phase = Cursor::kDone;
      return;
    }
    // Corrector.
    double aa = a_pred, pp = p_pred;
    bool converged = false, stuck = false;
    std::string why;
    int it = 0;
    double a_eval = aa, p_eval = pp, last_step = HUGE_VAL;
    for (it = 1; it <= 8; ++it) {
      a_eval = aa;
      p_eval = pp;
      const OrbitStatus s = EvalG(aa, pp, &g, &ga, &map);
      if (s != OrbitStatus::kOk) {
        stuck = s == OrbitStatus::kSticks;
        why = map.message;
        break;
      }
      if (it == 1 && !DGDp(aa, pp, g, hp, &gp)) {
        why = "dG/dp failed on both sides";
        break;
      }
      // [ga gp R^-1... ] in scaled p: dG/d(p/R) = gp R.
      const double r1 = -g, r2 = -(ta * (aa - a_pred) + tp * (pp - p_pred) / R);
      const double j11 = ga, j12 = gp * R, j21 = ta, j22 = tp;
      const double det = j11 * j22 - j12 * j21;
      if (det == 0 || !std::isfinite(det)) {
        why = "singular corrector";
        break;
      }
      const double da = (r1 * j22 - j12 * r2) / det, dps = (j11 * r2 - j21 * r1) / det;
      aa += da;
      pp += dps * R;
      // Converged, or stalled at the integration noise floor.
      const double step = std::abs(da) + std::abs(dps), tol = o_.orbit.EffectiveNewtonTol();
      if (step < tol || (it > 2 && step < 1e3 * tol && step > 0.5 * last_step)) {
        converged = true;
        break;
      }
      last_step = step;
      if (aa <= 0) {
        why = "amplitude became negative";
        break;
      }
    }
    if (!converged) {
      const bool near_touch = last_v - last_xdot_max < 0.1 * std::max(0.05, last_v);
      if (stuck && !hopf_start_pending && (near_touch || ds <= 4 * ds_min)) {
        if (GrazingFromPureSlip(c, p, tp > 0 ? 1.0 : -1.0, std::abs(p_pred - p))) return;
      }
      ds *= 0.5;
      if (ds < ds_min) {
        Fail("pure-slip branch at " + o_.param + " = " + Num(p),
             why.empty() ? "corrector did not converge" : why);
        return;
      }
      continue;
    }
    // Converged beyond the range end: land on the end itself instead.
    if (p_eval > hi_ || p_eval < lo_) {
      const double end = p_eval > hi_ ? hi_ : lo_;
      if (land(end, 0.5 * (a + a_eval)) || !shrink(end)) return;
      continue;
    }
    // New tangent, oriented along the old one.
    double nta = -gp * R, ntp = ga;
    const double n = std::hypot(nta, ntp);
    nta /= n;
    ntp /= n;
    if (nta * ta + ntp * tp < 0) {
      nta = -nta;
      ntp = -ntp;
    }
    const Orbit o = PureSlipFromMap(map);
    if (hopf_start_pending) {
      AddHopfEnd(p_hopf_start, o.stable);
      hopf_start_pending = false;
    } else if (ntp * tp < 0) {
      LocateFold(a, p, a_eval, p_eval, tp < 0);
    }
    Add(FromOrbit(p_eval, o, a_eval));
    a = a_eval;
    p = p_eval;
    ta = nta;
    tp = ntp;
    last_stable = o.stable;
    last_xdot_max = o.xdot_max;
    last_v = Model(At(p)).v();
    if (it <= 3) ds = std::min(1.5 * ds, ds_max);
  }
}

bool Tracer::CoveredByStickSlip(double p) const {
  const double tol = 1e-12 * std::max(1.0, range_);
  double lo = HUGE_VAL, hi = -HUGE_VAL;
  int branch = -1;
  for (const BranchPoint& pt : res_.points) {
    if (pt.kind != PointKind::kStickSlip) continue;
    if (pt.branch != branch) {
      if (p >= lo - tol && p <= hi + tol) return true;
      branch = pt.branch;
      lo = hi = pt.p;
    }
    lo = std::min(lo, pt.p);
    hi = std::max(hi, pt.p);
  }
  return p >= lo - tol && p <= hi + tol;
}

void Tracer::Trace(Cursor c) {
  while (c.phase != Cursor::kDone && !Stop()) {
    if (c.phase == Cursor::kStickSlip)
      TraceStickSlip(c);
    else
      TracePureSlip(c);
  }
  ++branch_;
}

ContinuationResult Tracer::Run() {
  // Hopf points first: pure-slip branches end on them.
  std::vector<BranchPoint> eq_rows = TraceEquilibrium();
  const int eq_id = 0;
  branch_ = 1;
  // The periodic orbit at `from`: stick-slip if the slip phase returns to
  // Omega; otherwise any pure-slip orbit a scan of the section finds.
  Orbit o;
  OrbitResult r;
  if (StickSlipAt(o_.from, &o, &r)) {
    Cursor c;
    c.phase = Cursor::kStickSlip;
    c.p = o_.from;
    c.dir = dir_;
    c.start = o;
    Trace(c);
  } else {
    SetP(o_.from);
    const Model m(At(o_.from));
    const double a_hi = 1.5 * (m.params().mu_s + m.v());
    for (const Orbit& ps : finder_.PureSlipScan(0.005, a_hi, 30)) {
      if (ps.xdot_max >= m.v() || Stop()) continue;
      Cursor c;
      c.phase = Cursor::kPureSlip;
      c.p = o_.from;
      c.a = ps.start[0] - m.SteadySliding().x;
      c.dir = dir_;
      Trace(c);
    }
  }
  // Steady sliding follows (or comes first, if nothing starts at `from`). It is
  // exact and already computed: kept even in a partial result, with its Hopf
  // points.
  for (auto& pt : eq_rows) {
    pt.branch = eq_id;
    Add(pt);
  }
  // Hopf points that no branch has reached yet start their own.
  for (size_t i = 0; i < hopf_.size() && !Stop(); ++i) {
    if (hopf_reached_[i]) continue;
    Cursor c;
    c.phase = Cursor::kPureSlip;
    c.p = hopf_[i];
    c.a = 0;
    c.from_hopf = true;
    Trace(c);
  }
  // Stick-slip orbits exist wherever the slip phase from (x0, v) returns to
  // Omega. One first-return integration per grid point finds any that the
  // branches so far did not reach; each is followed both ways.
  for (const BranchPoint& g : eq_rows) {
    if (Stop()) break;
    if (CoveredByStickSlip(g.p)) continue;
    Orbit o;
    OrbitResult r;
    if (!StickSlipAt(g.p, &o, &r)) continue;
    for (double d : {-dir_, dir_}) {
      Cursor c;
      c.phase = Cursor::kStickSlip;
      c.p = g.p;
      c.dir = d;
      c.skip_first = d == dir_;  // the point at g.p is on the first of the two
      c.start = o;
      Trace(c);
    }
  }
  Stop();
  std::stable_sort(
      res_.special.begin(), res_.special.end(),
      [&](const SpecialPoint& x, const SpecialPoint& y) { return (x.p - y.p) * dir_ < 0; });
  return res_;
}

}  // namespace

ContinuationResult Continue(const Params& base, const ContinuationOptions& options) {
  const std::string err = options.ValidationError(base);
  if (!err.empty()) throw InvalidArgument(err);
  Tracer tracer(base, options);
  return tracer.Run();
}

}  // namespace stickslip
