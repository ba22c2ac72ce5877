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

/// What the tables and figure call the swept parameter and the section.
struct DiagramLabels {
  std::string param;                        ///< the swept parameter's column name
  std::string param_label;                  ///< its axis label
  std::string section = "forcing phase 0";  ///< "x1 at x1' = 0 falling", ...
};

/// One row per kept section point of each value whose run is done. Columns:
/// direction, <param>, period (1..K: the return), the state's components but
/// the phase (x, xdot; x1, x1dot, x2, ...), stuck (contact 0 sticks at the
/// section; with k contacts stuck1..stuckk), sticks, exits, exit_phase (the
/// phase of the return's first stick exit in [0, 2 pi), -1 if none or no
/// forcing), lyapunov, lyapunov_err. Failed values are `# failed:` lines.
TsvTable OrbitDiagramTable(const System& s, const OrbitDiagram& d, const DiagramLabels& l);
/// One row per value whose run is done: direction, <param>, lyapunov,
/// lyapunov_err, sticks_per_period, collapses, <first component>_min and _max
/// (of the section points: x_min, x_max).
TsvTable ExponentTable(const System& s, const OrbitDiagram& d, const DiagramLabels& l);

/// Draws orbit_diagram.<ext> from orbit_diagram.tsv and lyapunov.tsv: the
/// section points of the first component (up sweep blue, down sweep
/// vermillion) over the exponent panel (zero line dotted).
std::string OrbitDiagramScript(const System& s, FigureFormat format, const DiagramLabels& l,
                               const std::string& title, bool up, bool down);

}  // namespace stickslip
