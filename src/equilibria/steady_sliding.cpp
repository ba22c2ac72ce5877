// Steady sliding and its eigenvalues (steady_sliding.hpp).
#include "stickslip/equilibria/steady_sliding.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>

namespace stickslip {

SteadyState SteadySliding(const System& s, const ModeSet& m) {
  SteadyState r;
  r.z.setZero(s.dimension());
  bool stable = false;
  if (!s.Rest(m, r.z, &stable)) return r;
  r.found = true;
  const int nt = s.tangent_dimension();
  Eigen::MatrixXd J(nt, nt);
  s.Jacobian(m, r.z, J);
  const Eigen::EigenSolver<Eigen::MatrixXd> es(J, false);
  r.eigenvalues.assign(es.eigenvalues().data(), es.eigenvalues().data() + nt);
  std::stable_sort(r.eigenvalues.begin(), r.eigenvalues.end(),
                   [](const std::complex<double>& a, const std::complex<double>& b) {
                     return a.real() > b.real();
                   });
  r.max_real = r.eigenvalues.empty() ? 0 : r.eigenvalues[0].real();
  return r;
}

Eigen::VectorXd NearSteadySliding(const System& s, double d) {
  const SteadyState rest = SteadySliding(s);
  Eigen::VectorXd z = rest.found ? rest.z : Eigen::VectorXd::Zero(s.dimension());
  z[0] += d;
  return z;
}

}  // namespace stickslip
