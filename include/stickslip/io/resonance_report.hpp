// The forced branch's resonance figure (x_max against the parameter, stable
// solid, unstable dashed, stick-slip and non-stop in two colours, Den
// Hartog's (1931) non-stop closed form overlaid where it applies) as a
// gnuplot script reading the system's tables (system_branch_report.hpp).
// The library writes text only; the apps run gnuplot.
#pragma once

#include <string>
#include <vector>

#include "stickslip/continuation/forced_branch.hpp"
#include "stickslip/io/figure_style.hpp"
#include "stickslip/io/report.hpp"

namespace stickslip {

/// Den Hartog's non-stop setting: coulomb, mu_s = mu_k, v = 0, beta = 0, in omega.
bool DenHartogApplies(const ForcedParams& p, ParameterAxis axis);

/// The resonance figure: draws resonance.<format> from branch.tsv.
/// A run from both ends shades the untraced interval `gap` (empty: none);
/// `specials` > 0 marks and labels the rows of special_points.tsv.
std::string ResonanceScript(const ForcedParams& p, ParameterAxis axis, int pieces,
                            const std::string& title, const std::vector<double>& gap, int specials,
                            FigureFormat format = FigureFormat::kPng);

}  // namespace stickslip
