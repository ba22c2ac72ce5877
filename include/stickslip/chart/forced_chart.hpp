// The chart of the forced oscillator in two of its parameters, e.g. the
// (Omega, A) map: the one chart's curves of LP, PD, NS and GR and their
// codimension-two points (ChartSystem, system_chart.hpp, on ForcedModel), and
// the response grid of the rectangle (Responses, response_grid.hpp).
#pragma once

#include <complex>
#include <functional>
#include <string>
#include <vector>

#include "stickslip/basin/attractors.hpp"
#include "stickslip/chart/chart.hpp"
#include "stickslip/chart/response_grid.hpp"
#include "stickslip/chart/system_chart.hpp"
#include "stickslip/forced/branch.hpp"
#include "stickslip/names.hpp"

namespace stickslip {

struct ForcedChartOptions {
  /// max_step's upper bound (a curve across the rectangle in at least 2 steps).
  static constexpr double kMaxStepLimit = 0.5;
  /// Upper bounds of seed_lines and of the response grid's n1 and n2.
  static constexpr int kMaxSeedLines = SystemChartOptions::kMaxSeedLines, kMaxGridSide = 1000;
  /// Default: (omega, force) on [0.5, 2] x [0.05, 1].
  Plane plane{Parameter::kOmega, Parameter::kForce, 0.5, 2, 0.05, 1};
  FlowOptions flow = ForcedModel::FlowDefaults();  ///< rtol, atol 1e-12 (forced flow defaults)
  int max_m = 2;                                   ///< curves of orbits of period multiple 1..max_m
  int seed_lines = 3;         ///< lines per axis across the rectangle, each seeding curves
  double max_step = 0.01;     ///< largest curve step, fraction of the rectangle
  double max_amplitude = 50;  ///< seed branches stop at |x| = max_amplitude
  bool curves = true;
  int n1 = 48, n2 = 32;             ///< response grid; 0: none
  LyapunovOptions iterate;          ///< per grid cell: transient, keep, flow
  int max_period = 16;              ///< largest m the grid looks for
  int threads = 2;                  ///< grid rows in parallel, capped by the hardware threads
  std::function<bool()> cancelled;  ///< polled between points and cells
  ForcedChartOptions() { iterate.transient = 300, iterate.keep = 64, iterate.align = 20; }
  /// Empty if valid for base, else one line naming the offending value.
  std::string ValidationError(const ForcedParams& base) const;
};

struct ForcedChartResult {
  /// The curves' status (SystemChart::status), made partial by failed grid
  /// cells too.
  ChartStatus status = ChartStatus::kOk;
  std::string message;
  /// The curves and codimension-two points: the one chart (ChartSystem) of
  /// ForcedModel, its axes the plane's.
  SystemChart chart;
  ResponseGrid grid;
  double seconds = 0, grid_seconds = 0;
};

/// Throws InvalidArgument if the options or the model are invalid.
ForcedChartResult ForcedChart(const ForcedParams& base, const ForcedChartOptions& options);

/// The one chart's options for these (the plane's axes as ForcedModel's
/// parameter indices, the flow, max_m, seed lines, step, max_amplitude).
SystemChartOptions SystemOptions(const ForcedModel& model, const ForcedChartOptions& options);

/// The response grid's options for these (cells, iteration, flow, max_period,
/// max_amplitude, threads, cancelled).
ResponseOptions ResponseOptionsOf(const ForcedChartOptions& options);

}  // namespace stickslip
