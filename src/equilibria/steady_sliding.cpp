// Steady sliding and its eigenvalues (steady_sliding.hpp).
#include "stickslip/equilibria/steady_sliding.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>

namespace stickslip {

namespace {

SteadyState RestOf(const System& s, const ModeSet& m, const Eigen::VectorXd& guess) {
  SteadyState r;
  r.z = guess;
  bool stable = false;
  if (!s.Rest(m, r.z, &stable)) return r;
  r.found = true;
  r.mode = m;
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

}  // namespace

SteadyState SteadySliding(const System& s, const ModeSet& m) {
  return RestOf(s, m, Eigen::VectorXd::Zero(s.dimension()));
}

SteadyState SteadySliding(const System& s, const SteadyState& near) {
  if (!near.found || near.z.size() != s.dimension()) return SteadySliding(s);
  return RestOf(s, near.mode, near.z);
}

SteadyState SteadySliding(const System& s) {
  const int k = s.contacts();
  const long modes = k <= kSteadyModeContacts ? 1L << k : 1;
  for (long bits = 0; bits < modes; ++bits) {
    ModeSet m;
    for (int c = 0; c < k; ++c) m.set(c, (bits >> c) & 1 ? Mode::kSlipAbove : Mode::kSlipBelow);
    SteadyState r = SteadySliding(s, m);
    if (r.found) return r;
  }
  SteadyState none;
  none.z.setZero(s.dimension());
  return none;
}

Eigen::VectorXd NearSteadySliding(const System& s, double d) {
  const SteadyState rest = SteadySliding(s);
  Eigen::VectorXd z = rest.found ? rest.z : Eigen::VectorXd::Zero(s.dimension());
  z[0] += d;
  return z;
}

}  // namespace stickslip
