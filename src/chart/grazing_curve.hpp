// GR curves: the grazing gap g(p1, p2) = (largest x' on the first return of
// the slip-below field from the exit point (x0, v), switching ignored) - v
// vanishes (OrbitFinder::GrazingGap). g > 0: the slip phase reaches the belt
// (stick-slip); g < 0: it stays below (pure slip). At g = 0 the first return
// is the grazing orbit, a pure-slip orbit touching x' = v at (x0, v); its
// nontrivial multiplier lambda = det of the run's Jacobian (the other is 1)
// gives the type: lambda < 1 persistence (a stable pure-slip orbit takes over),
// lambda > 1 a non-smooth fold (the stick-slip orbit meets an unstable
// pure-slip orbit: hysteresis). Where lambda = 1 (GR-LP) a fold curve of
// pure-slip orbits ends on the GR curve.
#pragma once

#include <Eigen/Dense>
#include <string>

#include "numerics/newton2.hpp"
#include "stickslip/chart/plane.hpp"
#include "stickslip/continuation/palc.hpp"
#include "stickslip/orbits/orbit.hpp"

namespace stickslip {

// The first-return run from the exit point at one point of the plane.
struct GrazingSample {
  OrbitStatus status = OrbitStatus::kOk;
  std::string message;
  double gap = 0;
  // With floquet only:
  double multiplier = 0;  // det of the run's Jacobian: lambda at g = 0
  double period = 0;      // time of the run: the period at g = 0
  double amplitude = 0;   // (x_max - x_min) / 2
  double max_slip = 0;    // largest slip speed v - x'_min visited
  bool ok() const { return status == OrbitStatus::kOk; }
};

// One evaluation of the gap at p (floquet: with the variational equations).
GrazingSample SampleGrazing(OrbitFinder& finder, const Params& p, bool floquet);

// F(p1, p2) = g. The Jacobian is a forward difference taken once per
// correction (a chord Jacobian), at the correction's first point.
class GrazingCurveProblem : public PalcProblem {
 public:
  // Throws InvalidArgument if the orbit options are invalid.
  GrazingCurveProblem(const Params& base, const Plane& plane, const OrbitOptions& options);
  int unknowns() const override { return 2; }
  bool Evaluate(const Eigen::VectorXd& u, Eigen::VectorXd* f, Eigen::MatrixXd* jac,
                std::string* why) override;
  void BeginCorrection() override { chord_stale_ = true; }
  std::string DomainError(const Eigen::VectorXd& u) const override;
  // The gap, multiplier, period and amplitude at an accepted point.
  GrazingSample Sample(double x1, double x2) { return At(x1, x2, true); }
  // Polled by the flow of every evaluation: an evaluation under way stops
  // (and fails) once it returns true.
  void set_cancel(std::function<bool()> cancel) { finder_.flow().set_cancel(std::move(cancel)); }

 private:
  GrazingSample At(double x1, double x2, bool floquet);
  Params base_;
  Plane plane_;
  OrbitFinder finder_;
  bool chord_stale_ = true;  // the chord Jacobian must be recomputed before use
  Eigen::MatrixXd chord_;
};

// The GR-LP point near (x1, x2): g = 0 and lambda = 1.
Newton2Result LocateGrazingFold(const Params& base, const Plane& plane, const OrbitOptions& options,
                                double x1, double x2);

}  // namespace stickslip
