// The continuation's outputs as text: branch.tsv, special_points.tsv and the
// gnuplot script that draws the bifurcation diagrams. Writing them to disk is
// the caller's (WriteFileAtomically in report.hpp).
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "stickslip/continuation/continuation.hpp"
#include "stickslip/io/figure_style.hpp"
#include "stickslip/io/report.hpp"

namespace stickslip {

/// The result's counts and seconds per phase as (key, value) text, in a fixed
/// order: orbit_solves, return_maps, newton_iterations, rejected_steps,
/// integrator_steps, seconds_equilibrium, ..., seconds_total.
std::vector<std::pair<std::string, std::string>> SummaryFields(const ContinuationResult& r);

/// Removes every point and special point with a non-finite number where one
/// must be (all fields but the equilibrium's period and t_stick, which are nan
/// by design). If any is removed, r becomes kFailed (a cancelled r stays
/// cancelled) and its message names the first such point and the count, so no
/// nan or inf is ever written as a result.
void DropNonFinite(ContinuationResult* r);

/// Columns: <r.param>, kind, branch, period, x_min, x_max, xdot_min, xdot_max,
/// t_stick, multiplier, stable, amplitude, then the extra columns, then pt
/// (the 1-based row number), x_start, xdot_start (BranchPoint). Metadata
/// lines before the header: model, status (partial or complete), then the
/// SummaryFields as `# key: value`.
TsvTable BranchTable(const ContinuationResult& r, const std::string& model_description,
                     const std::vector<ExtraColumn>& extra = {});

/// Columns: label, <r.param>, period, x_min, x_max, xdot_min, description, then
/// the extra columns (one value per special point), then pt (the row of
/// branch.tsv it sits on), lab (GR1, HB1, ...; labels.hpp), x_start, xdot_start.
TsvTable SpecialPointTable(const ContinuationResult& r, const std::vector<ExtraColumn>& extra = {});

/// A gnuplot script drawing, from branch.tsv and special_points.tsv in its own
/// directory (in the style of figure_style.hpp): bifurcation_x.png (x range), bifurcation_xdot.png
/// (x' range), period.png and multiplier.png (two panels: Floquet multiplier, steady sliding's
/// largest Re lambda, each with its threshold) against the parameter; stable solid, unstable
/// dashed, colour by kind, special points marked and labelled. The variable `suffix` (default
/// empty) is appended to every output name, so a caller can render to
/// temporary names and rename. With estimates (the columns of
/// CompareEstimates follow the fixed ones), also estimates.png: x'_min and x
/// range of the branch against the seed's and the averaging estimates.
/// `units` draws a physical run in SI units (figure_style.hpp; the default:
/// dimensionless).
std::string BifurcationScript(const ContinuationResult& r, const std::string& title,
                              bool estimates = false, FigureFormat format = FigureFormat::kPng,
                              const FigureUnits& units = {});
/// The output files BifurcationScript draws (extension of `format`).
std::vector<std::string> BifurcationFigures(bool estimates,
                                            FigureFormat format = FigureFormat::kPng);

}  // namespace stickslip
