// The chart's outputs as text: curves.tsv, codim2.tsv, regions.tsv and the
// gnuplot script drawing chart.png. Writing them is the caller's
// (WriteFileAtomically in report.hpp).
#pragma once

#include <string>

#include "stickslip/chart/chart.hpp"
#include "stickslip/io/figure_style.hpp"
#include "stickslip/io/report.hpp"

namespace stickslip {

// Columns: <p1>, <p2>, curve (HB, GR, LP), id (curve number), period,
// amplitude, multiplier, l1 (HB; "-" otherwise), type (HB supercritical /
// subcritical, GR persistence / nonsmooth-fold, LP fold), unphysical (1 if
// the orbit visits slip speeds where mu <= 0). Comments: model, status,
// the curves' ends and the count of unphysical points.
TsvTable CurvesTable(const ChartResult& r, const Plane& plane, const std::string& model);
// Columns: label (GH, GR-LP), <p1>, <p2>, description.
TsvTable Codim2Table(const ChartResult& r, const Plane& plane, const std::string& model);
// The regions as polygons (ChartResult::faces): columns face (1, 2, ...),
// region (0 steady sliding only, 1 stick-slip, 2 pure-slip oscillation,
// 3 bistable), name, ring (0 outline, 1... holes), <p1>, <p2>: one row per
// vertex, each ring closed. Comments: each face's area and interior point.
TsvTable RegionsTable(const ChartResult& r, const Plane& plane, const std::string& model);

// gnuplot script drawing chart.png (plus the variable `suffix`, as in
// BifurcationScript): the regions as filled polygons (the vertices of
// regions.tsv), the curves of curves.tsv on top, codim2.tsv's points labelled.
// title is gnuplot enhanced text (ChartTitle). `units` draws a physical run's
// axes in SI units (figure_style.hpp). chart_script.cpp.
std::string ChartScript(const ChartResult& r, const Plane& plane, const std::string& title,
                        FigureFormat format = FigureFormat::kPng, const FigureUnits& units = {});
// "Stability chart, cubic law: μ_s = 0.4, μ_m = 0.25, v_m = 0.5": the law's
// parameters but the two axes, as gnuplot enhanced text.
std::string ChartTitle(const Params& base, const Plane& plane);

}  // namespace stickslip
