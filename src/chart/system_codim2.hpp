// Private to src/chart/: the codimension-two points on one curve of a
// system's periodic orbits (system_chart.hpp), located on the curve itself.
// A sign change of another test function between two curve points (on LP:
// the PD test, LPPD, and the NS test, R1 where two multipliers are at +1;
// on PD: the LP test, LPPD, and the NS test, R2 where two are at -1; on NS:
// the LP test, R1, and the PD test, R2) is refined on the curve: the curve's
// system (orbit_curve.hpp) bordered by the hyperplane normal to the chord at
// a + s (b - a), solved by Newton, and the root in s by Illinois (Dahlquist &
// Bjorck 1974, section 6.2.3) to the corrector's tolerance; the chord's
// linear interpolation is the fallback, marked. An NS curve that ends where
// its pair turns real (a neutral saddle beyond) has its R1 or R2 located
// between its last point and that one. SL at an end where the switching
// sequence changes; CP where an LP curve's direction reverses.
#pragma once

#include <Eigen/Dense>
#include <memory>
#include <vector>

#include "chart/orbit_curve.hpp"
#include "stickslip/chart/system_chart.hpp"

namespace stickslip {

/// The points of one stretch of a curve, on one problem (one section start).
struct CurveStretch {
  std::shared_ptr<OrbitCurveProblem> problem;
  std::vector<Eigen::VectorXd> u;
};

/// Where a point of SystemCurve::points was traced: its stretch and unknowns.
struct TracedPoint {
  int stretch = 0;
  Eigen::VectorXd u;
};

/// A point dropped beyond one end of an NS curve (a neutral saddle).
struct BeyondEnd {
  bool first = false;  ///< beyond the curve's first point, else its last
  int stretch = 0;
  Eigen::VectorXd u;
};

/// Appends the codimension-two points of `curve` (its points traced as
/// `traced` says, on `stretches`) to curve->codim2.
void LocateCodim2(const std::vector<CurveStretch>& stretches,
                  const std::vector<TracedPoint>& traced, const std::vector<BeyondEnd>& beyond,
                  const SystemChartOptions& o, SystemCurve* curve);

/// The curve's points in order (the back way's stretches reversed, then the
/// first, then the forward way's), each sampled on its stretch's problem,
/// into curve->points, and its codimension-two points (LocateCodim2);
/// saddle[0], saddle[1]: neutral saddles dropped beyond its first and last
/// ends (empty: none).
void Assemble(const std::vector<CurveStretch>& back, const CurveStretch& first,
              const std::vector<CurveStretch>& fwd, const Eigen::VectorXd saddle[2],
              const SystemChartOptions& o, SystemCurve* curve);

}  // namespace stickslip
