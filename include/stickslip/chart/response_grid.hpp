// The response of any system on a grid of two of its parameters, a chart's
// raster shading (docs/theory.md, "Response grid"): each row (p2 fixed) is
// swept along p1 as an orbit diagram is, every cell starting from the end
// state of the one before (from the belt start, BeltStart, at the row's
// first cell and after a failure), and the attractor reached is classified
// on the system's section (ClassifyAttractor, basin/attractors.hpp: the
// stroboscopic map with a clock, else AttractorOptions::surface or the
// maxima of component 0): period m and sticks per period, rest,
// quasi-periodic (kUndecided), chaotic by the largest Lyapunov exponent,
// unbounded. Chaotic and quasi-periodic zones have no exact boundaries: the
// grid is a raster, where curves (system_chart.hpp) are exact.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "stickslip/basin/attractors.hpp"
#include "stickslip/chart/system_chart.hpp"

namespace stickslip {

struct ResponseGrid {
  int n1 = 0, n2 = 0;
  std::vector<double> x1, x2;        ///< cell centres
  std::vector<Attractor> cells;      ///< n1 * n2, index j * n1 + i (p1 fastest)
  std::vector<double> lyapunov_err;  ///< the exponent's standard error per cell
  std::vector<char> done;            ///< 0: not reached (cancelled)
  bool cancelled = false;
  int failed = 0;
  std::string failure;  ///< the first failed cell and why
  double seconds = 0;
  const Attractor& at(int i, int j) const { return cells[static_cast<size_t>(j) * n1 + i]; }
};

struct ResponseOptions {
  /// Upper bound of n1 and n2.
  static constexpr int kMaxSide = 1000;
  int n1 = 48, n2 = 32;  ///< cells along p1 and p2
  /// Per cell: iterate (transient, keep, flow), max_period, max_amplitude,
  /// surface (an autonomous system's section) and threads (rows in
  /// parallel, capped by the hardware threads); the slice is not used.
  AttractorOptions attractor;
  std::function<bool()> cancelled;  ///< polled between cells, on the calling thread
  /// Empty if valid for `system`, else one line naming the offending value.
  std::string ValidationError(const System& system) const;
};

/// The start of every row: each contact's velocity 0 (OntoSurface, as
/// a block carried by the belt), the other components and the clock at 0,
/// in Filippov's mode (ModeOf).
FlowPoint BeltStart(const System& system);

/// The grid over `plane` (its p1, p2 the system's parameter indices).
/// Throws InvalidArgument on an invalid plane or options.
ResponseGrid Responses(const System& system, const SystemPlane& plane,
                       const ResponseOptions& options);

}  // namespace stickslip
