// The max-norm of a vector, 0 for an empty one, nan if it holds a nan; out
// of line, on a Ref: a head() binds without a temporary on the heap.
#pragma once

#include <Eigen/Core>

namespace stickslip {

double MaxAbs(Eigen::Ref<const Eigen::VectorXd> v);

}  // namespace stickslip
