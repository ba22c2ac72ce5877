// The forced chart as files (issue 21 item 3): the curves, the
// codimension-two points and the response grid as TSV tables
// (docs/formats.md), and the (p1, p2) map as a gnuplot script: the grid's
// cells filled by response type (a raster), the LP, PD, NS and GR curves and
// the codimension-two points drawn over it. The library writes text only.
#pragma once

#include <string>
#include <vector>

#include "stickslip/chart/forced_chart.hpp"
#include "stickslip/io/figure_style.hpp"
#include "stickslip/io/report.hpp"
#include "stickslip/io/response_report.hpp"

namespace stickslip {

/// Columns: <p1>, <p2>, curve (LP, PD, NS, GR), id (1-based), m, phase (the
/// section's forcing phase Omega t of x0, xdot0), x0, xdot0,
/// sticks, crossings, x_min, x_max, mult1_re, mult1_im, mult2_re, mult2_im,
/// flag (NS: 1 a neutral saddle, real multipliers; GR: 1 the crossing margin,
/// 0 the grazing one). A comment line per curve: its seed and its ends.
TsvTable ForcedCurvesTable(const ForcedChartResult& r, const Plane& pl, const std::string& model);
/// Columns: label (R1, R2, LPPD, SL), <p1>, <p2>, curve (its id), on (its kind), description.
TsvTable ForcedCodim2Table(const ForcedChartResult& r, const Plane& pl, const std::string& model);
/// response.tsv (ResponseGridTable, response_report.hpp) with the model and status.
TsvTable ResponseTable(const ForcedChartResult& r, const Plane& pl, const std::string& model);

/// Draws forced_chart.<ext> from response.tsv, curves.tsv and codim2.tsv.
std::string ForcedChartScript(const ForcedChartResult& r, const Plane& pl, const std::string& title,
                              FigureFormat format);

}  // namespace stickslip
