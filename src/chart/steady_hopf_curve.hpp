// HB curves of any system's steady sliding in two parameters
// (system_chart.hpp): unknowns (p1, p2), one equation, Re lambda = 0 for the
// complex pair of the Jacobian at the rest point nearest the imaginary axis
// (Kuznetsov 2004, ch. 3). It is O(1) for any n, where the bialternate
// product prod_{i<j} (lambda_i + lambda_j) has n(n-1)/2 factors and under- or
// overflows, and it vanishes at Hopf points only (no neutral saddles). The
// rest point is explicit (System::Rest; where a model file has several, the
// one nearest the last sample's), so the test is a function of (p1, p2)
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
  /// The test of eigenvalues; false where no pair is complex.
  static bool Test(const SteadyState& s, double* test, double* omega);

 private:
  std::unique_ptr<System> system_;  // its p1, p2 set at every sample
  int p1_, p2_;
  // The first and the last sample's rest points and (p1, p2): Newton's guesses.
  mutable SteadyState seed_, near_;
  mutable Eigen::VectorXd seed_u_, near_u_;
};

}  // namespace stickslip
