// The forced chart (stickslip/chart/forced_chart.hpp): the one chart's
// curves of ForcedModel (ChartSystem), then the response grid.
#include "stickslip/chart/forced_chart.hpp"

#include <chrono>

#include "stickslip/errors.hpp"

namespace stickslip {

SystemChartOptions SystemOptions(const ForcedModel& model, const ForcedChartOptions& o) {
  SystemChartOptions so;
  const Plane& pl = o.plane;
  so.plane.p1 = model.ParameterIndex(pl.p1.name());
  so.plane.p2 = model.ParameterIndex(pl.p2.name());
  so.plane.from1 = pl.from1, so.plane.to1 = pl.to1;
  so.plane.from2 = pl.from2, so.plane.to2 = pl.to2;
  so.branch = OrbitBranchOptions(o.flow);  // every map on the chart's flow, its step cap too
  so.branch.max_amplitude = o.max_amplitude;
  so.max_m = o.max_m, so.seed_lines = o.seed_lines, so.max_step = o.max_step;
  so.cancelled = o.cancelled;
  return so;
}

ResponseOptions ResponseOptionsOf(const ForcedChartOptions& o) {
  ResponseOptions ro;
  ro.n1 = o.n1, ro.n2 = o.n2;
  AttractorOptions& a = ro.attractor;
  a.iterate = o.iterate, a.iterate.flow = o.flow, a.max_period = o.max_period;
  a.max_amplitude = o.max_amplitude, a.threads = o.threads;
  ro.cancelled = o.cancelled;
  return ro;
}

ForcedChartResult ForcedChart(const ForcedParams& base, const ForcedChartOptions& o) {
  const std::string e = o.ValidationError(base);
  if (!e.empty()) throw InvalidArgument(e);
  ForcedChartResult r;
  auto cancelled = [&o] { return o.cancelled && o.cancelled(); };
  // base's values of the two axes are not used (the chart sets them).
  const ForcedModel model(o.plane.At(base, o.plane.from1, o.plane.from2));
  if (o.curves) {
    r.chart = ChartSystem(model, SystemOptions(model, o));
  } else {
    r.chart.plane = SystemOptions(model, o).plane;
  }
  r.status = r.chart.status, r.message = r.chart.message;
  r.seconds = r.chart.seconds;
  if (o.n1 > 0 && !cancelled()) {
    r.grid = Responses(model, SystemOptions(model, o).plane, ResponseOptionsOf(o));
    r.grid_seconds = r.grid.seconds;
    if (r.grid.failed > 0) {
      r.message = r.status == ChartStatus::kOk ? r.grid.failure : r.message + "; " + r.grid.failure;
      r.status = ChartStatus::kPartial;
    }
  }
  if (cancelled()) r.status = ChartStatus::kCancelled, r.message = "cancelled";
  return r;
}

}  // namespace stickslip
