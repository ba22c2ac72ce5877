// ChartSystem (stickslip/chart/system_chart.hpp): the seed lines, each
// seed's curve unless one of its kind passes there, and the codimension-two
// points along the curves.
#include <chrono>

#include "chart/chart_trace.hpp"
#include "chart/system_chart_seeds.hpp"
#include "numerics/numbers.hpp"
#include "numerics/tolerances.hpp"
#include "stickslip/chart/system_chart.hpp"
#include "stickslip/errors.hpp"

namespace stickslip {

namespace {

bool NearSystemCurve(const std::vector<SystemCurve>& curves, const SystemSeed& s,
                     const SystemPlane& pl) {
  const Eigen::Vector2d scale(pl.to1 - pl.from1, pl.to2 - pl.from2);
  for (const SystemCurve& c : curves)
    if (c.kind == s.kind &&
        NearPolyline(c.points, Eigen::Vector2d(s.p1, s.p2), scale, Tolerances().forced_same_curve))
      return true;
  return false;
}

bool Cut(const CurveEnd& e) {
  return e.kind == CurveEndKind::kMaxPoints || e.kind == CurveEndKind::kStepTooSmall ||
         e.kind == CurveEndKind::kStartFailed || e.kind == CurveEndKind::kNoStart ||
         e.kind == CurveEndKind::kBranchJump;
}

// SL at an end where the switching sequence changes; LPPD, R1 and R2 where
// another test changes sign between two points (placed on the chord).
void FindCodim2(const System& s, const SystemPlane& pl, const SystemCurve& c, int index,
                std::vector<SystemCodim2>* out) {
  if (c.kind == CurveKind::kHopf || c.points.empty()) return;
  auto add = [&](Codim2Label label, double p1, double p2, const std::string& what) {
    out->push_back({label, c.kind, index, p1, p2, what});
  };
  const CurveEnd* ends[2] = {&c.ends.first, &c.ends.last};
  for (int k = 0; k < 2; ++k)
    if (ends[k]->kind == CurveEndKind::kSliding) {
      const SystemCurvePoint& p = k == 0 ? c.points.front() : c.points.back();
      add(Codim2Label::kSliding, p.p1, p.p2,
          std::string(CurveLabel(c.kind)) + " curve ends: " + ends[k]->why);
    }
  // CP: an LP curve's direction in the (scaled) plane reverses at a point.
  const double w1 = pl.to1 - pl.from1, w2 = pl.to2 - pl.from2;
  for (std::size_t i = 1; c.kind == CurveKind::kFold && i + 1 < c.points.size(); ++i) {
    const SystemCurvePoint &a = c.points[i - 1], &b = c.points[i], &d = c.points[i + 1];
    const double dot =
        (b.p1 - a.p1) * (d.p1 - b.p1) / (w1 * w1) + (b.p2 - a.p2) * (d.p2 - b.p2) / (w2 * w2);
    if (dot < 0)
      add(Codim2Label::kCusp, b.p1, b.p2,
          "cusp: two folds merge (the LP curve turns back at this point of it)");
  }
  // (other test, label): on LP the PD test (LPPD); on PD the LP test (LPPD);
  // on NS the LP test (R1) and the PD test (R2).
  std::vector<std::pair<int, Codim2Label>> watch;
  if (c.kind == CurveKind::kFold) watch = {{1, Codim2Label::kFoldFlip}};
  if (c.kind == CurveKind::kPeriodDoubling) watch = {{0, Codim2Label::kFoldFlip}};
  if (c.kind == CurveKind::kTorus) watch = {{0, Codim2Label::kR1}, {1, Codim2Label::kR2}};
  for (const auto& [k, label] : watch)
    for (std::size_t i = 1; i < c.points.size(); ++i) {
      const SystemCurvePoint &a = c.points[i - 1], &b = c.points[i];
      if ((a.tests[k] > 0) == (b.tests[k] > 0)) continue;
      const double f = a.tests[k] / (a.tests[k] - b.tests[k]);
      add(label, a.p1 + f * (b.p1 - a.p1), a.p2 + f * (b.p2 - a.p2),
          std::string(k == 0 ? "LP" : "PD") + " test changes sign on the " + CurveLabel(c.kind) +
              " curve between " + s.ParameterName(pl.p1) + " = " + Num(a.p1, 8) + " and " +
              Num(b.p1, 8) + " (chord)");
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
        if (Cut(curve.ends.first) || Cut(curve.ends.last)) {
          if (r.cut_curves++ == 0)
            cut = std::string(CurveLabel(curve.kind)) + " curve from " + curve.seed +
                  " cut short: " + curve.ends.Text();
        }
        FindCodim2(system, pl, curve, static_cast<int>(r.curves.size()), &r.codim2);
        r.curves.push_back(std::move(curve));
      }
    }
  }
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
