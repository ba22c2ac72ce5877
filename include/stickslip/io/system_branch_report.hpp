// The files of a system's one-parameter run (ss_continue --system;
// docs/formats.md, "A system's branch.tsv"): steady sliding (branch 0,
// steady_branch.hpp) and the pieces of its orbit branch (1, 2, ...;
// orbit_branch.hpp) as branch.tsv and special_points.tsv, and the gnuplot
// script of the bifurcation figure. Columns are named from the system's
// state names ("x'" -> "xdot") and its parameter.
#pragma once

#include <string>
#include <vector>

#include "stickslip/continuation/orbit_branch.hpp"
#include "stickslip/equilibria/steady_branch.hpp"
#include "stickslip/io/figure_style.hpp"
#include "stickslip/io/report.hpp"

namespace stickslip {

/// What one run computed: steady sliding and the orbit branch's pieces.
struct SystemRun {
  int parameter = 0;
  SteadyBranch steady;
  std::vector<OrbitBranch> pieces;  ///< toward to, then back toward from
  std::vector<int> numbers;         ///< each piece's branch number (default 1, 2, ...)
  /// Intervals of the parameter not traced (an unbounded resonance between
  /// two pieces), as pairs of ends; the figure shades them.
  std::vector<double> gap;
};

/// A column name for state component i: StateName with ' as "dot".
std::string StateColumn(const System& s, int i);
/// The tangent component `name` names (its StateName or StateColumn); -1 if none.
int StateIndex(const System& s, const std::string& name);
/// The tangent components' names, ", "-separated (for messages).
std::string StateNameList(const System& s);

/// branch.tsv: one row per point, steady sliding first.
TsvTable SystemBranchTable(const System& s, const SystemRun& run);
/// special_points.tsv: the located points with their row (pt) and label (lab).
TsvTable SystemSpecialTable(const System& s, const SystemRun& run);
/// bifurcation.gp, drawing the first displacement's extremes, the period and
/// the largest multiplier (|mu| of orbits; steady sliding's largest real
/// part on its own axis) against the parameter.
std::string SystemBranchScript(const System& s, const SystemRun& run, const std::string& title,
                               FigureFormat format);
/// The figure the script writes.
std::vector<std::string> SystemBranchFigures(FigureFormat format);

}  // namespace stickslip
