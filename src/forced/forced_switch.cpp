// Branch switching at a period doubling (branch.hpp, ContinueDoubled): at a
// flip of P^m the 2-cycles of P^m bifurcate as a pitchfork of P^2m, tangent
// to the flip eigenvector e (Kuznetsov, Elements of Applied Bifurcation
// Theory, 3rd ed., section 4.4); AUTO-07p starts the doubled branch the same
// way (ISW = -1 at a PD label, Doedel et al., AUTO-07p manual, section 10.6).
#include <cmath>
#include <string>

#include "forced_branch_problem.hpp"
#include "numerics/numbers.hpp"
#include "numerics/tolerances.hpp"
#include "stickslip/errors.hpp"

namespace stickslip {

namespace {

using Eigen::VectorXd;

// The eigenvector of the real eigenvalue of M nearest to -1 (unit, in x, x'),
// and that eigenvalue.
double FlipVector(const Mat2& M, Eigen::Vector2d* e) {
  Eigen::EigenSolver<Mat2> es(M);
  int k = 0;
  for (int i = 1; i < 2; ++i)
    if (std::abs(es.eigenvalues()[i] + 1.0) < std::abs(es.eigenvalues()[k] + 1.0)) k = i;
  *e = es.eigenvectors().col(k).real().normalized();
  return es.eigenvalues()[k].imag() == 0 ? es.eigenvalues()[k].real() : NAN;
}

ForcedBranch Failed(const std::string& why) {
  ForcedBranch b;
  b.status = ForcedBranchStatus::kStartFailed;
  b.message = why;
  return b;
}

}  // namespace

ForcedBranch ContinueDoubled(const ForcedParams& at_pd, ForcedAxis axis, double x0, double xdot0,
                             double lo, double hi, const ForcedBranchOptions& options) {
  if (const std::string e = ValidationError(at_pd); !e.empty()) throw InvalidArgument(e);
  const double p_pd = GetAxis(at_pd, axis);
  if (!(lo < p_pd && p_pd < hi) || !std::isfinite(lo) || !std::isfinite(hi))
    throw InvalidArgument("ContinueDoubled: the bounds must be finite with lo < " + Num(p_pd, 12) +
                          " < hi");
  if (const std::string e = options.palc.ValidationError(3); !e.empty()) throw InvalidArgument(e);
  if (const std::string e = options.ValidationError(); !e.empty()) throw InvalidArgument(e);
  if (!(std::isfinite(x0) && std::isfinite(xdot0)))
    throw InvalidArgument("x0 = " + Num(x0) + ", xdot0 = " + Num(xdot0) + ": both must be finite");
  // The flip direction from DP^m at the point.
  const ForcedModel model(at_pd);
  ForcedRequest rq;
  rq.t_end = options.m * model.period();
  rq.variational = true;
  const ForcedRun run = ForcedFlow(model, options.flow).Run(ForcedStart(model, 0, x0, xdot0), rq);
  if (run.status != ForcedStatus::kReached) return Failed("the PD orbit: " + run.message);
  Eigen::Vector2d e;
  const double mu = FlipVector(run.jacobian, &e);
  const Tolerances tol = Tolerances::From(options.flow.rtol, options.flow.atol);
  if (!(std::abs(mu + 1) <= tol.FlipMultiplier()))
    return Failed("no multiplier at -1 at " + std::string(ForcedAxisName(axis)) + " = " +
                  Num(p_pd, 12) + " (nearest " + Num(mu, 6) + "): not a period doubling");
  // The first doubled orbit: z + h e, its projection on e held, p free.
  ForcedBranchOptions doubled = options;
  doubled.m = 2 * options.m;
  forced_detail::StrobeProblem problem(at_pd, axis, doubled);
  Palc palc(problem, doubled.palc);
  const VectorXd scale = doubled.palc.scale.size() ? doubled.palc.scale : VectorXd::Ones(3);
  const Eigen::Vector3d z(x0, xdot0, p_pd);
  Eigen::Vector3d t(e[0], e[1], 0);
  const double h = doubled.palc.ds;
  const Eigen::Vector3d pred = z + h * t.cwiseProduct(scale);
  const PalcCorrection c = palc.Correct(pred, t.normalized());
  if (!c.ok) return Failed("the first 2m orbit did not converge: " + c.why);
  // On the doubled branch P^m z' != z' (the two points of the 2-cycle).
  ForcedParams q = at_pd;
  SetAxis(q, axis, c.u[2]);
  const ForcedModel mq(q);
  rq.t_end = options.m * mq.period();
  rq.variational = false;
  const ForcedRun half = ForcedFlow(mq, options.flow).Run(ForcedStart(mq, 0, c.u[0], c.u[1]), rq);
  const double split = std::hypot(half.end.x - c.u[0], half.end.xdot - c.u[1]);
  if (half.status != ForcedStatus::kReached || !(split > tol.DoubledSplit() * h))
    return Failed("the first 2m orbit fell back onto the m orbit at " +
                  std::string(ForcedAxisName(axis)) + " = " + Num(c.u[2], 12));
  // Away from the m orbit, holding the component of e that moves most.
  const Eigen::Vector3d u1 = c.u;
  const int fixed = std::abs(e[0]) >= std::abs(e[1]) ? 0 : 1;
  const Eigen::Vector3d away = (u1 - z).cwiseQuotient(scale);
  const double to = u1[2] >= p_pd ? hi : lo;
  return forced_detail::TraceBranch(at_pd, axis, p_pd, to, u1, fixed, away, doubled);
}

}  // namespace stickslip
