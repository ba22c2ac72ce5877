// HB curves: steady sliding x = mu(v) has eigenvalues solving
// lambda^2 + (2 beta + mu'(v)) lambda + 1 = 0, so they cross the imaginary axis
// (at +-i) where 2 beta + mu'(v) = 0, in any pair of parameters.
//
// Criticality. With y = x - mu(v), slip below the belt is
// y'' + y = -(2 beta + mu'(v)) y' + mu''(v) y'^2 / 2 - mu'''(v) y'^3 / 6 + ...
// For y'' + y = g(y') the quadratic term of g drops out of the first Lyapunov
// coefficient (Guckenheimer & Holmes 1983, eq. 3.4.11, with f = 0, g = a y^2 + b y^3:
// 16 l1 = g_yyy = 6 b). Averaging the energy y^2 + y'^2 = r^2 over a cycle
// (<sin^4> = 3/8) gives dr/dt = -(2 beta + mu') r / 2 - mu''' r^3 / 16, so
// l1 = -mu'''(v) / 16 and near HB the orbit radius is r^2 = -8 (2 beta + mu') / mu'''.
// l1 < 0: supercritical; l1 > 0: subcritical. A GH point is where l1 = 0 on HB.
#pragma once

#include <Eigen/Dense>
#include <string>

#include "numerics/newton2.hpp"
#include "stickslip/continuation/palc.hpp"
#include "stickslip/chart/plane.hpp"

namespace stickslip {

// 2 beta + mu'(v): the trace of steady sliding's Jacobian, negated. The same as
// HopfDamping (special_points.hpp) but from the friction law alone: no Model, no
// validation, so difference quotients may step to the domain's edge.
double HopfFunction(const Params& p);
// First Lyapunov coefficient of the Hopf point, -mu'''(v) / 16 (see above).
double HopfCriticality(const Params& p);

// F(p1, p2) = HopfFunction, in the plane's axes. Derivatives: exact in beta (2)
// and v (mu''(v)), central differences in the other parameters.
class HopfCurveProblem : public PalcProblem {
 public:
  HopfCurveProblem(const Params& base, const Plane& plane) : base_(base), plane_(plane) {}
  int unknowns() const override { return 2; }
  bool Evaluate(const Eigen::VectorXd& u, Eigen::VectorXd* f, Eigen::MatrixXd* jac,
                std::string* why) override;
  std::string DomainError(const Eigen::VectorXd& u) const override;

 private:
  double Partial(const Params& p, const ParameterAxis& axis) const;
  Params base_;
  Plane plane_;
};

// The GH point near (x1, x2): HopfFunction = 0 and HopfCriticality = 0.
Newton2Result LocateGeneralizedHopf(const Params& base, const Plane& plane, double x1, double x2);

}  // namespace stickslip
