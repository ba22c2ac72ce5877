// ChartSystem (stickslip/chart/system_chart.hpp): the seed lines, each
// seed's curve unless one of its kind passes there, and the codimension-two
// points along the curves.
#include <chrono>
#include <cmath>

#include "chart/chart_trace.hpp"
#include "chart/system_chart_seeds.hpp"
#include "numerics/numbers.hpp"
#include "numerics/tolerances.hpp"
#include "stickslip/chart/system_chart.hpp"
#include "stickslip/errors.hpp"

namespace stickslip {

namespace {

// Curves are told apart by kind and, with a clock, by their forcing periods
// m (section turns; 0 without a clock). Without a clock an orbit's returns to
// its section depend on the section (which contact's exit cuts it), so only
// the curves' places tell a doubled orbit's curve from its parent's.

// Whether seed s lies on a curve of its kind and turns already traced.
bool NearSystemCurve(const std::vector<SystemCurve>& curves, const SystemSeed& s,
                     const SystemPlane& pl) {
  const Eigen::Vector2d scale(pl.to1 - pl.from1, pl.to2 - pl.from2);
  for (const SystemCurve& c : curves)
    if (c.kind == s.kind && c.section.turns == s.section.turns &&
        NearPolyline(c.points, Eigen::Vector2d(s.p1, s.p2), scale, Tolerances().chart_same_curve))
      return true;
  return false;
}

// Whether most of curve c's points lie on a curve of its kind and turns
// already traced (a seed off its curve that corrected onto one drawn).
bool Duplicate(const std::vector<SystemCurve>& curves, const SystemCurve& c,
               const SystemPlane& pl) {
  const Eigen::Vector2d scale(pl.to1 - pl.from1, pl.to2 - pl.from2);
  for (const SystemCurve& d : curves) {
    if (d.kind != c.kind || d.section.turns != c.section.turns) continue;
    std::size_t on = 0;
    for (const SystemCurvePoint& p : c.points)
      on += NearPolyline(d.points, Eigen::Vector2d(p.p1, p.p2), scale,
                         Tolerances().chart_same_curve);
    if (2 * on > c.points.size()) return true;
  }
  return false;
}

// A way cut short by the continuation. (A branch jump is an end: the next
// point, also at half the step, lies off the curve, at a corner of it or on
// another curve.)
bool Cut(const CurveEnd& e) {
  return e.kind == CurveEndKind::kMaxPoints || e.kind == CurveEndKind::kStepTooSmall ||
         e.kind == CurveEndKind::kStartFailed || e.kind == CurveEndKind::kNoStart;
}

// GG: two GR gap curves of one period (clock turns) whose inner ends meet.
// Each end of a gap curve traced by Newton stops there (a corner of the gap:
// the larger of two touches), so the two ends straddle it. Both ends, where
// the tracer stopped or was cut, become corners (CurveEndKind::kCorner).
void FindDoubleGrazing(std::vector<SystemCurve>& curves, const SystemPlane& pl,
                       std::vector<SystemCodim2>* out) {
  const double tol = Tolerances().chart_double_grazing;
  auto inner = [](const SystemCurve& c, bool first) {
    const CurveEndKind k = (first ? c.ends.first : c.ends.last).kind;
    return !c.points.empty() &&
           (k == CurveEndKind::kStopped || k == CurveEndKind::kBranchJump || Cut({k, ""}));
  };
  for (std::size_t i = 0; i < curves.size(); ++i)
    for (std::size_t j = i + 1; j < curves.size(); ++j) {
      SystemCurve &a = curves[i], &b = curves[j];
      if (a.kind != CurveKind::kGrazing || b.kind != CurveKind::kGrazing || !a.gap || !b.gap ||
          a.section.turns != b.section.turns)
        continue;
      bool met = false;  // one GG per pair of curves
      for (const bool fa : {true, false})
        for (const bool fb : {true, false}) {
          if (met || !inner(a, fa) || !inner(b, fb)) continue;
          const SystemCurvePoint &p = fa ? a.points.front() : a.points.back(),
                                 &q = fb ? b.points.front() : b.points.back();
          if (std::hypot((p.p1 - q.p1) / (pl.to1 - pl.from1), (p.p2 - q.p2) / (pl.to2 - pl.from2)) >
              tol)
            continue;
          SystemCodim2 x =
              SystemCodim2::At(Codim2Label::kDoubleGrazing, CurveKind::kGrazing, (p.p1 + q.p1) / 2,
                               (p.p2 + q.p2) / 2, Codim2Method::kCurveEnd);
          x.curve = static_cast<int>(i);
          x.description = "GR curves " + std::to_string(i + 1) + " and " + std::to_string(j + 1) +
                          " meet: two touches of a surface at once (double grazing)";
          out->push_back(x);
          for (CurveEnd* e : {fa ? &a.ends.first : &a.ends.last, fb ? &b.ends.first : &b.ends.last})
            e->kind = CurveEndKind::kCorner;
          met = true;
        }
    }
}

}  // namespace

SystemChart ChartSystem(const System& system, const SystemChartOptions& o) {
  if (const std::string e = o.ValidationError(system); !e.empty()) throw InvalidArgument(e);
  const auto t0 = std::chrono::steady_clock::now();
  SystemChart r;
  r.plane = o.plane;
  SeedRuns runs;
  std::string cut;  // the first cut curve
  auto cancelled = [&o] { return o.cancelled && o.cancelled(); };
  const SystemPlane& pl = o.plane;
  for (int line = 0; line < o.seed_lines && !cancelled(); ++line) {
    const double f = (line + 0.5) / o.seed_lines;
    for (const bool along1 : {true, false}) {
      const double c =
          along1 ? pl.from2 + f * (pl.to2 - pl.from2) : pl.from1 + f * (pl.to1 - pl.from1);
      for (const SystemSeed& s : SystemSeedsOnLine(system, o, along1, c, &runs)) {
        if (cancelled() || NearSystemCurve(r.curves, s, pl)) continue;
        SystemCurve curve =
            s.kind == CurveKind::kHopf
                ? TraceHopfCurve(system, o, s.p1, s.p2, s.fixed)
                : TraceOrbitCurve(system, o, s.kind, s.start, s.p1, s.p2, s.section, s.fixed);
        curve.seed = s.where;
        const auto failed = [](const CurveEnd& e) {
          return e.kind == CurveEndKind::kStartFailed || e.kind == CurveEndKind::kNoStart;
        };
        if (curve.points.size() < 2 || (failed(curve.ends.first) && failed(curve.ends.last))) {
          ++r.seeds_not_traced;
          continue;
        }
        if (Duplicate(r.curves, curve, pl)) {
          ++r.duplicates;
          continue;
        }
        for (SystemCodim2& x : curve.codim2) {
          x.curve = static_cast<int>(r.curves.size());
          r.codim2.push_back(x);
        }
        r.curves.push_back(std::move(curve));
      }
    }
  }
  FindDoubleGrazing(r.curves, pl, &r.codim2);
  for (const SystemCurve& curve : r.curves)
    if ((Cut(curve.ends.first) || Cut(curve.ends.last)) && r.cut_curves++ == 0)
      cut = std::string(CurveLabel(curve.kind)) + " curve from " + curve.seed +
            " cut short: " + curve.ends.Text();
  r.seed_runs = runs.runs, r.failed_seed_runs = runs.failed;
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (cancelled()) {
    r.status = ChartStatus::kCancelled, r.message = "cancelled";
  } else if (runs.failed > 0 || r.cut_curves > 0) {
    r.status = ChartStatus::kPartial;
    r.message = runs.failed > 0
                    ? std::to_string(runs.failed) + " seed runs failed, the first " + runs.failure
                    : std::to_string(r.cut_curves) + " curves cut short, the first " + cut;
  }
  return r;
}

}  // namespace stickslip
