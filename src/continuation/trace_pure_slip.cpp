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
#include "continuation/special_points.hpp"
#include "numerics/tolerances.hpp"
#include "stickslip/continuation/palc.hpp"

namespace stickslip {

namespace {

// The pure-slip orbit a converged return map describes.
Orbit PureSlipFromMap(const ReturnMap& map) {
  Orbit o;
  o.kind = OrbitKind::kPureSlip;
  o.period = map.period;
  o.extrema = map.flow.extrema;
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
  void BeginCorrection() override { chord_stale_ = true; }
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
    if (!map.has_dpdp && chord_stale_ && !DGDp(u[0], u[1], g)) {
      *why = "dG/dp failed on both sides";
      return false;
    }
    chord_stale_ = false;
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
  bool chord_stale_ = true;  // the held dG/dp must be recomputed before use
};

PalcOptions CurveOptions(const ContinuationOptions& o, double R) {
  PalcOptions p;
  p.ds = p.ds_max = 2 * o.max_step;
  p.ds_min = std::min(o.min_step, p.ds);
  p.max_newton = Tolerances::kMaxCorrector;
  p.fast_iterations = Tolerances::kFastCorrector;
  p.grow = Tolerances::kGrow;
  p.tol = o.orbit.EffectiveNewtonTol();
  p.scale = Eigen::Vector2d(1.0, R);
  p.max_points = o.max_points + 1;  // the start and max_points steps
  p.closed_curves = false;          // a branch ends at range ends, Hopf or grazing points
  return p;
}

// The branch on Palc's loop (Palc::Continue); the hooks add the physics.
class PureSlipTracer : public PalcHooks {
 public:
  PureSlipTracer(BranchContext& ctx, const BranchStart& s)
      : ctx_(ctx),
        o_(ctx.options()),
        R_(ctx.LocalScale(s.p)),
        ds_min_(std::min(o_.min_step, 2 * o_.max_step)),
        // Forward-difference step for dG/dp, balanced against the integration error.
        curve_(ctx, std::max(Tolerances::kBranchDifferenceFloor, std::sqrt(o_.orbit.flow.rtol)) *
                        std::max(R_, std::abs(s.p))),
        palc_(curve_, Options()),
        hopf_pending_(s.from_hopf),
        p_hopf_start_(s.p) {}

  BranchEnd Run(const BranchStart& s);

  Eigen::VectorXd Predict(const PalcPoint& last, double ds, const Eigen::VectorXd&) override {
    return Eigen::Vector2d(last.u[0] + ds * last.tangent[0], last.u[1] + ds * last.tangent[1] * R_);
  }
  PalcAction Predicted(const PalcPoint& last, const Eigen::VectorXd& pred, double* ds) override;
  PalcAction Rejected(const PalcPoint& last, const PalcCorrection& c, const Eigen::VectorXd& pred,
                      double* ds) override;
  PalcAction Converged(const PalcPoint& last, const PalcCorrection& c, PalcPoint* next,
                       double* ds) override;

 private:
  PalcOptions Options() {
    PalcOptions p = CurveOptions(o_, R_);
    p.cancelled = [this] { return ctx_.Stop(); };
    return p;
  }
  bool Start(const BranchStart& s, PalcPoint* first);
  bool Land(double end, double a_guess);
  // A smaller step; false (and the branch failed with `why`) below min_step.
  bool Shrink(double* ds, double p, const std::string& why);
  PalcAction End(BranchEnd e) {
    end_ = e;
    return PalcAction::kEnd;
  }
  BranchEnd AtHopf(const PalcPoint& last);
  double Polish(const PalcCorrection& c);
  void Accept(const PalcPoint& last, const PalcCorrection& c, const PalcPoint& next);

  BranchContext& ctx_;
  const ContinuationOptions& o_;
  const double R_, ds_min_;
  PureSlipCurve curve_;
  Palc palc_;
  bool last_stable_ = true, hopf_pending_;
  double last_xdot_max_ = 0, last_v_ = 0;
  const double p_hopf_start_;
  BranchEnd end_{BranchEnd::kStopped};
};

// The first point and the tangent there; from a Hopf point the tangent is (1, 0).
bool PureSlipTracer::Start(const BranchStart& s, PalcPoint* first) {
  first->u = Eigen::Vector2d(s.a, s.p);
  first->tangent = Eigen::Vector2d(1, 0);
  if (hopf_pending_) return true;  // stability at the start is that of the first orbit
  Eigen::VectorXd f;
  Eigen::MatrixXd jac;
  std::string why;
  curve_.BeginCorrection();
  if (!curve_.Evaluate(first->u, &f, &jac, &why)) {
    ctx_.Fail("pure-slip orbit at " + ctx_.Where(s.p), why);
    return false;
  }
  first->tangent = palc_.Tangent(jac, Eigen::Vector2d(0, s.dir));
  const Orbit o = PureSlipFromMap(curve_.map);
  last_stable_ = o.stable;
  last_xdot_max_ = o.extrema.xdot_max;
  last_v_ = ctx_.At(s.p).v;  // the point was just evaluated: a valid model
  ctx_.Add(ctx_.FromOrbit(s.p, o, s.a));
  return true;
}

// The branch's last point on a range end; false if no orbit converges there.
bool PureSlipTracer::Land(double end, double a_guess) {
  Orbit o;
  double a_end = 0;
  if (!ctx_.PureSlipAtFixedP(end, std::max(a_guess, Tolerances::kLandMinAmplitude), &o, &a_end))
    return false;
  if (hopf_pending_) ctx_.AddHopfEnd(p_hopf_start_, o.stable);
  ctx_.Add(ctx_.FromOrbit(end, o, a_end));
  return true;
}

bool PureSlipTracer::Shrink(double* ds, double p, const std::string& why) {
  *ds *= 0.5;
  ++ctx_.counts().rejected_steps;
  if (*ds >= ds_min_) return true;
  ctx_.Fail("pure-slip orbit at " + ctx_.Where(p), why);
  return false;
}

// Near a Hopf point a^2 is linear in p (the amplitude of a Hopf branch goes
// like sqrt|p - p_HB|), so along the tangent a^2 vanishes a tp R / (2 |ta|) ahead.
BranchEnd PureSlipTracer::AtHopf(const PalcPoint& last) {
  const double a = last.u[0], p = last.u[1];
  const double to_zero = std::abs(a * last.tangent[1] * R_ / (2 * last.tangent[0]));
  if (!ctx_.NearHopf(p, Tolerances::kHopfSlack * to_zero)) {
    ctx_.Fail("pure-slip branch at " + ctx_.Where(p),
              "the amplitude shrinks to zero away from any Hopf point");
    return {BranchEnd::kStopped};
  }
  ctx_.AddHopfEnd(p, last_stable_);
  return {BranchEnd::kHopf, p};
}

// Before a correction: the range ends inside this step (land on it exactly),
// or the amplitude would drop below kAmplitudeEnd (end at the Hopf point).
PalcAction PureSlipTracer::Predicted(const PalcPoint& last, const Eigen::VectorXd& pred,
                                     double* ds) {
  const double a = last.u[0], p = last.u[1], lo = ctx_.lo(), hi = ctx_.hi();
  if (pred[1] > hi || pred[1] < lo) {
    const double end = pred[1] > hi ? hi : lo;
    const Eigen::VectorXd& t = last.tangent;
    if (std::abs(end - p) <= Tolerances::From(o_.orbit.flow.rtol, o_.orbit.flow.atol).on_end * R_)
      return End({BranchEnd::kRangeEnd});
    if (Land(end, a + (end - p) / (t[1] * R_) * t[0])) return End({BranchEnd::kRangeEnd});
    return Shrink(ds, end, "no convergence at the range end") ? PalcAction::kRetry
                                                              : PalcAction::kEnd;
  }
  if (!hopf_pending_ && last.tangent[0] < 0 && pred[0] < Tolerances::kAmplitudeEnd) {
    if (a <= Tolerances::kHopfFrom * Tolerances::kAmplitudeEnd) return End(AtHopf(last));
    return Shrink(ds, p, "no step approaches the Hopf point") ? PalcAction::kRetry
                                                              : PalcAction::kEnd;
  }
  return PalcAction::kGoOn;
}

// A corrector that failed: a grazing point ahead ends the branch; otherwise a
// smaller step (retry), or the branch fails below min_step.
PalcAction PureSlipTracer::Rejected(const PalcPoint& last, const PalcCorrection& c,
                                    const Eigen::VectorXd& pred, double* ds) {
  ctx_.counts().newton_iterations += c.iterations;
  const double p = last.u[1];
  const bool near_touch = last_v_ - last_xdot_max_ <
                          Tolerances::kNearTouch * std::max(Tolerances::kNearTouchMin, last_v_);
  if (curve_.stuck && !hopf_pending_ && (near_touch || *ds <= Tolerances::kSmallStep * ds_min_)) {
    const double dp_sign = last.tangent[1] > 0 ? 1.0 : -1.0;
    double p_gr = 0;
    if (GrazingAhead(ctx_, p, dp_sign, std::abs(pred[1] - p), &p_gr))
      return End({BranchEnd::kGrazing, p_gr, dp_sign, PointKind::kPureSlip});
  }
  *ds *= 0.5;
  ++ctx_.counts().rejected_steps;
  if (*ds >= ds_min_) return PalcAction::kRetry;
  ctx_.Fail("pure-slip branch at " + ctx_.Where(p), c.why);
  return PalcAction::kEnd;
}

// The amplitude of a converged point at its own p. The corrector's step norm
// in (a, p) leaves |G| ~ tol |G_p|, i.e. an amplitude error G / G_a at fixed p
// that grows like 1 / a towards a Hopf point (G_a ~ a there). One Newton step
// in a at fixed p (the extra corrector step) takes it to the integration
// noise; curve_.map follows.
double PureSlipTracer::Polish(const PalcCorrection& c) {
  const double a = c.u[0], da = -c.f[0] / c.jac(0, 0);
  if (!std::isfinite(da) ||
      std::abs(da) <= Tolerances::kPolish * o_.orbit.flow.rtol * std::max(1.0, a))
    return a;
  double g = 0, ga = 0;  // ga: the map's multiplier P' comes with it
  ReturnMap map;
  if (ctx_.EvalG(a + da, c.u[1], &g, &ga, &map) != OrbitStatus::kOk) return a;
  curve_.map = std::move(map);
  return a + da;
}

// A converged point beyond a range end lands on the end instead; otherwise it
// is polished (the extra corrector step) and accepted.
PalcAction PureSlipTracer::Converged(const PalcPoint& last, const PalcCorrection& c,
                                     PalcPoint* next, double* ds) {
  ctx_.counts().newton_iterations += c.iterations;
  const double lo = ctx_.lo(), hi = ctx_.hi();
  if (c.u[1] > hi || c.u[1] < lo) {
    const double end = c.u[1] > hi ? hi : lo;
    if (Land(end, 0.5 * (last.u[0] + c.u[0]))) return End({BranchEnd::kRangeEnd});
    if (hopf_pending_ && c.u[0] <= Tolerances::kHopfFrom * Tolerances::kAmplitudeEnd) {
      // The branch leaves the range before its amplitude can be resolved
      // (below kAmplitudeEnd): in range it is its Hopf point only.
      ctx_.AddHopfEnd(p_hopf_start_, PureSlipFromMap(curve_.map).stable);
      return End({BranchEnd::kHopf, p_hopf_start_});
    }
    return Shrink(ds, end, "no convergence at the range end") ? PalcAction::kRetry
                                                              : PalcAction::kEnd;
  }
  next->u[0] = Polish(c);
  Accept(last, c, *next);
  return PalcAction::kGoOn;
}

// Records an accepted point: its row, the Hopf end it started from, and a
// fold between it and the last point if the tangent's p component changed sign.
void PureSlipTracer::Accept(const PalcPoint& last, const PalcCorrection& c, const PalcPoint& next) {
  Orbit o = PureSlipFromMap(curve_.map);
  o.newton_stalled = c.stalled;
  if (hopf_pending_) {
    ctx_.AddHopfEnd(p_hopf_start_, o.stable);
    hopf_pending_ = false;
  } else if (next.tangent[1] * last.tangent[1] < 0) {
    auto g = [&](double a, double p, double* gv) {
      return ctx_.EvalG(a, p, gv, nullptr, nullptr) == OrbitStatus::kOk;
    };
    double a_lp = 0, p_lp = 0;
    ReturnMap map;
    double gv = 0;
    if (LocateFold(g, last.u[0], last.u[1], c.u[0], c.u[1], last.tangent[1] < 0, R_, &a_lp,
                   &p_lp) &&
        ctx_.EvalG(a_lp, p_lp, &gv, nullptr, &map) == OrbitStatus::kOk)
      ctx_.AddSpecial(FoldPoint(p_lp, map.flow, "fold of the pure-slip branch (smooth LP)"));
  }
  ctx_.Add(ctx_.FromOrbit(c.u[1], o, next.u[0]));
  last_stable_ = o.stable;
  last_xdot_max_ = o.extrema.xdot_max;
  last_v_ = ctx_.At(c.u[1]).v;  // evaluated by EvalG: a valid model
}

BranchEnd PureSlipTracer::Run(const BranchStart& s) {
  PalcPoint first;
  if (!Start(s, &first)) return {BranchEnd::kStopped};
  const double ds_max = 2 * o_.max_step;
  const double ds = hopf_pending_ ? std::max(Tolerances::kAmplitudeEnd * 1.5, ds_max) : ds_max;
  const PalcResult r = palc_.Continue(first, ds, *this);
  if (r.status == PalcStatus::kMaxPoints)
    ctx_.Fail("pure-slip branch at " + ctx_.Where(r.points.back().u[1]), r.message);
  return end_;
}

}  // namespace

BranchEnd TracePureSlip(BranchContext& ctx, const BranchStart& start) {
  return PureSlipTracer(ctx, start).Run(start);
}

}  // namespace stickslip
