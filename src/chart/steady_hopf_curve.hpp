// HB curves of any system's steady sliding in two parameters
// (system_chart.hpp): unknowns (p1, p2), one equation, the bialternate test
//   prod_{i<j} (lambda_i + lambda_j) = 0
// of the Jacobian's eigenvalues at the rest point (Kuznetsov 2004, ch. 10:
// zero where a pair sums to 0, a Hopf pair or a neutral saddle). The rest
// point is explicit (System::Rest), so the test is a function of (p1, p2)
// alone; its gradient by central differences.
#pragma once

#include <Eigen/Dense>
#include <memory>
#include <string>

#include "stickslip/continuation/palc.hpp"
#include "stickslip/equilibria/steady_sliding.hpp"

namespace stickslip {

class SteadyHopfProblem final : public PalcProblem {
 public:
  SteadyHopfProblem(const System& system, int p1, int p2);
  int unknowns() const override { return 2; }
  bool Evaluate(const Eigen::VectorXd& u, Eigen::VectorXd* f, Eigen::MatrixXd* jac,
                std::string* why) override;
  /// The system invalid at u, no rest point, or a contact open there.
  std::string DomainError(const Eigen::VectorXd& u) const override;
  /// Steady sliding at u and its test; false with *why outside the domain.
  bool Sample(const Eigen::VectorXd& u, SteadyState* state, double* test, std::string* why) const;
  /// The test of eigenvalues.
  static double Test(const SteadyState& s);

 private:
  std::unique_ptr<System> system_;  // its p1, p2 set at every sample
  int p1_, p2_;
};

}  // namespace stickslip
