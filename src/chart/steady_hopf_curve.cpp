// HB curves of steady sliding (chart/steady_hopf_curve.hpp).
#include "chart/steady_hopf_curve.hpp"

#include <algorithm>
#include <cmath>
#include <complex>

#include "numerics/numbers.hpp"
#include "numerics/tolerances.hpp"

namespace stickslip {

using Eigen::MatrixXd;
using Eigen::VectorXd;

SteadyHopfProblem::SteadyHopfProblem(const System& system, int p1, int p2)
    : system_(system.Clone()), p1_(p1), p2_(p2) {}

bool SteadyHopfProblem::Test(const SteadyState& s, double* test, double* omega) {
  double best = HUGE_VAL;
  for (const auto& l : s.eigenvalues)
    if (l.imag() > 0 && std::abs(l.real()) < best)
      best = std::abs(l.real()), *test = l.real(), *omega = l.imag();
  return best < HUGE_VAL;
}

bool SteadyHopfProblem::Sample(const VectorXd& u, SteadyState* state, double* test,
                               std::string* why) const {
  if (!u.allFinite()) {
    *why = "a point that is not finite";
    return false;
  }
  system_->SetParameterValue(p1_, u[0]);
  system_->SetParameterValue(p2_, u[1]);
  *why = system_->ValidationError();
  if (!why->empty()) return false;
  // From the rest point of the first or the last sample, whichever lies
  // nearer in (p1, p2) (a curve's second leg starts at its seed): a curve
  // follows one of several (a drill's fast and slow steady rotations).
  const bool last = !seed_.found || (u - near_u_).norm() <= (u - seed_u_).norm();
  const SteadyState& guess = last ? near_ : seed_;
  *state = guess.found ? SteadySliding(*system_, guess) : SteadySliding(*system_);
  if (state->found) {
    if (!seed_.found) seed_ = *state, seed_u_ = u;
    near_ = *state, near_u_ = u;
  }
  if (!state->found) {
    *why = "no steady sliding at " + system_->ParameterName(p1_) + " = " + Num(u[0]) + ", " +
           system_->ParameterName(p2_) + " = " + Num(u[1]);
    return false;
  }
  for (int i = 0; i < system_->contacts(); ++i)
    if (const auto n = system_->NormalForce(i); n && !(n->At(state->z.data()) > 0)) {
      *why = "contact " + std::to_string(i + 1) + " open at steady sliding (normal force " +
             Num(n->At(state->z.data())) + ")";
      return false;
    }
  double omega = 0;
  if (Test(*state, test, &omega) && std::isfinite(*test)) return true;
  *why = "no complex pair of eigenvalues at " + system_->ParameterName(p1_) + " = " + Num(u[0]) +
         ", " + system_->ParameterName(p2_) + " = " + Num(u[1]);
  return false;
}

std::string SteadyHopfProblem::DomainError(const VectorXd& u) const {
  SteadyState s;
  double t = 0;
  std::string why;
  Sample(u, &s, &t, &why);
  return why;
}

bool SteadyHopfProblem::Evaluate(const VectorXd& u, VectorXd* f, MatrixXd* jac, std::string* why) {
  SteadyState s;
  double t0 = 0;
  if (!Sample(u, &s, &t0, why)) return false;
  f->resize(1);
  (*f)[0] = t0;
  jac->resize(1, 2);
  for (int i = 0; i < 2; ++i) {
    const double d = Tolerances::kBranchDifference * std::max(1.0, std::abs(u[i]));
    VectorXd up = u, dn = u;
    up[i] += d, dn[i] -= d;
    double tp = 0, tm = 0;
    std::string w;
    const bool okp = Sample(up, &s, &tp, &w), okm = Sample(dn, &s, &tm, &w);
    if (!okp && !okm) {
      *why = w;
      return false;
    }
    if (!okp) up = u, tp = t0;
    if (!okm) dn = u, tm = t0;
    (*jac)(0, i) = (tp - tm) / (up[i] - dn[i]);
  }
  return jac->allFinite();
}

}  // namespace stickslip
