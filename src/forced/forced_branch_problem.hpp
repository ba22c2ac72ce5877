// Private to src/forced/: the stroboscopic residual as a PalcProblem.
#pragma once

#include "../continuation/orbit_problem.hpp"
#include "stickslip/forced/branch.hpp"

namespace stickslip::forced_detail {

// F(x, x', p) = P^m(x, x'; p) - (x, x') at theta = 0: the one branch
// driver's problem (src/continuation/orbit_problem.hpp) on the forced model's
// stroboscopic section, with the forced rows and domain message.
class StrobeProblem final : public PalcProblem {
 public:
  StrobeProblem(const ForcedParams& base, ForcedAxis axis, const ForcedBranchOptions& o);
  StrobeProblem(const StrobeProblem&) = delete;  // core_ holds core_options_ by reference
  StrobeProblem& operator=(const StrobeProblem&) = delete;
  int unknowns() const override { return 3; }
  bool Evaluate(const Eigen::VectorXd& u, Eigen::VectorXd* f, Eigen::MatrixXd* jac,
                std::string* why) override {
    return core_.Evaluate(u, f, jac, why);
  }
  std::string DomainError(const Eigen::VectorXd& u) const override;
  // The row of the last evaluated point.
  ForcedBranchRow Row() const;

 private:
  ForcedParams base_;
  ForcedAxis axis_;
  const ForcedBranchOptions& o_;
  OrbitBranchOptions core_options_;
  orbit_detail::OrbitProblem core_;
};

// The branch through `first` (corrected with component `fixed` held), traced
// along `direction` (unscaled), with ContinueForced's rows, special points,
// jumps and ends between p = from and p = to.
ForcedBranch TraceBranch(const ForcedParams& base, ForcedAxis axis, double from, double to,
                         const Eigen::Vector3d& first, int fixed, const Eigen::Vector3d& direction,
                         const ForcedBranchOptions& options);

}  // namespace stickslip::forced_detail
