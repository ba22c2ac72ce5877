// The pure-slip branch tracer: G(a, p) = 0, a = x* - xbar the section
// amplitude, as a PALC problem (palc.hpp) in scaled coordinates
// (a, p / |to - from|); dG/dp from the parameter column at every evaluation
// (Taylor, BranchContext::column()), else by a one-sided difference once per
// correction.
// The tracer adds what the physics needs: landing on the range ends, ending
// on a Hopf point, handing over at a grazing point.
#include <algorithm>
#include <cmath>

#include "continuation/branch_tracers.hpp"
#include "stickslip/continuation/palc.hpp"
#include "continuation/special_points.hpp"

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

// G(a, p) = 0 for the PALC; dG/dp from the parameter column, or by a
// difference held over one correction (a chord).
class PureSlipCurve : public PalcProblem {
 public:
  PureSlipCurve(BranchContext& ctx, double hp) : ctx_(ctx), hp_(hp) {}
  int unknowns() const override { return 2; }
  void BeginCorrection() override { fresh_ = true; }
  bool Evaluate(const Eigen::VectorXd& u, Eigen::VectorXd* f, Eigen::MatrixXd* jac,
                std::string* why) override {
    double g = 0, ga = 0;
    const OrbitStatus s = ctx_.EvalG(u[0], u[1], &g, &ga, &map, ctx_.column() ? &gp_ : nullptr);
    stuck = s == OrbitStatus::kSticks;
    if (s != OrbitStatus::kOk) {
      *why = map.message;
      return false;
    }
    // The column's dG/dp is this evaluation's; the quotient is held (a chord).
    if (!map.has_dpdp && fresh_ && !DGDp(u[0], u[1], g)) {
      *why = "dG/dp failed on both sides";
      return false;
    }
    fresh_ = false;
    *f = Eigen::VectorXd::Constant(1, g);
    *jac = Eigen::MatrixXd(1, 2);
    (*jac) << ga, gp_;
    return true;
  }
  std::string DomainError(const Eigen::VectorXd& u) const override {
    return u[0] <= 0 ? "amplitude became negative" : "";
  }
  ReturnMap map;       // of the last evaluation
  bool stuck = false;  // the last evaluation stuck to the belt

 private:
  // dG/dp by a one-sided difference (forward, else backward); g = G(a, p).
  bool DGDp(double a, double p, double g) {
    for (double step : {hp_, -hp_}) {
      double g2 = 0;
      if (ctx_.EvalG(a, p + step, &g2, nullptr, nullptr) == OrbitStatus::kOk) {
        gp_ = (g2 - g) / step;
        return true;
      }
    }
    return false;
  }
  BranchContext& ctx_;
  const double hp_;
  double gp_ = 0;
  bool fresh_ = true;
};

PalcOptions CurveOptions(const ContinuationOptions& o, double R) {
  PalcOptions p;
  p.ds = p.ds_max = 2 * o.max_step;
  p.ds_min = std::min(o.min_step, p.ds);
  p.max_newton = tuning::kMaxCorrector;
  p.tol = o.orbit.EffectiveNewtonTol();
  p.scale = Eigen::Vector2d(1.0, R);
  return p;
}

class PureSlipTracer {
 public:
  PureSlipTracer(BranchContext& ctx, const BranchStart& s)
      : ctx_(ctx),
        o_(ctx.options()),
        R_(ctx.LocalScale(s.p)),
        ds_max_(2 * o_.max_step),
        ds_min_(o_.min_step),
        a_(s.a),
        p_(s.p),
        ds_(ds_max_),
        // Forward-difference step for dG/dp, balanced against the integration error.
        curve_(ctx, std::max(1e-7, std::sqrt(o_.orbit.flow.rtol)) * std::max(R_, std::abs(s.p))),
        palc_(curve_, CurveOptions(o_, R_)),
        hopf_pending_(s.from_hopf),
        p_hopf_start_(s.p) {}

  BranchEnd Run(const BranchStart& s);

 private:
  bool Start(double dir);
  bool Land(double end, double a_guess);
  // A smaller step; false (and the branch failed with `why`) below min_step.
  bool Shrink(double p, const char* why);
  BranchEnd AtHopf();
  BranchEnd Rejected(const PalcCorrection& c, double p_pred, bool* retry);
  void Accept(const PalcCorrection& c);
  double Polish(const PalcCorrection& c);

  BranchContext& ctx_;
  const ContinuationOptions& o_;
  const double R_, ds_max_, ds_min_;
  double a_, p_;
  Eigen::Vector2d t_ = Eigen::Vector2d(1, 0);  // unit tangent, scaled (a, p / R)
  double ds_;
  PureSlipCurve curve_;
  Palc palc_;
  bool last_stable_ = true, hopf_pending_;
  double last_xdot_max_ = 0, last_v_ = 0;
  const double p_hopf_start_;
  static constexpr BranchEnd kStopped{BranchEnd::kStopped};
};

// The first point and the tangent there; from a Hopf point the tangent is (1, 0).
bool PureSlipTracer::Start(double dir) {
  if (hopf_pending_) {
    ds_ = std::max(tuning::kAmplitudeEnd * 1.5, ds_max_);
    return true;  // stability at the start is that of the first orbit, added with it
  }
  Eigen::VectorXd f;
  Eigen::MatrixXd jac;
  std::string why;
  curve_.BeginCorrection();
  if (!curve_.Evaluate(Eigen::Vector2d(a_, p_), &f, &jac, &why)) {
    ctx_.Fail("pure-slip orbit at " + ctx_.Where(p_), why);
    return false;
  }
  t_ = palc_.Tangent(jac, Eigen::Vector2d(0, dir));
  const Orbit o = PureSlipFromMap(curve_.map);
  last_stable_ = o.stable;
  last_xdot_max_ = o.xdot_max;
  last_v_ = Model(ctx_.At(p_)).v();
  ctx_.Add(ctx_.FromOrbit(p_, o, a_));
  return true;
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

bool PureSlipTracer::Shrink(double p, const char* why) {
  ds_ *= 0.5;
  ++ctx_.counts().rejected_steps;
  if (ds_ >= ds_min_) return true;
  ctx_.Fail("pure-slip orbit at " + ctx_.Where(p), why);
  return false;
}

// Near a Hopf point a^2 is linear in p (the amplitude of a Hopf branch goes
// like sqrt|p - p_HB|), so along the tangent a^2 vanishes a tp R / (2 |ta|) ahead.
BranchEnd PureSlipTracer::AtHopf() {
  const double to_zero = std::abs(a_ * t_[1] * R_ / (2 * t_[0]));
  if (!ctx_.NearHopf(p_, tuning::kHopfSlack * to_zero)) {
    ctx_.Fail("pure-slip branch at " + ctx_.Where(p_),
              "the amplitude shrinks to zero away from any Hopf point");
    return kStopped;
  }
  ctx_.AddHopfEnd(p_, last_stable_);
  return {BranchEnd::kHopf, p_};
}

// A corrector that failed: a grazing point ahead ends the branch; otherwise a
// smaller step (retry), or the branch fails below min_step.
BranchEnd PureSlipTracer::Rejected(const PalcCorrection& c, double p_pred, bool* retry) {
  *retry = false;
  const bool near_touch =
      last_v_ - last_xdot_max_ < tuning::kNearTouch * std::max(tuning::kNearTouchMin, last_v_);
  if (curve_.stuck && !hopf_pending_ && (near_touch || ds_ <= tuning::kSmallStep * ds_min_)) {
    const double dp_sign = t_[1] > 0 ? 1.0 : -1.0;
    double p_gr = 0;
    if (GrazingAhead(ctx_, p_, dp_sign, std::abs(p_pred - p_), &p_gr))
      return {BranchEnd::kGrazing, p_gr, dp_sign, PointKind::kPureSlip};
  }
  ds_ *= 0.5;
  ++ctx_.counts().rejected_steps;
  if (ds_ < ds_min_) {
    ctx_.Fail("pure-slip branch at " + ctx_.Where(p_), c.why);
    return kStopped;
  }
  *retry = true;
  return kStopped;
}

// The amplitude of a converged point at its own p. The corrector's step norm
// in (a, p) leaves |G| ~ tol |G_p|, i.e. an amplitude error G / G_a at fixed p
// that grows like 1 / a towards a Hopf point (G_a ~ a there). One Newton step
// in a at fixed p takes it to the integration noise; curve_.map follows.
double PureSlipTracer::Polish(const PalcCorrection& c) {
  const double a = c.u[0], da = -c.f[0] / c.jac(0, 0);
  if (!std::isfinite(da) || std::abs(da) <= tuning::kPolish * o_.orbit.flow.rtol * std::max(1.0, a))
    return a;
  double g = 0, ga = 0;  // ga: the map's multiplier P' comes with it
  ReturnMap map;
  if (ctx_.EvalG(a + da, c.u[1], &g, &ga, &map) != OrbitStatus::kOk) return a;
  curve_.map = std::move(map);
  return a + da;
}

// A converged point: new tangent along the old one, fold between the two
// points if the tangent's p component changed sign.
void PureSlipTracer::Accept(const PalcCorrection& c) {
  const Eigen::VectorXd t = palc_.Tangent(c.jac, t_);
  const double a = Polish(c);
  Orbit o = PureSlipFromMap(curve_.map);
  o.newton_stalled = c.stalled;
  if (hopf_pending_) {
    ctx_.AddHopfEnd(p_hopf_start_, o.stable);
    hopf_pending_ = false;
  } else if (t[1] * t_[1] < 0) {
    auto g = [&](double a, double p, double* gv) {
      return ctx_.EvalG(a, p, gv, nullptr, nullptr) == OrbitStatus::kOk;
    };
    double a_lp = 0, p_lp = 0;
    ReturnMap map;
    double gv = 0;
    if (LocateFold(g, a_, p_, c.u[0], c.u[1], t_[1] < 0, R_, &a_lp, &p_lp) &&
        ctx_.EvalG(a_lp, p_lp, &gv, nullptr, &map) == OrbitStatus::kOk)
      ctx_.AddSpecial(FoldPoint(p_lp, map.flow, "fold of the pure-slip branch (smooth LP)"));
  }
  ctx_.Add(ctx_.FromOrbit(c.u[1], o, a));
  a_ = a;
  p_ = c.u[1];
  t_ = t;
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
    const double a_pred = a_ + ds_ * t_[0], p_pred = p_ + ds_ * t_[1] * R_;
    // The range ends inside this step: land on it exactly.
    if (p_pred > hi || p_pred < lo) {
      const double end = p_pred > hi ? hi : lo;
      if (std::abs(end - p_) <= 1e-13 * R_) return {BranchEnd::kRangeEnd};
      if (Land(end, a_ + (end - p_) / (t_[1] * R_) * t_[0])) return {BranchEnd::kRangeEnd};
      if (!Shrink(end, "no convergence at the range end")) return kStopped;
      continue;
    }
    if (!hopf_pending_ && t_[0] < 0 && a_pred < tuning::kAmplitudeEnd) {
      if (a_ <= tuning::kHopfFrom * tuning::kAmplitudeEnd) return AtHopf();
      if (!Shrink(p_, "no step approaches the Hopf point")) return kStopped;
      continue;
    }
    const PalcCorrection c = palc_.Correct(Eigen::Vector2d(a_pred, p_pred), t_);
    ctx_.counts().newton_iterations += c.iterations;
    if (!c.ok) {
      bool retry = false;
      const BranchEnd e = Rejected(c, p_pred, &retry);
      if (retry) continue;
      return e;
    }
    // Converged beyond the range end: land on the end itself instead.
    if (c.u[1] > hi || c.u[1] < lo) {
      const double end = c.u[1] > hi ? hi : lo;
      if (Land(end, 0.5 * (a_ + c.u[0]))) return {BranchEnd::kRangeEnd};
      if (hopf_pending_ && c.u[0] <= tuning::kHopfFrom * tuning::kAmplitudeEnd) {
        // The branch leaves the range before its amplitude can be resolved
        // (below kAmplitudeEnd): in range it is its Hopf point only.
        ctx_.AddHopfEnd(p_hopf_start_, PureSlipFromMap(curve_.map).stable);
        return {BranchEnd::kHopf, p_hopf_start_};
      }
      if (!Shrink(end, "no convergence at the range end")) return kStopped;
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
