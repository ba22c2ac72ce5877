// The max-norm of a vector, 0 for an empty one.
#pragma once

#include <Eigen/Core>

namespace stickslip {

inline double MaxAbs(const Eigen::VectorXd& v) { return v.size() ? v.cwiseAbs().maxCoeff() : 0.0; }

}  // namespace stickslip
