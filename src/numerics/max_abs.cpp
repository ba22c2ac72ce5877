// The max-norm out of line (max_abs.hpp).
#include "numerics/max_abs.hpp"

#include <algorithm>
#include <cmath>

namespace stickslip {

double MaxAbs(Eigen::Ref<const Eigen::VectorXd> v) {
  double m = 0;
  for (Eigen::Index i = 0; i < v.size(); ++i) {
    const double a = std::abs(v[i]);
    if (std::isnan(a)) return a;  // a nan is no size: no test passes on it
    m = std::max(m, a);
  }
  return m;
}

}  // namespace stickslip
