#include "chart/hopf_curve.hpp"

#include <cmath>

#include "numerics/tolerances.hpp"
#include "stickslip/systems/belt/friction.hpp"

namespace stickslip {

double HopfFunction(const Params& p) { return 2.0 * p.beta + Friction(p).DMu(p.v); }

double HopfCriticality(const Params& p) { return -Friction(p).D3Mu(p.v) / 16.0; }

double HopfCurveProblem::Partial(const Params& p, const ParameterAxis& axis) const {
  if (axis.id() == Parameter::kBeta) return 2.0;
  if (axis.id() == Parameter::kV) return Friction(p).D2Mu(p.v);
  const double x = axis.Get(p), h = Tolerances::kHopfDifference *
                                    std::max(std::abs(x), Tolerances::kHopfDifferenceFloor);
  Params lo = p, hi = p;
  axis.Set(lo, x - h);
  axis.Set(hi, x + h);
  return (HopfFunction(hi) - HopfFunction(lo)) / (2.0 * h);
}

bool HopfCurveProblem::Evaluate(const Eigen::VectorXd& u, Eigen::VectorXd* f, Eigen::MatrixXd* jac,
                                std::string* why) {
  const Params p = plane_.At(base_, u[0], u[1]);
  const std::string err = ValidationError(p);
  if (!err.empty()) {
    *why = err;
    return false;
  }
  f->resize(1);
  (*f)[0] = HopfFunction(p);
  jac->resize(1, 2);
  (*jac)(0, 0) = Partial(p, plane_.p1);
  (*jac)(0, 1) = Partial(p, plane_.p2);
  return true;
}

std::string HopfCurveProblem::DomainError(const Eigen::VectorXd& u) const {
  return ValidationError(plane_.At(base_, u[0], u[1]));
}

Newton2Result LocateGeneralizedHopf(const Params& base, const Plane& plane, double x1, double x2) {
  auto f = [&](const Eigen::Vector2d& x, Eigen::Vector2d* value) {
    const Params p = plane.At(base, x[0], x[1]);
    if (!ValidationError(p).empty()) return false;
    *value << HopfFunction(p), HopfCriticality(p);
    return true;
  };
  return Newton2(f, Eigen::Vector2d(x1, x2));
}

}  // namespace stickslip
