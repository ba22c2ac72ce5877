#include "chart/grazing_curve.hpp"

#include <cmath>

#include "numerics/tolerances.hpp"

namespace stickslip {

GrazingSample SampleGrazing(OrbitFinder& finder, const Params& p, bool floquet) {
  GrazingSample s;
  const std::string err = ValidationError(p);
  if (!err.empty()) {
    s.status = OrbitStatus::kNoReturn;
    s.message = err;
    return s;
  }
  finder.set_model(Model(p));
  finder.set_floquet(floquet);
  FlowResult run;
  s.status = finder.GrazingGap(&s.gap, &run);
  if (!s.ok()) {
    s.message = std::string("grazing gap: ") + Name(s.status) +
                (run.message.empty() ? "" : ": " + run.message);
    return s;
  }
  if (floquet) {
    s.multiplier = run.jacobian.determinant();
    s.period = run.t;
    s.amplitude = run.extrema.HalfSpanX();
    s.max_slip = p.v - run.extrema.xdot_min;
  }
  return s;
}

GrazingCurveProblem::GrazingCurveProblem(const Params& base, const Plane& plane,
                                         const OrbitOptions& options)
    : base_(base), plane_(plane), finder_(Model(base), options) {}

GrazingSample GrazingCurveProblem::At(double x1, double x2, bool floquet) {
  return SampleGrazing(finder_, plane_.At(base_, x1, x2), floquet);
}

bool GrazingCurveProblem::Evaluate(const Eigen::VectorXd& u, Eigen::VectorXd* f,
                                   Eigen::MatrixXd* jac, std::string* why) {
  const GrazingSample s = At(u[0], u[1], false);
  if (!s.ok()) {
    *why = s.message;
    return false;
  }
  f->resize(1);
  (*f)[0] = s.gap;
  if (chord_stale_) {
    // Forward differences, h relative to the rectangle's size.
    chord_.resize(1, 2);
    const double rel = Tolerances().chart_difference;
    const double h[2] = {rel * plane_.width1(), rel * plane_.width2()};
    for (int k = 0; k < 2; ++k) {
      Eigen::VectorXd uh = u;
      uh[k] += h[k];
      const GrazingSample sh = At(uh[0], uh[1], false);
      if (!sh.ok()) {
        *why = sh.message;
        return false;
      }
      chord_(0, k) = (sh.gap - s.gap) / h[k];
    }
    chord_stale_ = false;
  }
  *jac = chord_;
  return true;
}

std::string GrazingCurveProblem::DomainError(const Eigen::VectorXd& u) const {
  return ValidationError(plane_.At(base_, u[0], u[1]));
}

Newton2Result LocateGrazingFold(const Params& base, const Plane& plane, const OrbitOptions& options,
                                double x1, double x2) {
  OrbitFinder finder(Model(base), options);
  auto f = [&](const Eigen::Vector2d& x, Eigen::Vector2d* value) {
    const GrazingSample s = SampleGrazing(finder, plane.At(base, x[0], x[1]), true);
    if (!s.ok()) return false;
    *value << s.gap, s.multiplier - 1.0;
    return true;
  };
  return Newton2(f, Eigen::Vector2d(x1, x2), Tolerances::kGrazingNewtonTol,
                 Tolerances::kGrazingNewtonStep);
}

}  // namespace stickslip
