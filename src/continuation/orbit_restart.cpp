// A branch from an orbit already computed (orbit_branch.hpp,
// ContinueOrbitsFrom; AUTO-07p's restart at a label, IRS): no Newton with p
// held first, since at a fold DP - I is singular there. The branch's tangent
// is the null vector t of [F_u F_p] (Keller's pseudo-arclength, Kuznetsov
// 2004, section 10.2.2); the first correction holds the component of t that
// moves most, as AUTO's restart does with its stored tangent.
#include <Eigen/SVD>
#include <chrono>
#include <cmath>

#include "numerics/numbers.hpp"
#include "numerics/tolerances.hpp"
#include "orbit_problem.hpp"
#include "stickslip/errors.hpp"

namespace stickslip {

OrbitBranch ContinueOrbitsFrom(const System& system, int parameter, const FlowPoint& start,
                               const PoincareSection& section, double to, int side,
                               const OrbitBranchOptions& options) {
  orbit_detail::CheckInputs(system, parameter, start, section, to, options);
  if (side < -1 || side > 1)
    throw InvalidArgument("ContinueOrbitsFrom: side = " + std::to_string(side) +
                          " must be -1, 0 or 1");
  const auto t0 = std::chrono::steady_clock::now();
  const double from = system.ParameterValue(parameter);
  orbit_detail::OrbitProblem problem(system, parameter, start, section, options);
  if (options.palc.cancelled) problem.shooting().flow().set_cancel(options.palc.cancelled);
  const int k = problem.parameter_index();
  const Eigen::VectorXd u0 = problem.Unknowns(start, from);
  Eigen::VectorXd f;
  Eigen::MatrixXd jac;
  std::string why;
  if (!problem.Evaluate(u0, &f, &jac, &why)) {
    OrbitBranch out;
    out.section = section;
    const bool cancelled = options.palc.cancelled && options.palc.cancelled();
    out.status = cancelled ? BranchStatus::kCancelled : BranchStatus::kStartFailed;
    out.message = "the map fails at the start, " + system.ParameterName(parameter) + " = " +
                  Num(from) + ": " + why;
    return out;
  }
  // t: the right singular vector of the smallest singular value of the
  // k x (k + 1) Jacobian (its null vector on a branch).
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(jac, Eigen::ComputeFullV);
  const Eigen::VectorXd t = svd.matrixV().col(k);
  int fixed = 0;
  t.cwiseAbs().maxCoeff(&fixed);
  const bool fold = std::abs(t[k]) < Tolerances::kFoldTangent;
  const double sign =
      fold && side != 0 ? side * (t[fixed] > 0 ? 1 : -1) : (t[k] * (to - from) > 0 ? 1 : -1);
  const Eigen::VectorXd scale =
      options.palc.scale.size() ? options.palc.scale : Eigen::VectorXd::Ones(k + 1);
  OrbitBranch out = orbit_detail::TraceBranch(problem, system, parameter, u0, fixed,
                                              sign * t.cwiseQuotient(scale), from, to, options);
  out.evaluations += 1;
  if (options.palc.cancelled && options.palc.cancelled() && !Complete(out.status))
    out.status = BranchStatus::kCancelled;  // cut short by the cancel, whatever failed first
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

}  // namespace stickslip
