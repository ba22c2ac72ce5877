// The orbit diagram as files (issue 21 item 1): the section points and the
// exponents as TSV tables (docs/formats.md), and the classic figure (section
// points against the parameter, the exponent panel below) as a gnuplot script.
// The library writes text only; the apps run gnuplot.
#pragma once

#include <string>

#include "stickslip/chaos/orbit_diagram.hpp"
#include "stickslip/io/figure_style.hpp"
#include "stickslip/io/report.hpp"

namespace stickslip {

/// One row per kept section point of each value whose run is done. Columns:
/// direction, <axis>, period (1..K), x, xdot, stuck, sticks, exits, exit_phase
/// (Omega t of the period's first stick exit in [0, 2 pi), -1 if none),
/// lyapunov, lyapunov_err. Failed values are `# failed:` comment lines.
TsvTable OrbitDiagramTable(const OrbitDiagram& d, ParameterAxis axis);
/// One row per value whose run is done: direction, <axis>, lyapunov,
/// lyapunov_err, sticks_per_period, collapses, x_min, x_max (of the section points).
TsvTable ExponentTable(const OrbitDiagram& d, ParameterAxis axis);

/// Draws orbit_diagram.<ext> from orbit_diagram.tsv and lyapunov.tsv: the
/// section points x (up sweep blue, down sweep vermillion) over the exponent
/// panel (zero line dotted).
std::string OrbitDiagramScript(FigureFormat format, ParameterAxis axis, const std::string& title,
                               bool up, bool down);

}  // namespace stickslip
