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
/// rest point's), mult<k>_re and mult<k>_im (the Floquet multipliers, the
/// largest modulus first: one per tangent component with a clock, one fewer
/// on an autonomous system's surface section; HB: 0), mult_max (the
/// largest |multiplier|; HB: 0) and test (the curve's test function there). A
/// comment line per curve: its kind (GR: its margin), m, points, seed and ends.
TsvTable SystemCurvesTable(const System& s, const SystemChart& c);
/// codim2.tsv: label (SL, LPPD, R1, R2, CP, GG), <p1>, <p2>, curve (its id),
/// on (its kind), description, located (Codim2Method: end, refined, chord,
/// point).
TsvTable SystemCodim2Table(const System& s, const SystemChart& c);
/// chart.gp, on a 1000 x 860 page: the curves from curves.tsv (HB orange, GR red,
/// LP black, PD black dashed, NS magenta; with a clock, those of m >= 2
/// forcing periods thinner, with their own dashes) and codim2.tsv's points (SL open circles, the others
/// filled dots, each named by a label placed where it keeps most room from the
/// curves, the points and the other labels) in the rectangle; with a grid of
/// cells, over response.tsv's cells filled by response class (ResponseRaster,
/// response_report.hpp). Axes read "forcing frequency Ω" for the belt's and
/// forcing's parameters, else the parameter's name.
std::string SystemChartScript(const System& s, const SystemChart& c, const std::string& title,
                              FigureFormat format, const ResponseGrid* grid = nullptr);

}  // namespace stickslip
