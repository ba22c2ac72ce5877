// The forced branch as files (issue 20, item 4): the rows and special points
// as TSV tables, and the resonance figure (x_max against the parameter,
// stable solid, unstable dashed, stick-slip and non-stop in two colours, Den
// Hartog's (1931) non-stop closed form overlaid where it applies) as a
// gnuplot script. The library writes text only; the apps run gnuplot.
#pragma once

#include <string>
#include <vector>

#include "stickslip/forced/branch.hpp"
#include "stickslip/io/figure_style.hpp"
#include "stickslip/io/report.hpp"

namespace stickslip {

/// Columns: branch, <axis>, m, sticks, crossings, kind, x_min, x_max,
/// xdot_min, xdot_max, period, x0, xdot0, mult1_re, mult1_im, mult2_re,
/// mult2_im, mult_max (the largest modulus), stable, pt (the row's number,
/// 1-based). Throws InvalidArgument if a value is not finite.
/// `pieces`: the traced pieces of a forced run (a run from both ends has
/// two), numbered 1, 2, ... in the `branch` column; each one's m is
/// PeriodMultiple(piece).
TsvTable ForcedBranchTable(const std::vector<OrbitBranch>& pieces, ParameterAxis axis,
                           const ForcedParams& p);
/// label, then the same columns, then lab (GR1, CR1, PD1, ...: the label
/// with its index per type, as AUTO-07p's LAB) and description (one line),
/// for the located special points.
TsvTable ForcedSpecialTable(const std::vector<OrbitBranch>& pieces, ParameterAxis axis,
                            const ForcedParams& p);

/// Den Hartog's non-stop setting: coulomb, mu_s = mu_k, v = 0, beta = 0, in omega.
bool DenHartogApplies(const ForcedParams& p, ParameterAxis axis);

/// The resonance figure: draws resonance.<format> from branch.tsv.
/// A run from both ends shades the untraced interval `gap` (empty: none);
/// `specials` > 0 marks and labels the rows of special_points.tsv.
std::string ResonanceScript(const ForcedParams& p, ParameterAxis axis, int pieces,
                            const std::string& title, const std::vector<double>& gap, int specials,
                            FigureFormat format = FigureFormat::kPng);

}  // namespace stickslip
