#include "numerics/newton2.hpp"

#include <cmath>

#include "numerics/stall.hpp"

namespace stickslip {

Newton2Result Newton2(const Function2& f, const Eigen::Vector2d& x0, double tol, double step,
                      int max_iterations) {
  Newton2Result r;
  r.x = x0;
  double last = HUGE_VAL;
  for (r.iterations = 1; r.iterations <= max_iterations; ++r.iterations) {
    if (!f(r.x, &r.f)) {
      r.why = "cannot evaluate at the Newton iterate";
      return r;
    }
    Eigen::Matrix2d jac;
    for (int k = 0; k < 2; ++k) {
      Eigen::Vector2d xh = r.x, fh;
      const double h = step * std::max(std::abs(r.x[k]), 1.0);
      xh[k] += h;
      if (!f(xh, &fh)) {
        r.why = "cannot evaluate the difference quotient";
        return r;
      }
      jac.col(k) = (fh - r.f) / h;
    }
    const double det = jac.determinant();
    if (det == 0 || !std::isfinite(det)) {
      r.why = "singular Jacobian";
      return r;
    }
    const Eigen::Vector2d dx = -jac.inverse() * r.f;
    r.x += dx;
    const double size = std::max(std::abs(dx[0]) / std::max(std::abs(r.x[0]), 1.0),
                                 std::abs(dx[1]) / std::max(std::abs(r.x[1]), 1.0));
    bool stalled = false;
    if (NewtonConverged(size, last, r.iterations, tol, &stalled)) {
      r.ok = f(r.x, &r.f);
      if (!r.ok) r.why = "cannot evaluate at the converged point";
      return r;
    }
    last = size;
  }
  r.why = "Newton did not converge in " + std::to_string(max_iterations) + " iterations";
  return r;
}

}  // namespace stickslip
