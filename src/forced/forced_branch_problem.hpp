// Private to src/forced/: the stroboscopic residual as a PalcProblem.
#pragma once

#include "stickslip/forced/branch.hpp"

namespace stickslip::forced_detail {

// F(x, x', p) = P^m(x, x'; p) - (x, x'); dF/d(x, x') from the variational
// run, dF/dp by central differences of two plain runs.
class StrobeProblem final : public PalcProblem {
 public:
  StrobeProblem(const ForcedParams& base, ForcedAxis axis, const ForcedBranchOptions& o)
      : base_(base), axis_(axis), o_(o) {}
  int unknowns() const override { return 3; }
  bool Evaluate(const Eigen::VectorXd& u, Eigen::VectorXd* f, Eigen::MatrixXd* jac,
                std::string* why) override;
  std::string DomainError(const Eigen::VectorXd& u) const override;
  // The row of the last evaluated point.
  ForcedBranchRow Row() const;
  // det(DP^m - I) (LP) and det(DP^m + I) (PD) at the last evaluated point.
  double FoldTest() const { return (last_.jacobian - Mat2::Identity()).determinant(); }
  double FlipTest() const { return (last_.jacobian + Mat2::Identity()).determinant(); }
  // det(DP^m) - 1: |mu|^2 - 1 for a complex pair (NS).
  double TorusTest() const { return last_.jacobian.determinant() - 1; }

 private:
  bool End(const ForcedParams& q, const ForcedPoint& z, bool variational, ForcedRun* run,
           std::string* why) const;

  ForcedParams base_;
  ForcedAxis axis_;
  const ForcedBranchOptions& o_;
  ForcedRun last_;
  Eigen::Vector3d last_u_ = Eigen::Vector3d::Zero();
};

// The branch through `first` (corrected with component `fixed` held), traced
// along `direction` (unscaled), with ContinueForced's rows, special points,
// jumps and ends between p = from and p = to.
ForcedBranch TraceBranch(const ForcedParams& base, ForcedAxis axis, double from, double to,
                         const Eigen::Vector3d& first, int fixed, const Eigen::Vector3d& direction,
                         const ForcedBranchOptions& options);

}  // namespace stickslip::forced_detail
