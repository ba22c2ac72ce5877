// Basins on a section as files (issue 21 item 4, issue 31 item 6): the starts
// and the attractors as TSV tables (docs/formats.md) and the basin figure as
// a gnuplot script. Columns are named from the system's states (x' -> xdot).
#pragma once

#include <string>

#include "stickslip/basin/attractors.hpp"
#include "stickslip/io/figure_style.hpp"
#include "stickslip/io/report.hpp"

namespace stickslip {

/// One row per start done: the slice's two components, attractor (index into
/// the attractor table), kind, m, sticks, lyapunov (of that start's run).
/// Failed starts are `# failed:` lines as well.
TsvTable AttractorStartTable(const System& s, const AttractorBasins& b, const StartSlice& slice);
/// One row per attractor: attractor, kind, m, sticks, the tangent block's
/// components (a section point of it), lyapunov, starts, fraction (of the
/// starts done), label, sticks_per_period.
TsvTable AttractorTable(const System& s, const AttractorBasins& b);
/// A one-line name: "period 2, 1 stick", "chaotic, 0.66 sticks/period", "rest", ...
std::string AttractorLabel(const Attractor& a);

/// What the basin figure says of its section and which files it reads.
struct AttractorFigure {
  std::string stem = "basins_forced";  ///< <stem>.tsv drawn as <stem>.<ext>
  std::string xlabel = "displacement x at forcing phase 0 (dimensionless)";
  std::string ylabel = "velocity x' at forcing phase 0 (dimensionless)";
  std::string comment = "Basins on the stroboscopic section (forcing phase 0) of ss_basin --force.";
};

/// Draws <stem>.<ext> from <stem>.tsv: each start a cell coloured by its
/// attractor, the attractors' section points on top.
std::string AttractorScript(const System& s, const AttractorBasins& b, const StartSlice& slice,
                            const AttractorFigure& figure, const std::string& title,
                            FigureFormat format);

}  // namespace stickslip
