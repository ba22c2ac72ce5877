// A response grid as files (chart/response_grid.hpp; docs/formats.md,
// "response.tsv"): its cells as a TSV table and, for a chart's gnuplot
// script, its classes' fills and the raster's plot clause. The library
// writes text only.
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "stickslip/chart/response_grid.hpp"
#include "stickslip/io/report.hpp"

namespace stickslip {

/// The response classes of a grid, in a fixed order: periodic (m, sticks)
/// by m then sticks (m >= 5 one class), then rest, quasi-periodic, chaotic, unbounded,
/// contact-lost, failed (only those present). class_of[k] indexes names for cell k (-1: not done).
struct ResponseClasses {
  std::vector<std::string> names;  ///< "m = 1, 1 stick", "chaotic", ...
  std::vector<AttractorKind> kinds;
  std::vector<int> class_of;
};
ResponseClasses ClassifyResponses(const ResponseGrid& g);

/// response.tsv: one row per grid cell, p1 fastest: <p1>, <p2> (the cell
/// centre), class (index into the comment lines' list), response (periodic,
/// rest, quasi-periodic, chaotic, unbounded, contact-lost, failed), m,
/// sticks (per m periods), lyapunov, lyapunov_err ("-" where not measured). Cells not reached (cancelled) are left
/// out. A comment names the grid and its classes.
TsvTable ResponseGridTable(const ResponseGrid& g, const std::string& p1, const std::string& p2);

/// The fill of class `cls`: a hue per m (1 blue, 2 green, 3 orange, 4
/// purple, 5+ ochre), darker for fewer sticks; rest white, quasi-periodic
/// light grey, chaotic dark grey, unbounded pink, contact-lost yellow,
/// failed red ("#rrggbb").
std::string ResponseFill(const ResponseClasses& c, int cls);

/// gnuplot: `array C[...] = [...]`, the classes' fills (one line).
void ResponsePalette(std::ostream& os, const ResponseClasses& c);
/// gnuplot: the plot clause that fills response.tsv's cells of a rectangle
/// width1 x width2 wide, then a key entry per class, each after ", \".
void ResponseRaster(std::ostream& os, const ResponseGrid& g, const ResponseClasses& c,
                    double width1, double width2);

}  // namespace stickslip
