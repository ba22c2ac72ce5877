// The forced chart's tables (stickslip/io/forced_chart_report.hpp).
#include "stickslip/io/forced_chart_report.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <sstream>
#include <tuple>

namespace stickslip {

namespace {

void Header(TsvTable& t, const ForcedChartResult& r, const std::string& model) {
  t.AddComment("model: forced oscillator, " + model);
  if (r.status == ChartStatus::kOk)
    t.AddComment("status: complete");
  else if (r.status == ChartStatus::kCancelled)
    t.AddComment("status: cut short (cancelled: a signal or --max_time)");
  else
    t.AddComment(std::string("status: partial (") + Name(r.status) + "): " + r.message);
}

// Periodic responses of m >= kManyPeriods share one class (the grid's m and
// sticks columns keep them apart).
constexpr int kManyPeriods = 5;

std::string PeriodicName(int m, int sticks) {
  if (m >= kManyPeriods) return "m >= " + std::to_string(kManyPeriods);
  return "m = " + std::to_string(m) + ", " +
         (sticks == 0 ? std::string("no stick")
                      : std::to_string(sticks) + (sticks == 1 ? " stick" : " sticks"));
}

// A failed or unbounded cell's exponent is no number: "-".
TsvTable::Cell Number(double x) { return std::isfinite(x) ? TsvTable::Cell(x) : "-"; }

std::string KindName(AttractorKind k) {
  return k == AttractorKind::kUndecided ? "quasi-periodic" : Name(k);
}

}  // namespace

ResponseClasses ClassifyResponses(const ResponseGrid& g) {
  ResponseClasses c;
  std::vector<std::pair<int, int>> periodic;
  std::vector<AttractorKind> others;
  for (size_t k = 0; k < g.cells.size(); ++k) {
    if (!g.done[k]) continue;
    const Attractor& a = g.cells[k];
    if (a.kind == AttractorKind::kPeriodic)
      periodic.emplace_back(std::min(a.m, kManyPeriods), a.m >= kManyPeriods ? 0 : a.sticks);
    else
      others.push_back(a.kind);
  }
  std::sort(periodic.begin(), periodic.end());
  periodic.erase(std::unique(periodic.begin(), periodic.end()), periodic.end());
  for (const auto& [m, s] : periodic) {
    c.names.push_back(PeriodicName(m, s));
    c.kinds.push_back(AttractorKind::kPeriodic);
  }
  for (AttractorKind k : {AttractorKind::kRest, AttractorKind::kUndecided, AttractorKind::kChaotic,
                          AttractorKind::kUnbounded, AttractorKind::kFailed})
    if (std::find(others.begin(), others.end(), k) != others.end()) {
      c.names.push_back(KindName(k));
      c.kinds.push_back(k);
    }
  c.class_of.assign(g.cells.size(), -1);
  for (size_t k = 0; k < g.cells.size(); ++k) {
    if (!g.done[k]) continue;
    const Attractor& a = g.cells[k];
    const std::string name =
        a.kind == AttractorKind::kPeriodic ? PeriodicName(a.m, a.sticks) : KindName(a.kind);
    c.class_of[k] =
        static_cast<int>(std::find(c.names.begin(), c.names.end(), name) - c.names.begin());
  }
  return c;
}

TsvTable ForcedCurvesTable(const ForcedChartResult& r, const Plane& pl, const std::string& model) {
  TsvTable t({pl.p1.name(), pl.p2.name(), "curve", "id", "m", "phase", "x0", "xdot0", "sticks",
              "crossings", "x_min", "x_max", "mult1_re", "mult1_im", "mult2_re", "mult2_im",
              "flag"});
  Header(t, r, model);
  const std::vector<SystemCurve>& curves = r.chart.curves;
  t.AddComment("seed runs: " + std::to_string(r.chart.seed_runs) + " one-parameter runs");
  for (size_t i = 0; i < curves.size(); ++i) {
    const SystemCurve& c = curves[i];
    t.AddComment("curve " + std::to_string(i + 1) + " " + Name(c.kind) + " m = " +
                 std::to_string(c.section.turns) + ": " + std::to_string(c.points.size()) +
                 " points, from " + c.seed + ", ends " + c.ends.Text());
  }
  for (size_t i = 0; i < curves.size(); ++i) {
    const SystemCurve& c = curves[i];
    // GR: 1 where the margin is an arrival's (a crossing reaches the band's edge).
    const int flag = c.kind == CurveKind::kGrazing && !c.gap ? 1 : 0;
    for (const SystemCurvePoint& p : c.points) {
      const OrbitRow& o = p.orbit;
      std::complex<double> mu[2];
      for (int k = 0; k < 2 && k < static_cast<int>(o.multipliers.size()); ++k)
        mu[k] = o.multipliers[k];
      t.AddRow({p.p1, p.p2, Name(c.kind), static_cast<int>(i + 1), c.section.turns, o.start.z[2],
                o.start.z[0], o.start.z[1], o.sticks, o.crossings, o.lo[0], o.hi[0], mu[0].real(),
                mu[0].imag(), mu[1].real(), mu[1].imag(), flag});
    }
  }
  return t;
}

TsvTable ForcedCodim2Table(const ForcedChartResult& r, const Plane& pl, const std::string& model) {
  TsvTable t({"label", pl.p1.name(), pl.p2.name(), "curve", "on", "description", "located"});
  Header(t, r, model);
  t.AddComment(
      "located: refined (the test function's root on the corrected curve), chord (linear "
      "between two curve points: the refinement failed), end (SL: the curve's end; GG: the "
      "middle of two curve ends that meet), point (CP: the curve point where it turns back)");
  for (const SystemCodim2& p : r.chart.codim2)
    t.AddRow({Name(p.label), p.p1, p.p2, p.curve + 1, Name(p.on), p.description, Name(p.method)});
  return t;
}

TsvTable ResponseTable(const ForcedChartResult& r, const Plane& pl, const std::string& model) {
  const ResponseGrid& g = r.grid;
  const ResponseClasses c = ClassifyResponses(g);
  TsvTable t(
      {pl.p1.name(), pl.p2.name(), "class", "response", "m", "sticks", "lyapunov", "lyapunov_err"});
  Header(t, r, model);
  t.AddComment("grid " + std::to_string(g.n1) + " x " + std::to_string(g.n2) +
               " cell centres, each row swept along " + pl.p1.name() +
               " from the previous cell's end state; " + std::to_string(g.failed) + " failed");
  for (size_t i = 0; i < c.names.size(); ++i)
    t.AddComment("class " + std::to_string(i) + ": " + c.names[i]);
  for (size_t k = 0; k < g.cells.size(); ++k) {
    if (!g.done[k]) continue;
    const Attractor& a = g.cells[k];
    const bool periodic = a.kind == AttractorKind::kPeriodic;
    t.AddRow({g.x1[k % g.n1], g.x2[k / g.n1], c.class_of[k], KindName(a.kind), periodic ? a.m : 0,
              a.sticks, Number(a.lyapunov), Number(g.lyapunov_err[k])});
  }
  return t;
}

}  // namespace stickslip
