// LP curves: folds of pure-slip orbits, G(a, p1, p2) = 0 and dG/da = 0 for the
// desingularised return map G(a) = (P(xbar + a) - xbar - a) / a of the section
// x' = 0 (OrbitFinder::Desingularised), a the section amplitude. Near a GH
// point G = c0 (2 beta + mu') + c2 a^2 + c4 a^4 + ... with c2 ~ l1, so a fold
// curve leaves every GH point (Bautin 1949; Kuznetsov 2004, section 8.3) with
// a^2 ~ -c2 / (2 c4). It ends where its orbit reaches the belt speed: on the GR
// curve, at the GR-LP point (grazing_curve.hpp).
#pragma once

#include <Eigen/Dense>
#include <string>

#include "stickslip/chart/plane.hpp"
#include "stickslip/continuation/palc.hpp"
#include "stickslip/orbits/orbit.hpp"

namespace stickslip {

// The pure-slip orbit at an accepted point of a fold curve.
struct FoldSample {
  OrbitStatus status = OrbitStatus::kOk;
  std::string message;
  double g = 0, dg = 0;                              // G and dG/da
  double period = 0, amplitude = 0, multiplier = 0;  // P'(x*) of the orbit
  double xdot_max = 0;  // the orbit stays below the belt while xdot_max < v
  double max_slip = 0;  // largest slip speed v - x'_min visited
  bool ok() const { return status == OrbitStatus::kOk; }
};

// F(a, p1, p2) = (G, dG/da); dG/da from the variational equations, the
// Jacobian by forward differences once per correction (a chord Jacobian).
class FoldCurveProblem : public PalcProblem {
 public:
  // Throws InvalidArgument if the orbit options are invalid.
  FoldCurveProblem(const Params& base, const Plane& plane, const OrbitOptions& options);
  int unknowns() const override { return 3; }
  bool Evaluate(const Eigen::VectorXd& u, Eigen::VectorXd* f, Eigen::MatrixXd* jac,
                std::string* why) override;
  void BeginCorrection() override { chord_stale_ = true; }
  std::string DomainError(const Eigen::VectorXd& u) const override;
  FoldSample Sample(const Eigen::VectorXd& u);

 private:
  Params base_;
  Plane plane_;
  OrbitFinder finder_;
  bool chord_stale_ = true;  // the chord Jacobian must be recomputed before use
  Eigen::MatrixXd chord_;
};

}  // namespace stickslip
