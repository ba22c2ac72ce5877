// dst = src for the dynamic vectors and matrices results carry, out of line:
// Eigen's inline assignment is a resize and a vectorised loop at every use,
// and the code of one Newton solve held dozens of them (docs/benchmarks.md,
// "A Newton solve's own code").
#pragma once

#include <Eigen/Core>

namespace stickslip {

void CopyInto(const Eigen::VectorXd& src, Eigen::VectorXd* dst);
void CopyInto(const Eigen::MatrixXd& src, Eigen::MatrixXd* dst);

}  // namespace stickslip
