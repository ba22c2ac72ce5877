// A system's chart as files (ss_chart --system; docs/formats.md, "A
// system's chart"): its curves and codimension-two points as TSV tables and
// the (p1, p2) plane as a gnuplot script. Columns are named from the system
// (its parameters and state names). The library writes text only.
#pragma once

#include <string>

#include "stickslip/chart/response_grid.hpp"
#include "stickslip/chart/system_chart.hpp"
#include "stickslip/io/figure_style.hpp"
#include "stickslip/io/report.hpp"

namespace stickslip {

/// curves.tsv: <p1>, <p2>, curve (HB, LP, PD, NS, GR), id (1-based), m (the
/// orbit's period in forcing periods, or in returns to its section:
/// PeriodMultiple; HB: 0), period, sticks, crossings, <z>_0 per state
/// component (the orbit's section point, a clock's phase included; HB: the
/// rest point), then <z>_min and <z>_max per tangent component (HB: both the
/// rest point's), mult_max (the largest |multiplier|; HB: 0) and test (the
/// curve's test function there). A comment line per curve: its kind (GR: its
/// margin), seed and ends.
TsvTable SystemCurvesTable(const System& s, const SystemChart& c);
/// codim2.tsv: label (SL, LPPD, R1, R2, CP, GG), <p1>, <p2>, curve (its id),
/// on (its kind), description, located (Codim2Method: end, refined, chord,
/// point).
TsvTable SystemCodim2Table(const System& s, const SystemChart& c);
/// chart.gp: the curves from curves.tsv (HB red, LP black, PD black dashed,
/// NS magenta, GR blue) and codim2.tsv's points (SL open circles, the others filled)
/// in the rectangle; with a grid of cells, over response.tsv's cells filled
/// by response class (ResponseRaster, response_report.hpp).
std::string SystemChartScript(const System& s, const SystemChart& c, const std::string& title,
                              FigureFormat format, const ResponseGrid* grid = nullptr);

}  // namespace stickslip
