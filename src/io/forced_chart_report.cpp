// The forced chart's tables (stickslip/io/forced_chart_report.hpp).
#include "stickslip/io/forced_chart_report.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <sstream>
#include <tuple>

namespace stickslip {

namespace {

// The model and status lines, before the table's own comments.
void Header(TsvTable& t, const ForcedChartResult& r, const std::string& model) {
  std::string status = "complete";
  if (r.status == ChartStatus::kCancelled)
    status = "cut short (cancelled: a signal or --max_time)";
  else if (r.status != ChartStatus::kOk)
    status = std::string("partial (") + Name(r.status) + "): " + r.message;
  t.PrependMeta({{"model", "forced oscillator, " + model}, {"status", status}});
}

}  // namespace

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
  TsvTable t = ResponseGridTable(r.grid, pl.p1.name(), pl.p2.name());
  Header(t, r, model);
  return t;
}

}  // namespace stickslip
