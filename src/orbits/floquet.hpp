// Private to src/orbits/: the Floquet multipliers of a Poincare map's DP
// (shooting.hpp, Shooting::Describe): its eigenvalues by modulus, and an
// event section's deflation of the flow direction's 0 (docs/theory.md, "One
// shooting").
#pragma once

#include <Eigen/Dense>
#include <complex>
#include <vector>

namespace stickslip::floquet_detail {

// The eigenvalues of M by modulus, the largest first.
std::vector<std::complex<double>> Eigenvalues(Eigen::Ref<const Eigen::MatrixXd> M);

// B = H DP H for an event section's DP (g^T DP = 0, g the event's gradient):
// B's first row is 0, and the multipliers are its trailing block's
// eigenvalues. v and w are scratch of n entries each.
void Deflate(const Eigen::MatrixXd& DP, const Eigen::VectorXd& g, Eigen::MatrixXd* B,
             Eigen::VectorXd* v, Eigen::VectorXd* w);

}  // namespace stickslip::floquet_detail
