// Exact basin stability as text: the "basin stability <attractor> <fraction>"
// lines, and the curve against a parameter as basin_stability.tsv with the
// gnuplot script that draws basin_stability.png. Writing is the caller's.
#pragma once

#include <string>
#include <vector>

#include "stickslip/basin/basin_stability.hpp"
#include "stickslip/io/figure_style.hpp"
#include "stickslip/io/report.hpp"

namespace stickslip {

/// One line per share: "basin stability steady-sliding 0.123456789012"
/// (12 decimals), without a trailing newline.
std::vector<std::string> BasinStabilityLines(const BasinStability& b);

/// Columns: <param>, steady_sliding, stick_slip, pure_slip (all stable
/// pure-slip orbits), undecided (a region no attractor bounds), enclosed (the
/// fraction of the box inside the innermost pure-slip orbit, 0 if none), then
/// metadata: model, the box, status.
TsvTable BasinStabilityTable(const BasinStabilityCurve& c, const std::string& model_description,
                             const Box& box);

/// A parameter value the figure marks: a special point of the branch over the
/// same range ("HB", "GR", "LP"); a jump (a fold or grazing: an orbit ends)
/// breaks the curves there instead of joining the rows on its two sides.
struct BasinStabilityMark {
  double p = 0;
  std::string label;
  bool jump = false;
};

/// gnuplot script drawing basin_stability.<format> (plus `suffix`, default
/// empty) from basin_stability.tsv in its own directory, in the shared style
/// (figure_style.hpp): each fraction against the parameter, in SI units for
/// a physical run (`units`), the marks as labelled vertical lines.
std::string BasinStabilityScript(const ParameterAxis& param, const std::string& title,
                                 FigureFormat format = FigureFormat::kPng,
                                 const FigureUnits& units = {},
                                 const std::vector<BasinStabilityMark>& marks = {});

}  // namespace stickslip
