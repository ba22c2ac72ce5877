// Two-parameter curves of any system's periodic orbits (system_chart.hpp):
// the branch problem F(u, p1) = P(u; p1, p2) - u = 0 of the one branch driver
// (continuation/orbit_problem.hpp), with p2 as one more unknown, bordered by
// one test function of the monodromy (Kuznetsov 2004, ch. 10; the branch
// driver's RowTest, so a curve passes through its located points):
//   LP  prod (mu_i - 1),  PD  prod (mu_i + 1),  NS  prod_{i<j} (mu_i mu_j - 1).
// Unknowns (u, p1, p2). dF/du = DP - I from the variational run, dF/dp1 as
// the branch driver has it, dF/dp2 and the test's row by central differences
// (each a run with the monodromy; an exact row would need second-order
// variational equations).
#pragma once

#include <Eigen/Dense>
#include <string>
#include <vector>

#include "continuation/orbit_problem.hpp"
#include "stickslip/chart/chart.hpp"

namespace stickslip {

class OrbitCurveProblem final : public PalcProblem {
 public:
  /// `start` the seed's section point (its clock and mode); p1 the branch's
  /// parameter, p2 the held one.
  OrbitCurveProblem(const System& system, int p1, int p2, const FlowPoint& start,
                    const PoincareSection& section, CurveKind kind,
                    const OrbitBranchOptions& options);
  int unknowns() const override { return nu_ + 2; }
  bool Evaluate(const Eigen::VectorXd& u, Eigen::VectorXd* f, Eigen::MatrixXd* jac,
                std::string* why) override;
  std::string DomainError(const Eigen::VectorXd& u) const override;
  /// u of a row (its start and p) at p2.
  Eigen::VectorXd Unknowns(const OrbitRow& row, double p2) const;
  /// The orbit at u (with its multipliers, counts and extremes) as a row; its
  /// test function in *test, its mode sequence in *modes if given. False
  /// with *why where the map fails.
  bool Sample(const Eigen::VectorXd& u, OrbitRow* row, double* test, std::string* why,
              std::vector<ModeSet>* modes = nullptr);
  /// max(|P(z) - z|, |test|) at u (max norm): an accepted point's residual.
  bool Residual(const Eigen::VectorXd& u, double* residual, std::string* why);
  /// This curve's test function of a row (RowTest's LP, PD or NS).
  double Test(const OrbitRow& r) const;
  int plane_index() const { return nu_; }  ///< u[nu], u[nu + 1] are (p1, p2)
  /// The status of the last map that failed, in any call.
  OrbitStatus last_map_failure() const { return orbit_.last_failure(); }
  /// The status of the orbit of the last Evaluate that failed with `why`
  /// (kContactOpen: a normal force at 0 on the orbit; kModeChanged: the
  /// return's mode differs, the switching sequence changed), else kOk.
  OrbitStatus FailureOf(const std::string& why) const {
    return why == last_failure_ ? last_status_ : OrbitStatus::kOk;
  }

 private:
  // The map at u: the residual and the test (the orbit's multipliers).
  bool At(const Eigen::VectorXd& u, Eigen::VectorXd* r, double* test, std::string* why);
  OrbitBranchOptions options_;  // before orbit_, which holds a reference to it
  // Mutable: DomainError sets the held p2 on its system before checking.
  mutable orbit_detail::OrbitProblem orbit_;
  int p2_, nu_;
  CurveKind kind_;
  std::string last_failure_;  // the last failed Evaluate's why and its orbit's status
  OrbitStatus last_status_ = OrbitStatus::kOk;
};

}  // namespace stickslip
