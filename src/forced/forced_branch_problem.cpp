#include "forced_branch_problem.hpp"

#include <cmath>

#include "numerics/numbers.hpp"
#include "numerics/tolerances.hpp"
#include "stickslip/errors.hpp"

namespace stickslip {

const char* ForcedAxisName(ForcedAxis a) { return Name(a); }

double GetAxis(const ForcedParams& p, ForcedAxis a) {
  switch (a) {
    case ForcedAxis::kOmega:
      return p.omega;
    case ForcedAxis::kForce:
      return p.force;
    case ForcedAxis::kV:
      return p.base.v;
    case ForcedAxis::kBeta:
      return p.base.beta;
  }
  return 0;
}

void SetAxis(ForcedParams& p, ForcedAxis a, double value) {
  switch (a) {
    case ForcedAxis::kOmega:
      p.omega = value;
      return;
    case ForcedAxis::kForce:
      p.force = value;
      return;
    case ForcedAxis::kV:
      p.base.v = value;
      return;
    case ForcedAxis::kBeta:
      p.base.beta = value;
      return;
  }
}

const char* ForcedBranchStatusName(ForcedBranchStatus s) { return Name(s); }

const char* ForcedLabelName(ForcedLabel l) { return Name(l); }

namespace forced_detail {

std::string StrobeProblem::DomainError(const Eigen::VectorXd& u) const {
  ForcedParams q = base_;
  SetAxis(q, axis_, u[2]);
  std::string e = ValidationError(q);
  const double bound = 2 * o_.max_amplitude;  // rows stop at max_amplitude first
  if (e.empty() && !(std::abs(u[0]) <= bound && std::abs(u[1]) <= bound))
    e = "|x| or |x'| = " + Num(std::max(std::abs(u[0]), std::abs(u[1]))) + " beyond max_amplitude";
  return e;
}

bool StrobeProblem::End(const ForcedParams& q, const ForcedPoint& z, bool variational,
                        ForcedRun* run, std::string* why) const {
  const ForcedModel model(q);
  ForcedRequest rq;
  rq.t_end = o_.m * model.period();
  rq.variational = variational;
  rq.extremes = variational;  // the parameter's differences need the end only
  *run = ForcedFlow(model, o_.flow).Run(ForcedStart(model, 0, z.x, z.xdot), rq);
  if (run->status == ForcedStatus::kReached) return true;
  *why = run->message;
  return false;
}

bool StrobeProblem::Evaluate(const Eigen::VectorXd& u, Eigen::VectorXd* f, Eigen::MatrixXd* jac,
                             std::string* why) {
  *why = DomainError(u);
  if (!why->empty()) return false;
  ForcedParams q = base_;
  SetAxis(q, axis_, u[2]);
  const ForcedPoint z{0, u[0], u[1], Mode::kSlipBelow};
  if (!End(q, z, true, &last_, why)) return false;
  last_u_ = u;
  f->resize(2);
  *f << last_.end.x - u[0], last_.end.xdot - u[1];
  jac->resize(2, 3);
  jac->leftCols(2) = last_.jacobian - Mat2::Identity();
  // dP/dp: central differences, step ~ cbrt(eps) relative (truncation and rounding balanced).
  const double d = Tolerances::kForcedBranchDifference * std::max(1.0, std::abs(u[2]));
  ForcedRun plus, minus;
  ForcedParams qp = base_, qm = base_;
  SetAxis(qp, axis_, u[2] + d);
  SetAxis(qm, axis_, u[2] - d);
  if (!ValidationError(qm).empty()) qm = q;  // one-sided at the domain's edge
  if (!End(qp, z, false, &plus, why) || !End(qm, z, false, &minus, why)) return false;
  const double span = GetAxis(qp, axis_) - GetAxis(qm, axis_);
  (*jac)(0, 2) = (plus.end.x - minus.end.x) / span;
  (*jac)(1, 2) = (plus.end.xdot - minus.end.xdot) / span;
  // Where the map jumps within the step (a stick phase of finite length born
  // or lost, mu_s > mu_k), the side with other events gives a slope of
  // jump / step: then the side that keeps them (measured: 6e-6 from a jump,
  // dP/dp = 9e3 made the corrector accept points with residual 1e-5 as
  // stalled, issue 20). At a kink (slopes of one size) the central
  // difference stays: it turns the branch's corners.
  auto same = [&](const ForcedRun& r) {
    return r.sticks == last_.sticks && r.exits == last_.exits && r.crossings == last_.crossings;
  };
  const double hp = GetAxis(qp, axis_) - u[2], hm = u[2] - GetAxis(qm, axis_);
  if (same(plus) == same(minus) || !(hp > 0 && hm > 0)) return true;
  const Eigen::Vector2d sp((plus.end.x - last_.end.x) / hp, (plus.end.xdot - last_.end.xdot) / hp);
  const Eigen::Vector2d sm((last_.end.x - minus.end.x) / hm,
                           (last_.end.xdot - minus.end.xdot) / hm);
  const Eigen::Vector2d& keep = same(plus) ? sp : sm;
  const double inf = (sp - sm).lpNorm<Eigen::Infinity>();
  if (inf > Tolerances::kJumpSlopeRatio * (1 + keep.lpNorm<Eigen::Infinity>())) jac->col(2) = keep;
  return true;
}

ForcedBranchRow StrobeProblem::Row() const {
  ForcedBranchRow r;
  r.p = last_u_[2];
  r.x0 = last_u_[0], r.xdot0 = last_u_[1];
  r.m = o_.m;
  r.sticks = last_.sticks;
  r.crossings = last_.crossings;
  r.extrema = last_.extrema;
  Multipliers(last_.jacobian, r.multipliers);
  r.stable = std::abs(r.multipliers[0]) < 1;
  return r;
}

}  // namespace forced_detail
}  // namespace stickslip
