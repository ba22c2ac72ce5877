// Following one curve of a chart through its rectangle with PALC (palc.hpp):
// both ways from a start point, each way until the curve leaves the rectangle
// (the last point is then placed on the border by a correction with the
// crossed coordinate held), closes, is stopped, or the continuation fails.
#pragma once

#include <Eigen/Dense>
#include <algorithm>
#include <functional>
#include <string>
#include <vector>

#include "numerics/tolerances.hpp"
#include "stickslip/chart/chart.hpp"
#include "stickslip/chart/plane.hpp"
#include "stickslip/continuation/palc.hpp"

namespace stickslip {

struct TraceOptions {
  Plane plane;
  int i1 = 0;              // u[i1], u[i1 + 1] are the plane's coordinates
  double max_step = 0.01;  // fraction of the rectangle (scaled arclength)
  double other_scale = 1;  // scale of the unknowns other than the plane's
  // Corrector tolerance on the scaled update (PalcOptions::tol).
  double tol = Tolerances().chart_corrector;
  std::function<bool()> cancelled;
  // Stops a way at an accepted point (e.g. an LP orbit touching the belt).
  std::function<bool(const Eigen::VectorXd&)> stop;
  // Whether `next` continues `last` (accepted in turn; scale: PALC's): empty
  // if so, else why not; the way then ends there (end kind and why from the
  // check), `next` dropped. Empty function: no check.
  std::function<CurveEnd(const PalcPoint& last, const PalcPoint& next,
                         const Eigen::VectorXd& scale)>
      same_branch;
  // With same_branch: a way that leaves its branch inside the rectangle ends
  // where it does (the last step bisected), not at the last point before.
  bool refine_ends = false;
};

struct TraceResult {
  std::vector<Eigen::VectorXd> u;  // the curve, in order
  CurveEnds ends;
  // Empty, or why a way ended early (max-points, step-too-small, start-failed):
  // the curve is cut short inside the rectangle.
  std::string cut;
  int evaluations = 0;
  bool cancelled = false;
  bool stopped = false;  // the last way ended on TraceOptions::stop
};

// Both ways from u0, corrected with component `fixed` held.
TraceResult TraceBothWays(PalcProblem& problem, const TraceOptions& options,
                          const Eigen::VectorXd& u0, int fixed);
// One way, the tangent oriented along `direction` (scaled).
TraceResult TraceOneWay(PalcProblem& problem, const TraceOptions& options,
                        const Eigen::VectorXd& u0, int fixed, const Eigen::VectorXd& direction);

// Whether x (a plane point) lies within 2e-3 of the rectangle's size of a
// curve of this kind already traced (start points found again are skipped).
bool NearCurve(const std::vector<Curve>& curves, CurveKind kind, const Plane& plane,
               const Eigen::Vector2d& x);

// Whether x lies within `tol` of the polyline through `points` (each with p1,
// p2), all coordinates divided by `scale` (the rectangle's widths).
template <class Points>
bool NearPolyline(const Points& points, const Eigen::Vector2d& x, const Eigen::Vector2d& scale,
                  double tol) {
  const Eigen::Vector2d xs = x.cwiseQuotient(scale);
  for (size_t i = 0; i < points.size(); ++i) {
    const Eigen::Vector2d b = Eigen::Vector2d(points[i].p1, points[i].p2).cwiseQuotient(scale);
    const Eigen::Vector2d a =
        i == 0 ? b : Eigen::Vector2d(points[i - 1].p1, points[i - 1].p2).cwiseQuotient(scale);
    const Eigen::Vector2d d = b - a;
    const double t =
        d.squaredNorm() > 0 ? std::clamp((xs - a).dot(d) / d.squaredNorm(), 0.0, 1.0) : 0.0;
    if ((a + t * d - xs).norm() < tol) return true;
  }
  return false;
}

}  // namespace stickslip
