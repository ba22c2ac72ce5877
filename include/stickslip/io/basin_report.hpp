// The basin classification as text: basins.tsv (one row per start),
// orbits.tsv (every periodic orbit sampled as a curve) and the gnuplot script
// drawing basins.png. Writing them to disk is the caller's
// (WriteFileAtomically in report.hpp).
#pragma once

#include <string>
#include <vector>

#include "stickslip/basin/basin.hpp"
#include "stickslip/io/basin_stability_report.hpp"
#include "stickslip/io/figure_style.hpp"
#include "stickslip/io/report.hpp"

namespace stickslip {

// Columns: x, xdot, fate, orbit (index of the pure-slip orbit, -1 else),
// t_settle. Metadata lines `# key: value` after the header: model, status,
// grid, steady sliding, one `orbit:` line per periodic orbit, and for each
// unstable pure-slip orbit its smallest disturbance (`disturbances[i]` belongs
// to result.orbits.pure_slip[i]; empty: none written).
TsvTable BasinTable(const BasinResult& r, const std::string& model_description,
                    const std::vector<Disturbance>& disturbances);

// A periodic orbit's curve for orbits.tsv.
struct OrbitCurveRows {
  std::string kind;  // "stick-slip" or "pure-slip"
  bool stable = false;
  std::vector<Vec2> points;
};
// Columns: orbit, kind, stable, x, xdot. With `stability` (curves in the
// order stick-slip, then PeriodicOrbits::pure_slip), also basin_stability:
// the fraction of the box that reaches that orbit (0 for an unstable one),
// and its "basin stability <attractor> <fraction>" lines as comments.
TsvTable OrbitTable(const std::vector<OrbitCurveRows>& curves,
                    const BasinStability* stability = nullptr);

// gnuplot script (style of figure_style.hpp) drawing basins.png (.pdf, .svg) from basins.tsv and
// orbits.tsv in its own directory: the starts coloured by fate, every orbit over them (stable
// solid, unstable dashed), the stick band and steady sliding. `suffix` (default empty) is appended
// to the output name. `units` draws a physical run in SI units (figure_style.hpp).
std::string BasinScript(const BasinResult& r, const Model& model,
                        const std::vector<OrbitCurveRows>& curves, const std::string& title,
                        FigureFormat format = FigureFormat::kPng, const FigureUnits& units = {});

}  // namespace stickslip
