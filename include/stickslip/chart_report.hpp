// The chart's outputs as text: curves.tsv, codim2.tsv, regions.tsv and the
// gnuplot script drawing chart.png. Writing them is the caller's
// (WriteFileAtomically in report.hpp).
#pragma once

#include "stickslip/figure_style.hpp"

#include <string>

#include "stickslip/chart.hpp"
#include "stickslip/report.hpp"

namespace stickslip {

// Columns: <p1>, <p2>, curve (HB, GR, LP), id (curve number), period,
// amplitude, multiplier, l1 (HB; "-" otherwise), type (HB supercritical /
// subcritical, GR persistence / nonsmooth-fold, LP fold), unphysical (1 if
// the orbit visits slip speeds where mu <= 0). Comments: model, status,
// the curves' ends and the count of unphysical points.
TsvTable CurvesTable(const ChartResult& r, const Plane& plane, const std::string& model);
// Columns: label (GH, GR-LP), <p1>, <p2>, description.
TsvTable Codim2Table(const ChartResult& r, const Plane& plane, const std::string& model);
// Columns: <p1>, <p2>, region (0 steady sliding only, 1 stick-slip,
// 2 pure-slip oscillation, 3 bistable), name.
TsvTable RegionsTable(const ChartResult& r, const Plane& plane, const std::string& model);

// gnuplot script drawing chart.png (plus the variable `suffix`, as in
// BifurcationScript) from the three tables in its own directory.
std::string ChartScript(const ChartResult& r, const Plane& plane, const std::string& title,
                        FigureFormat format = FigureFormat::kPng);

}  // namespace stickslip
