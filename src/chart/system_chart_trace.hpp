// Private to src/chart/: the tracer's settings (chart_trace.hpp) for a
// system's chart (system_chart.hpp).
#pragma once

#include "chart/chart_trace.hpp"
#include "stickslip/chart/system_chart.hpp"

namespace stickslip {

/// The rectangle, step, corrector tolerance and cancellation of `o`; the
/// plane's coordinates at u[i1], u[i1 + 1].
TraceOptions TraceFor(const SystemChartOptions& o, int i1);

}  // namespace stickslip
