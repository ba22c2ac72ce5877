// The pure-slip branch tracer: pseudo-arclength continuation (Keller 1977) of
// G(a, p) = 0 in scaled coordinates (a, p / |to - from|), a = x* - xbar the
// section amplitude; the corrector is Newton on G and the arclength condition,
// with dG/dp by a one-sided difference once per step.
#include <algorithm>
#include <cmath>

#include "branch_tracers.hpp"
#include "stickslip/special_points.hpp"

namespace stickslip {

namespace {

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

// The unit tangent of G(a, p / R) = 0 from its gradient (ga, gp R), oriented
// along (ra, rp).
void Tangent(double ga, double gp_scaled, double ra, double rp, double* ta, double* tp) {
  double nta = -gp_scaled, ntp = ga;
  const double n = std::hypot(nta, ntp);
  nta /= n;
  ntp /= n;
  if (nta * ra + ntp * rp < 0) {
    nta = -nta;
    ntp = -ntp;
  }
  *ta = nta;
  *tp = ntp;
}

class PureSlipTracer {
 public:
  PureSlipTracer(BranchContext& ctx, const BranchStart& s)
      : ctx_(ctx),
        o_(ctx.options()),
        R_(ctx.range()),
        ds_max_(2 * o_.max_step),
        ds_min_(o_.min_step),
        a_(s.a),
        p_(s.p),
        ds_(ds_max_),
        // Forward-difference step for dG/dp, balanced against the integration error.
        hp_(std::max(1e-7, std::sqrt(o_.orbit.flow.rtol)) * std::max(R_, std::abs(s.p))),
        hopf_pending_(s.from_hopf),
        p_hopf_start_(s.p) {}

  BranchEnd Run(const BranchStart& s);

 private:
  struct Corrected {
    bool converged = false, stuck = false;
    int iterations = 0;
    double a = 0, p = 0;  // where G was last evaluated
    std::string why;
  };
  bool Start(double dir);
  bool DGDp(double a, double p, double g, double* gp);
  Corrected Correct(double a_pred, double p_pred);
  bool Land(double end, double a_guess);
  bool Shrink(double end);
  BranchEnd AtHopf();
  BranchEnd Rejected(const Corrected& c, double p_pred, bool* retry);
  void Accept(const Corrected& c);
  // A pure-slip step sticks: a grazing point ahead in p, within a few steps.
  bool GrazingAhead(double dp_sign, double step, double* p_gr);

  BranchContext& ctx_;
  const ContinuationOptions& o_;
  const double R_, ds_max_, ds_min_;
  double a_, p_, ta_ = 1, tp_ = 0, ds_, hp_;
  ReturnMap map_;
  double g_ = 0, ga_ = 0, gp_ = 0;
  bool last_stable_ = true, hopf_pending_;
  double last_xdot_max_ = 0, last_v_ = 0;
  const double p_hopf_start_;
  static constexpr BranchEnd kStopped{BranchEnd::kStopped};
};

bool PureSlipTracer::DGDp(double a, double p, double g, double* gp) {
  for (double step : {hp_, -hp_}) {
    double g2 = 0;
    if (ctx_.EvalG(a, p + step, &g2, nullptr, nullptr) == OrbitStatus::kOk) {
      *gp = (g2 - g) / step;
      return true;
    }
  }
  return false;
}

// The first point and the tangent there; from a Hopf point the tangent is (1, 0).
bool PureSlipTracer::Start(double dir) {
  if (hopf_pending_) {
    ds_ = std::max(tuning::kAmplitudeEnd * 1.5, ds_max_);
    return true;  // stability at the start is that of the first orbit, added with it
  }
  const std::string where = "pure-slip orbit at " + ctx_.Where(p_);
  if (ctx_.EvalG(a_, p_, &g_, &ga_, &map_) != OrbitStatus::kOk) {
    ctx_.Fail(where, map_.message);
    return false;
  }
  if (!DGDp(a_, p_, g_, &gp_)) {
    ctx_.Fail(where, "dG/dp failed on both sides");
    return false;
  }
  Tangent(ga_, gp_ * R_, 0, dir, &ta_, &tp_);
  const Orbit o = PureSlipFromMap(map_);
  last_stable_ = o.stable;
  last_xdot_max_ = o.xdot_max;
  last_v_ = Model(ctx_.At(p_)).v();
  ctx_.Add(ctx_.FromOrbit(p_, o, a_));
  return true;
}

// Newton on (G, arclength) from the predictor, a 2x2 system solved by Cramer's rule.
PureSlipTracer::Corrected PureSlipTracer::Correct(double a_pred, double p_pred) {
  Corrected c;
  double aa = a_pred, pp = p_pred, last_step = HUGE_VAL;
  for (c.iterations = 1; c.iterations <= tuning::kMaxCorrector; ++c.iterations) {
    c.a = aa;
    c.p = pp;
    ++ctx_.counts().newton_iterations;
    const OrbitStatus s = ctx_.EvalG(aa, pp, &g_, &ga_, &map_);
    if (s != OrbitStatus::kOk) {
      c.stuck = s == OrbitStatus::kSticks;
      c.why = map_.message;
      return c;
    }
    if (c.iterations == 1 && !DGDp(aa, pp, g_, &gp_)) {
      c.why = "dG/dp failed on both sides";
      return c;
    }
    // In scaled p: dG/d(p/R) = gp R.
    const double r1 = -g_, r2 = -(ta_ * (aa - a_pred) + tp_ * (pp - p_pred) / R_);
    const double j11 = ga_, j12 = gp_ * R_, j21 = ta_, j22 = tp_;
    const double det = j11 * j22 - j12 * j21;
    if (det == 0 || !std::isfinite(det)) {
      c.why = "singular corrector";
      return c;
    }
    const double da = (r1 * j22 - j12 * r2) / det, dps = (j11 * r2 - j21 * r1) / det;
    aa += da;
    pp += dps * R_;
    // Converged, or stalled at the integration noise floor.
    const double step = std::abs(da) + std::abs(dps), tol = o_.orbit.EffectiveNewtonTol();
    if (step < tol || (c.iterations > tuning::kStallAfter && step < tuning::kStallFactor * tol &&
                       step > tuning::kStallRatio * last_step)) {
      c.converged = true;
      return c;
    }
    last_step = step;
    if (aa <= 0) {
      c.why = "amplitude became negative";
      return c;
    }
  }
  return c;
}

// The branch's last point on a range end; false if no orbit converges there.
bool PureSlipTracer::Land(double end, double a_guess) {
  Orbit o;
  double a_end = 0;
  if (!ctx_.PureSlipAtFixedP(end, std::max(a_guess, tuning::kLandMinAmplitude), &o, &a_end))
    return false;
  if (hopf_pending_) ctx_.AddHopfEnd(p_hopf_start_, o.stable);
  ctx_.Add(ctx_.FromOrbit(end, o, a_end));
  return true;
}

// A smaller step towards the end; false (and the branch failed) below min_step.
bool PureSlipTracer::Shrink(double end) {
  ds_ *= 0.5;
  ++ctx_.counts().rejected_steps;
  if (ds_ >= ds_min_) return true;
  ctx_.Fail("pure-slip orbit at " + ctx_.Where(end), "no convergence at the range end");
  return false;
}

BranchEnd PureSlipTracer::AtHopf() {
  if (!ctx_.NearHopf(p_)) {
    ctx_.Fail("pure-slip branch at " + ctx_.Where(p_),
              "the amplitude shrinks to zero away from any Hopf point");
    return kStopped;
  }
  ctx_.AddHopfEnd(p_, last_stable_);
  return {BranchEnd::kHopf, p_};
}

bool PureSlipTracer::GrazingAhead(double dp_sign, double step, double* p_gr) {
  double gap0 = 0;
  if (!ctx_.GrazingGapAt(p_, &gap0)) return false;
  double q = p_;
  for (int k = 0; k < tuning::kSearchSteps; ++k) {
    double q2 = p_ + dp_sign * step * std::pow(tuning::kSearchGrow, k);
    q2 = std::min(ctx_.hi(), std::max(ctx_.lo(), q2));
    double gap2 = 0;
    const bool ok = ctx_.GrazingGapAt(q2, &gap2);
    if (ok && gap0 * gap2 < 0) {
      const RootResult r =
          LocateGrazing(ctx_.finder(), ctx_.base(), ctx_.axis(), p_, q2, gap0, gap2, o_.locate_tol);
      *p_gr = r.x;
      return r.ok;
    }
    if (q2 == q) break;  // at the range end
    q = q2;
  }
  return false;
}

// A corrector that failed: a grazing point ahead ends the branch; otherwise a
// smaller step (retry), or the branch fails below min_step.
BranchEnd PureSlipTracer::Rejected(const Corrected& c, double p_pred, bool* retry) {
  *retry = false;
  const bool near_touch =
      last_v_ - last_xdot_max_ < tuning::kNearTouch * std::max(tuning::kNearTouchMin, last_v_);
  if (c.stuck && !hopf_pending_ && (near_touch || ds_ <= tuning::kSmallStep * ds_min_)) {
    const double dp_sign = tp_ > 0 ? 1.0 : -1.0;
    double p_gr = 0;
    if (GrazingAhead(dp_sign, std::abs(p_pred - p_), &p_gr))
      return {BranchEnd::kGrazing, p_gr, dp_sign, PointKind::kPureSlip};
  }
  ds_ *= 0.5;
  ++ctx_.counts().rejected_steps;
  if (ds_ < ds_min_) {
    ctx_.Fail("pure-slip branch at " + ctx_.Where(p_),
              c.why.empty() ? "corrector did not converge" : c.why);
    return kStopped;
  }
  *retry = true;
  return kStopped;
}

// A converged point: new tangent along the old one, fold between the two
// points if the tangent's p component changed sign.
void PureSlipTracer::Accept(const Corrected& c) {
  double nta = 0, ntp = 0;
  Tangent(ga_, gp_ * R_, ta_, tp_, &nta, &ntp);
  const Orbit o = PureSlipFromMap(map_);
  if (hopf_pending_) {
    ctx_.AddHopfEnd(p_hopf_start_, o.stable);
    hopf_pending_ = false;
  } else if (ntp * tp_ < 0) {
    auto g = [&](double a, double p, double* gv) {
      return ctx_.EvalG(a, p, gv, nullptr, nullptr) == OrbitStatus::kOk;
    };
    double a_lp = 0, p_lp = 0;
    ReturnMap map;
    double gv = 0;
    if (LocateFold(g, a_, p_, c.a, c.p, tp_ < 0, R_, &a_lp, &p_lp) &&
        ctx_.EvalG(a_lp, p_lp, &gv, nullptr, &map) == OrbitStatus::kOk)
      ctx_.AddSpecial(FoldPoint(p_lp, map.flow, "fold of the pure-slip branch (smooth LP)"));
  }
  ctx_.Add(ctx_.FromOrbit(c.p, o, c.a));
  a_ = c.a;
  p_ = c.p;
  ta_ = nta;
  tp_ = ntp;
  last_stable_ = o.stable;
  last_xdot_max_ = o.xdot_max;
  last_v_ = Model(ctx_.At(p_)).v();
  if (c.iterations <= tuning::kFastCorrector) ds_ = std::min(tuning::kGrow * ds_, ds_max_);
}

BranchEnd PureSlipTracer::Run(const BranchStart& s) {
  if (!Start(s.dir)) return kStopped;
  const double lo = ctx_.lo(), hi = ctx_.hi();
  for (int count = 1; !ctx_.Stop(); ++count) {
    if (count > o_.max_points) {
      ctx_.Fail("pure-slip branch at " + ctx_.Where(p_),
                "more than max_points = " + std::to_string(o_.max_points) + " points");
      return kStopped;
    }
    const double a_pred = a_ + ds_ * ta_, p_pred = p_ + ds_ * tp_ * R_;
    // The range ends inside this step: land on it exactly.
    if (p_pred > hi || p_pred < lo) {
      const double end = p_pred > hi ? hi : lo;
      if (std::abs(end - p_) <= 1e-13 * R_) return {BranchEnd::kRangeEnd};
      if (Land(end, a_ + (end - p_) / (tp_ * R_) * ta_)) return {BranchEnd::kRangeEnd};
      if (!Shrink(end)) return kStopped;
      continue;
    }
    if (!hopf_pending_ && ta_ < 0 && a_pred < tuning::kAmplitudeEnd) return AtHopf();
    const Corrected c = Correct(a_pred, p_pred);
    if (!c.converged) {
      bool retry = false;
      const BranchEnd e = Rejected(c, p_pred, &retry);
      if (retry) continue;
      return e;
    }
    // Converged beyond the range end: land on the end itself instead.
    if (c.p > hi || c.p < lo) {
      const double end = c.p > hi ? hi : lo;
      if (Land(end, 0.5 * (a_ + c.a))) return {BranchEnd::kRangeEnd};
      if (!Shrink(end)) return kStopped;
      continue;
    }
    Accept(c);
  }
  return kStopped;
}

}  // namespace

BranchEnd TracePureSlip(BranchContext& ctx, const BranchStart& start) {
  return PureSlipTracer(ctx, start).Run(start);
}

}  // namespace stickslip
