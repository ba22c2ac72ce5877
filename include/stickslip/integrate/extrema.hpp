// The extremes of x and x' over a run, an orbit or a branch point: one value
// type for the flow, the orbits, the continuation and the forced oscillator.
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <limits>

namespace stickslip {

struct Extrema {
  double x_min = 0, x_max = 0, xdot_min = 0, xdot_max = 0;

  /// The identity of Add and Merge (+-inf): nothing seen yet.
  static Extrema Empty() {
    constexpr double inf = std::numeric_limits<double>::infinity();
    return {inf, -inf, inf, -inf};
  }
  /// One state (x, x').
  static Extrema Point(double x, double xdot) { return {x, x, xdot, xdot}; }

  bool empty() const { return !(x_min <= x_max); }
  void AddX(double x) { x_min = std::min(x_min, x), x_max = std::max(x_max, x); }
  void AddXdot(double xdot) {
    xdot_min = std::min(xdot_min, xdot), xdot_max = std::max(xdot_max, xdot);
  }
  void Add(double x, double xdot) { AddX(x), AddXdot(xdot); }
  void Merge(const Extrema& o) {
    x_min = std::min(x_min, o.x_min), x_max = std::max(x_max, o.x_max);
    xdot_min = std::min(xdot_min, o.xdot_min), xdot_max = std::max(xdot_max, o.xdot_max);
  }
  /// (x_max - x_min) / 2: the amplitude of a stick-slip orbit.
  double HalfSpanX() const { return (x_max - x_min) / 2; }
};

/// The extremes of x and x' from recorded extremes of the components 0, 1
/// (a run's, an orbit's or a branch row's lo and hi), else Extrema::Empty().
inline Extrema ExtremaOf(const Eigen::VectorXd& lo, const Eigen::VectorXd& hi) {
  return lo.size() >= 2 && hi.size() >= 2 ? Extrema{lo[0], hi[0], lo[1], hi[1]} : Extrema::Empty();
}

}  // namespace stickslip
