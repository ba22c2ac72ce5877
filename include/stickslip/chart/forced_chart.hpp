// The chart of the forced oscillator in two of its parameters (issue 21 item
// 3), e.g. the (Omega, A) map: the two-parameter curves of LP, PD, NS and GR
// (forced_curve.hpp, followed by PALC from the special points that
// one-parameter runs locate on seed lines across the rectangle), their
// codimension-two points, and the response type on a grid of the rectangle
// (period m and sticks per period of the attractor reached, quasi-periodic,
// chaotic by the largest Lyapunov exponent: chaos/lyapunov.hpp). Chaotic and
// quasi-periodic zones have no exact boundaries: the grid is a raster.
#pragma once

#include <complex>
#include <functional>
#include <string>
#include <vector>

#include "stickslip/basin/attractors.hpp"
#include "stickslip/chart/chart.hpp"
#include "stickslip/forced/branch.hpp"
#include "stickslip/names.hpp"

namespace stickslip {

struct ForcedCurvePoint {
  double p1 = 0, p2 = 0;
  double x0 = 0, xdot0 = 0;  ///< the orbit's point at the section phase
  /// The section: forcing phase Omega t in [0, 2 pi), moved off 0 where the
  /// orbit would stick at the section (the map is not smooth there).
  double phase = 0;
  int sticks = 0, crossings = 0;
  Extrema extrema;  ///< the table writes x_min, x_max
  std::complex<double> multipliers[2];
  /// NS: the multipliers are real (mu1 mu2 = 1, a neutral saddle, no NS).
  /// GR: the margin is a crossing's (else a grazing's).
  bool flag = false;
};

struct ForcedCurve {
  CurveKind kind = CurveKind::kFold;
  int m = 1;  ///< period multiple of the orbit
  std::vector<ForcedCurvePoint> points;
  CurveEnds ends;
  std::string seed;  ///< where it started: "omega = 0.8 line, force = 0.3"
  int evaluations = 0;
  double seconds = 0;
};

/// Codimension-two points on the curves.
using ForcedCodim2Method = Codim2Method;

struct ForcedCodim2 {
  Codim2Label label = Codim2Label::kR1;
  CurveKind on = CurveKind::kFold;
  int curve = 0;  ///< index into ForcedChartResult::curves
  double p1 = 0, p2 = 0;
  ForcedCodim2Method method = ForcedCodim2Method::kCurveEnd;
  /// kRefined: the orbit there (section phase, point, multipliers) and the
  /// test function's value (det DP - 1, det DP + 1 or |tr DP| - 2).
  double phase = 0, x0 = 0, xdot0 = 0, test = 0;
  std::complex<double> multipliers[2];
  std::string description;
};

/// The response at one grid cell: the attractor reached from the previous
/// cell's end state (each row of the grid swept along p1 like an orbit
/// diagram), classified as forced_basin.hpp does. kUndecided is reported as
/// quasi-periodic: not periodic within max_period and not chaotic.
struct ResponseGrid {
  int n1 = 0, n2 = 0;
  std::vector<double> x1, x2;        ///< cell centres
  std::vector<Attractor> cells;      ///< n1 * n2, index j * n1 + i (p1 fastest)
  std::vector<double> lyapunov_err;  ///< the exponent's standard error per cell
  std::vector<char> done;            ///< 0: not reached (cancelled)
  int failed = 0;
  std::string failure;  ///< the first failed cell and why
  const Attractor& at(int i, int j) const { return cells[static_cast<size_t>(j) * n1 + i]; }
};

struct ForcedChartOptions {
  /// max_step's upper bound (a curve across the rectangle in at least 2 steps).
  static constexpr double kMaxStepLimit = 0.5;
  /// Upper bounds of seed_lines and of the response grid's n1 and n2.
  static constexpr int kMaxSeedLines = 50, kMaxGridSide = 1000;
  /// Default: (omega, force) on [0.5, 2] x [0.05, 1].
  Plane plane{Parameter::kOmega, Parameter::kForce, 0.5, 2, 0.05, 1};
  FlowOptions flow = ForcedModel::FlowDefaults();  ///< rtol, atol 1e-12 (forced flow defaults)
  int max_m = 2;                                   ///< curves of orbits of period multiple 1..max_m
  int seed_lines = 3;         ///< one-parameter runs per axis, across the rectangle
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
  ChartStatus status = ChartStatus::kOk;
  std::string message;
  std::vector<ForcedCurve> curves;
  std::vector<ForcedCodim2> codim2;
  ResponseGrid grid;
  int seed_runs = 0;         ///< one-parameter runs made for seeds
  int cut_curves = 0;        ///< curves with an end inside the rectangle (ends say why)
  int seeds_not_traced = 0;  ///< seeds whose start failed both ways
  double seconds = 0, grid_seconds = 0;
};

/// Throws InvalidArgument if the options or the model are invalid.
ForcedChartResult ForcedChart(const ForcedParams& base, const ForcedChartOptions& options);

/// One curve from a point near it (x0, xdot0 at (p1, p2); p2 held while it
/// is corrected), both ways to the rectangle's border: what ForcedChart does
/// per seed, for callers and tests. status kOk, or kPartial (why in *message).
/// Throws InvalidArgument for kind kHopf, or invalid options or parameters.
ForcedCurve TraceForcedCurve(const ForcedParams& base, const ForcedChartOptions& options,
                             CurveKind kind, int m, double x0, double xdot0, double p1, double p2,
                             std::string* message);

/// The response grid alone (ForcedChart's second half).
ResponseGrid ForcedResponseGrid(const ForcedParams& base, const ForcedChartOptions& options,
                                bool* cancelled);

}  // namespace stickslip
