#include "chart/fold_curve.hpp"

#include <cmath>

#include "numerics/tolerances.hpp"

namespace stickslip {

FoldCurveProblem::FoldCurveProblem(const Params& base, const Plane& plane,
                                   const OrbitOptions& options)
    : base_(base), plane_(plane), finder_(Model(base), options) {}

FoldSample FoldCurveProblem::Sample(const Eigen::VectorXd& u) {
  FoldSample s;
  const Params p = plane_.At(base_, u[1], u[2]);
  std::string err = ValidationError(p);
  if (err.empty() && !(u[0] > 0)) err = "the section amplitude a must be > 0";
  if (!err.empty()) {
    s.status = OrbitStatus::kCollapsed;
    s.message = err;
    return s;
  }
  finder_.set_model(Model(p));
  ReturnMap map;
  s.status = finder_.Desingularised(u[0], &s.g, &s.dg, &map);
  if (!s.ok()) {
    s.message = std::string("pure-slip return map at a = ") + std::to_string(u[0]) + ": " +
                (map.message.empty() ? Name(s.status) : map.message);
    return s;
  }
  s.period = map.period;
  s.amplitude = map.flow.extrema.HalfSpanX();
  s.multiplier = map.dpdx;
  s.xdot_max = map.flow.extrema.xdot_max;
  s.max_slip = p.v - map.flow.extrema.xdot_min;
  return s;
}

bool FoldCurveProblem::Evaluate(const Eigen::VectorXd& u, Eigen::VectorXd* f, Eigen::MatrixXd* jac,
                                std::string* why) {
  const FoldSample s = Sample(u);
  if (!s.ok()) {
    *why = s.message;
    return false;
  }
  f->resize(2);
  *f << s.g, s.dg;
  if (chord_stale_) {
    chord_.resize(2, 3);
    const double h[3] = {
        Tolerances::kFoldAmplitudeStep * std::max(u[0], Tolerances::kFoldAmplitudeFloor),
        Tolerances().chart_difference * plane_.width1(),
        Tolerances().chart_difference * plane_.width2()};
    for (int k = 0; k < 3; ++k) {
      Eigen::VectorXd uh = u;
      uh[k] += h[k];
      const FoldSample sh = Sample(uh);
      if (!sh.ok()) {
        *why = sh.message;
        return false;
      }
      chord_(0, k) = (sh.g - s.g) / h[k];
      chord_(1, k) = (sh.dg - s.dg) / h[k];
    }
    chord_(0, 0) = s.dg;
    chord_stale_ = false;
  }
  *jac = chord_;
  return true;
}

std::string FoldCurveProblem::DomainError(const Eigen::VectorXd& u) const {
  if (!(u[0] > 0)) return "the section amplitude a must be > 0";
  return ValidationError(plane_.At(base_, u[1], u[2]));
}

}  // namespace stickslip
