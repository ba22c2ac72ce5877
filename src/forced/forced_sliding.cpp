// Sliding bifurcations on forced branches (branch.hpp, ForcedLabel): the
// classification of di Bernardo, Kowalczyk & Nordmark (Physica D 170, 2002,
// section 3) as Kowalczyk & Piiroinen (Physica D 237, 2008) find it in a
// forced dry-friction oscillator, read off the change of the orbit's stick
// structure; and the natural-parameter search across a jump of the map.
#include "forced_sliding.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "numerics/numbers.hpp"
#include "numerics/tolerances.hpp"

namespace stickslip::forced_detail {

ForcedBranchRow RowOf(const ForcedOrbit& o, double p) {
  ForcedBranchRow r;
  r.p = p;
  r.x0 = o.start.x, r.xdot0 = o.start.xdot;
  r.m = o.m;
  r.sticks = o.sticks, r.crossings = o.crossings;
  r.extrema = o.extrema;
  r.multipliers[0] = o.multipliers[0], r.multipliers[1] = o.multipliers[1];
  r.stable = o.stable;
  return r;
}

namespace {

ForcedParams At(const ForcedParams& base, ForcedAxis axis, double p) {
  ForcedParams q = base;
  SetAxis(q, axis, p);
  return q;
}

// The events over one period of the orbit of row r.
std::vector<ForcedEvent> Events(const ForcedParams& base, ForcedAxis axis,
                                const ForcedBranchOptions& o, const ForcedBranchRow& r) {
  const ForcedModel model(At(base, axis, r.p));
  std::vector<ForcedEvent> ev;
  ForcedRequest rq;
  rq.t_end = r.m * model.period();
  rq.events = &ev;
  rq.extremes = false;
  ForcedFlow(model, o.flow).Run(ForcedStart(model, 0, r.x0, r.xdot0), rq);
  return ev;
}

// How close an arrival at x' = v (a crossing, or a stick entry) comes to the
// stick band's edge: min | |x + 2 beta v - A cos(Omega t)| - mu_s | over the
// arrivals (inf: none). Crossing-sliding is an arrival on the edge, from
// either side (di Bernardo, Kowalczyk & Nordmark 2002, section 3.1).
double CrossingToEdge(const ForcedParams& base, ForcedAxis axis, const ForcedBranchOptions& o,
                      const ForcedBranchRow& r) {
  const ForcedModel model(At(base, axis, r.p));
  double best = std::numeric_limits<double>::infinity();
  for (const ForcedEvent& e : Events(base, axis, o, r))
    if (e.kind == ForcedEventKind::kCrossing || e.kind == ForcedEventKind::kStickIn)
      best = std::min(best, std::abs(std::abs(model.StickForce(e.t, e.x)) - model.static_limit()));
  return best;
}

// The shortest slip phase that runs from a stick exit to the next stick
// entry, over one period T of the orbit from row r (events wrap around T).
double ShortestSlipBetweenSticks(const ForcedParams& base, ForcedAxis axis,
                                 const ForcedBranchOptions& o, const ForcedBranchRow& r) {
  const ForcedModel model(At(base, axis, r.p));
  const std::vector<ForcedEvent> ev = Events(base, axis, o, r);
  const double period = r.m * model.period();
  double best = period;
  const size_t n = ev.size();
  for (size_t i = 0; i < n; ++i) {
    if (ev[i].kind != ForcedEventKind::kStickOut) continue;
    for (size_t k = 1; k <= n; ++k) {  // the next event that is no touch
      const ForcedEvent& e = ev[(i + k) % n];
      if (e.kind == ForcedEventKind::kTouch) continue;
      if (e.kind == ForcedEventKind::kStickIn) {
        const double dt = e.t - ev[i].t + (i + k >= n ? period : 0);
        best = std::min(best, dt);
      }
      break;
    }
  }
  return best;
}

// How close the stick force of a stick phase comes to the band's edge at an
// interior extremum: min (mu_s - |f(t)|) over the roots of
// f' = v + A Omega sin(Omega t) = 0 inside the stick phases of row r's orbit,
// f = x_a + v (t - t_a) + 2 beta v - A cos(Omega t) (the stick force of docs/theory.md, "One core";
// inf: none). Zero where a stick phase splits (adding-sliding, di Bernardo, Kowalczyk & Nordmark
// 2002, section 3, case 4).
double StickTouchToEdge(const ForcedParams& base, ForcedAxis axis, const ForcedBranchOptions& o,
                        const ForcedBranchRow& r) {
  const ForcedModel model(At(base, axis, r.p));
  const double w = model.omega(), s = -model.v() / (model.force() * w);
  double best = std::numeric_limits<double>::infinity();
  if (!(std::abs(s) <= 1)) return best;
  const double period = r.m * model.period();
  std::vector<ForcedEvent> ev = Events(base, axis, o, r);
  // The stick phases as (t_a, x_a, t_b): one from t = 0 if the orbit starts stuck.
  std::vector<std::array<double, 3>> phases;
  double t_a = r.xdot0 == model.v() ? 0 : NAN, x_a = r.x0;
  for (const ForcedEvent& e : ev) {
    if (e.kind == ForcedEventKind::kStickIn) t_a = e.t, x_a = e.x;
    if (e.kind == ForcedEventKind::kStickOut && std::isfinite(t_a))
      phases.push_back({t_a, x_a, e.t}), t_a = NAN;
  }
  if (std::isfinite(t_a)) phases.push_back({t_a, x_a, period});
  for (const auto& ph : phases)
    for (const double root : {std::asin(s), M_PI - std::asin(s)})
      for (double t = root / w + std::ceil((ph[0] - root / w) / model.period()) * model.period();
           t < ph[2]; t += model.period()) {
        if (t <= ph[0]) continue;
        best = std::min(best, model.static_limit() -
                                  std::abs(model.StickForce(t, ph[1] + model.v() * (t - ph[0]))));
      }
  return best;
}

std::string Change(const ForcedBranchRow& a, const ForcedBranchRow& b) {
  return "sticks " + std::to_string(a.sticks) + " -> " + std::to_string(b.sticks) + ", crossings " +
         std::to_string(a.crossings) + " -> " + std::to_string(b.crossings);
}

}  // namespace

void ClassifySliding(const ForcedParams& base, ForcedAxis axis, const ForcedBranchOptions& o,
                     const ForcedBranchRow& before, const ForcedBranchRow& after,
                     ForcedBranchRow* point) {
  const int ds = after.sticks - before.sticks, dc = after.crossings - before.crossings;
  const std::string change = " (" + Change(before, after) + ")";
  // An arrival on the band's edge at the point: crossing-sliding, also where
  // the stick it becomes merges with the next one (a jump, mu_s > mu_k).
  // A change of crossings alone is one too: on x' = v outside the band
  // x'' = -f +- mu(0+) != 0, so a crossing is born or lost only where an
  // arrival passes the band's edge, never by a tangency (docs/theory.md,
  // "Why no SW"; the Den Hartog floor's reference, ForcedSwitchingSliding).
  const Tolerances tol = Tolerances::From(o.flow.rtol, o.flow.atol);
  const double edge = tol.BandEdge() * (1 + before.extrema.x_max - before.extrema.x_min);
  const bool on_edge =
      std::min(CrossingToEdge(base, axis, o, before), CrossingToEdge(base, axis, o, after)) <= edge;
  if ((ds != 0 && dc == -ds) || (dc != 0 && (on_edge || ds == 0))) {
    point->label = ForcedLabel::kCR;
    // The description follows the counts' direction (issue 35, item 4).
    const char* what = ds > 0   ? "a crossing of x' = v reaches the stick band's edge and turns "
                                  "into a stick phase"
                       : ds < 0 ? "a stick phase shrinks to a crossing of x' = v on the stick "
                                  "band's edge"
                       : dc < 0 ? "a crossing of x' = v reaches the stick band's edge and is lost"
                                : "a crossing of x' = v is born on the stick band's edge";
    point->description = std::string("crossing-sliding: ") + what + change;
  } else if (ds != 0 && dc == 0) {
    // Adding-sliding leaves a slip phase between two sticks that vanishes at
    // the point; grazing-sliding a stick phase born from a tangency.
    const ForcedBranchRow& more = ds > 0 ? after : before;
    const ForcedModel model(At(base, axis, more.p));
    const double slip = ShortestSlipBetweenSticks(base, axis, o, more);
    const double vanishing = tol.VanishingPhase() * more.m * model.period();
    if (slip <= vanishing) {
      point->label = ForcedLabel::kAD;
      point->description =
          std::string("adding-sliding: the stick force touches the band's edge tangentially, ") +
          (ds > 0 ? "a stick phase splits around a short slip"
                  : "two stick phases merge as the slip between them vanishes") +
          change;
    } else {
      point->label = ForcedLabel::kGR;
      point->description =
          std::string(
              "grazing-sliding: a slip phase touches x' = v tangentially (x'' = 0) "
              "inside the stick band, ") +
          (ds > 0 ? "a stick phase is born" : "a stick phase vanishes") + change;
    }
  } else {
    point->label = ForcedLabel::kSL;
    point->description = "sliding bifurcation: the stick structure changes" + change;
  }
}

namespace {
constexpr int kConfirmSteps = 4;  // natural steps that confirm an edge in BisectEdge
}  // namespace

bool BisectEdge(const ForcedParams& base, ForcedAxis axis, const ForcedBranchOptions& o,
                ForcedBranchRow lo, double hi, double tol, ForcedBranchRow* before,
                ForcedBranchRow* after, std::string* why) {
  const ForcedBranchRow ref = lo;
  ForcedOrbitOptions oo;
  oo.flow = o.flow;
  auto shoot = [&](double p, const ForcedBranchRow& from) {
    return ShootStroboscopic(ForcedModel(At(base, axis, p)), from.x0, from.xdot0, ref.m, oo);
  };
  auto good = [&](const ForcedOrbit& orb) {
    return orb.status == ForcedOrbitStatus::kConverged && orb.sticks == ref.sticks &&
           orb.crossings == ref.crossings;
  };
  // Newton from the secant predictor through the last two orbits: from lo's
  // state alone, the first iterate near the edge can land past it and
  // converge to another orbit, which would end the bisection early (measured:
  // 9e-6 short of a crossing-sliding point on the coulomb belt, issue 20).
  ForcedBranchRow prev = lo;
  bool have_prev = false;
  while (std::abs(hi - lo.p) > tol * (1 + std::abs(lo.p))) {
    const double mid = 0.5 * (lo.p + hi);
    ForcedBranchRow guess = lo;
    if (have_prev) {
      const double s = (mid - lo.p) / (lo.p - prev.p);
      guess.x0 += s * (lo.x0 - prev.x0), guess.xdot0 += s * (lo.xdot0 - prev.xdot0);
    }
    ForcedOrbit orb = shoot(mid, guess);
    // Not found: confirm by natural steps from lo (Newton can wander across
    // the map's discontinuity near the edge and converge elsewhere).
    for (int k = 1; k <= kConfirmSteps && !good(orb); ++k) {
      const double pk = lo.p + (mid - lo.p) * k / kConfirmSteps;
      orb = shoot(pk, k == 1 ? lo : guess);
      if (!good(orb)) break;
      guess = RowOf(orb, pk);
      if (k < kConfirmSteps) orb.status = ForcedOrbitStatus::kNoConvergence;
    }
    if (good(orb)) {
      prev = lo, have_prev = true;
      lo = RowOf(orb, mid);
    } else {
      hi = mid;
    }
  }
  *before = lo;
  ForcedOrbit orb = shoot(hi, lo);
  if (orb.status != ForcedOrbitStatus::kConverged || good(orb)) {
    // No orbit near: settle from the edge's orbit (200 periods) and shoot again.
    const ForcedModel model(At(base, axis, hi));
    ForcedRequest rq;
    rq.t_end = 200 * ref.m * model.period();
    rq.extremes = false;
    const ForcedRun tr = ForcedFlow(model, o.flow).Run(ForcedStart(model, 0, lo.x0, lo.xdot0), rq);
    if (tr.status == ForcedStatus::kReached)
      orb = ShootStroboscopic(model, tr.end.x, tr.end.xdot, ref.m, oo);
  }
  if (orb.status != ForcedOrbitStatus::kConverged || good(orb)) {
    *why = "no periodic orbit (m = " + std::to_string(ref.m) + ") found beyond " + Num(lo.p, 15) +
           ", where the orbit's stick structure ends";
    return false;
  }
  *after = RowOf(orb, hi);
  return true;
}

ForcedBranchRow EdgeWithoutOrbit(const ForcedParams& base, ForcedAxis axis,
                                 const ForcedBranchOptions& o, const ForcedBranchRow& before,
                                 double dir) {
  ForcedBranchRow beyond = before, point = before;
  beyond.p = before.p + dir * 10 * o.locate_tol * (1 + std::abs(before.p));
  // Classified from one period just beyond, where that is a valid model (A,
  // v >= 0) and the run ends well; else the edge stays unlabelled.
  const ForcedParams at = At(base, axis, beyond.p);
  if (ValidationError(at).empty()) {
    const ForcedModel model(at);
    ForcedRequest rq;
    rq.t_end = before.m * model.period();
    rq.extremes = false;
    const ForcedRun run =
        ForcedFlow(model, o.flow).Run(ForcedStart(model, 0, before.x0, before.xdot0), rq);
    beyond.sticks = run.sticks, beyond.crossings = run.crossings;
    if (run.status == ForcedStatus::kReached)
      ClassifySliding(base, axis, o, before, beyond, &point);
  }
  const Tolerances tol = Tolerances::From(o.flow.rtol, o.flow.atol);
  if (StickTouchToEdge(base, axis, o, before) <= tol.BandEdge()) {
    point.label = ForcedLabel::kAD;  // the slip that splits the stick is not short: a jump
    point.description =
        "adding-sliding: the stick force touches the band's edge inside a stick phase, "
        "which splits (mu(0+) < mu_s: the slip is not short, the map jumps)";
  }
  point.description += "; no periodic orbit of m = " + std::to_string(before.m) + " beyond";
  return point;
}

bool JumpAcross(const ForcedParams& base, ForcedAxis axis, const ForcedBranchOptions& o,
                const ForcedBranchRow& last, double dir, double step, double limit, double tol,
                ForcedBranchRow* before, ForcedBranchRow* after, std::string* why) {
  ForcedOrbitOptions oo;
  oo.flow = o.flow;
  auto clamp = [&](double p) { return dir > 0 ? std::min(p, limit) : std::max(p, limit); };
  ForcedBranchRow lo = last;
  double hi = clamp(last.p + dir * step);
  for (int k = 0;; ++k) {  // the first value past the edge
    const ForcedOrbit orb =
        ShootStroboscopic(ForcedModel(At(base, axis, hi)), lo.x0, lo.xdot0, last.m, oo);
    if (orb.status != ForcedOrbitStatus::kConverged || orb.sticks != last.sticks ||
        orb.crossings != last.crossings)
      break;
    lo = RowOf(orb, hi);
    if (k == 6 || hi == limit) {
      *why = "an orbit of the same stick structure goes on to " + Num(hi, 12);
      *after = lo;  // the farthest orbit found
      return false;
    }
    hi = clamp(hi + dir * step * (2 << k));
  }
  return BisectEdge(base, axis, o, lo, hi, tol, before, after, why);
}

}  // namespace stickslip::forced_detail
