// Newton's method for two equations in two unknowns with a forward-difference
// Jacobian: locates codimension-two points (GH, GR-LP) from a nearby guess.
#pragma once

#include <Eigen/Dense>
#include <functional>
#include <string>

#include "numerics/tolerances.hpp"
namespace stickslip {

// f(x, &value) returns false (and may set nothing) where it cannot be evaluated.
using Function2 = std::function<bool(const Eigen::Vector2d& x, Eigen::Vector2d* value)>;

struct Newton2Result {
  bool ok = false;
  Eigen::Vector2d x = Eigen::Vector2d::Zero();
  Eigen::Vector2d f = Eigen::Vector2d::Zero();
  int iterations = 0;
  std::string why;  // when !ok
};

// Newton from x0; differences h = step .* max(|x|, 1) (per unknown). Converged
// when |dx_k| <= tol * max(|x_k|, 1) for both k, or stalled at the noise floor
// (NewtonConverged of numerics/stall.hpp).
Newton2Result Newton2(const Function2& f, const Eigen::Vector2d& x0, double tol = Tolerances::kNewton2Tol,
                      double step = Tolerances::kNewton2Step, int max_iterations = 30);

}  // namespace stickslip
