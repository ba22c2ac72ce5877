// Out-of-line copies (dense_copy.hpp).
#include "numerics/dense_copy.hpp"

#include <algorithm>

namespace stickslip {

void CopyInto(const Eigen::VectorXd& src, Eigen::VectorXd* dst) {
  if (dst->size() != src.size()) dst->resize(src.size());
  std::copy(src.data(), src.data() + src.size(), dst->data());
}

void CopyInto(const Eigen::MatrixXd& src, Eigen::MatrixXd* dst) {
  if (dst->rows() != src.rows() || dst->cols() != src.cols()) dst->resize(src.rows(), src.cols());
  std::copy(src.data(), src.data() + src.size(), dst->data());
}

}  // namespace stickslip
