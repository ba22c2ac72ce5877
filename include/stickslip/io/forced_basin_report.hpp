// Forced basins as files (issue 21 item 4): the starts and the attractors as
// TSV tables (docs/formats.md) and the basin figure as a gnuplot script.
#pragma once

#include <string>

#include "stickslip/basin/forced_basin.hpp"
#include "stickslip/io/figure_style.hpp"
#include "stickslip/io/report.hpp"

namespace stickslip {

/// One row per start done: x, xdot, attractor (index into the attractor
/// table), kind, m, sticks, lyapunov (of that start's run). Failed starts are
/// `# failed:` lines as well.
TsvTable ForcedBasinTable(const ForcedBasins& b);
/// One row per attractor: attractor, kind, m, sticks, x, xdot (a section point
/// of it), lyapunov, starts, fraction (of the starts done).
TsvTable AttractorTable(const ForcedBasins& b);
/// A one-line name: "period 2, 1 stick", "chaotic, ~2 sticks/period", "rest", ...
std::string AttractorLabel(const Attractor& a);

/// Draws basins_forced.<ext> from basins_forced.tsv and attractors.tsv: each
/// start a cell coloured by its attractor, the attractors' section points on top.
std::string ForcedBasinScript(const ForcedBasins& b, const ForcedBasinOptions& o,
                              const std::string& title, FigureFormat format);

}  // namespace stickslip
