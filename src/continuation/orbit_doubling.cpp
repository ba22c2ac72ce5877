// Branch switching at a period doubling for any system (orbit_branch.hpp,
// ContinueDoubled): at a flip of P the 2-cycles of P bifurcate as a
// pitchfork of P^2, tangent to the flip eigenvector e (Kuznetsov, Elements of
// Applied Bifurcation Theory, 3rd ed., section 4.4); AUTO-07p starts the
// doubled branch the same way (ISW = -1 at a PD label, AUTO-07p manual,
// section 10.6).
#include <Eigen/Eigenvalues>
#include <chrono>
#include <cmath>
#include <memory>
#include <string>

#include "numerics/numbers.hpp"
#include "numerics/tolerances.hpp"
#include "orbit_problem.hpp"
#include "stickslip/errors.hpp"

namespace stickslip {

namespace {

using Eigen::MatrixXd;
using Eigen::VectorXd;

// A start that failed, on the section of twice the period (OrbitBranch::section).
OrbitBranch Failed(const std::string& why, const PoincareSection& doubled) {
  OrbitBranch b;
  b.section = doubled;
  b.status = BranchStatus::kStartFailed;
  b.message = why;
  return b;
}

// The real eigenvector of DP's eigenvalue nearest -1 (unit), and that
// eigenvalue (NaN if it is complex).
double FlipVector(const MatrixXd& dp, VectorXd* e) {
  Eigen::EigenSolver<MatrixXd> es(dp);
  int k = 0;
  for (int i = 1; i < dp.rows(); ++i)
    if (std::abs(es.eigenvalues()[i] + 1.0) < std::abs(es.eigenvalues()[k] + 1.0)) k = i;
  *e = es.eigenvectors().col(k).real().normalized();
  return es.eigenvalues()[k].imag() == 0 ? es.eigenvalues()[k].real() : NAN;
}

// The section of twice the period: twice the turns, the returns or the time.
PoincareSection Doubled(const PoincareSection& s) {
  PoincareSection d = s;
  d.turns *= 2;
  if (s.kind == SectionKind::kTime)
    d.time *= 2;
  else
    d.returns *= 2;
  return d;
}

}  // namespace

OrbitBranch ContinueDoubled(const System& system, int parameter, const FlowPoint& pd,
                            const PoincareSection& section, double lo, double hi,
                            const OrbitBranchOptions& options) {
  orbit_detail::CheckParameter(system, parameter);  // before its value is read
  const double p_pd = system.ParameterValue(parameter);
  if (!(std::isfinite(lo) && std::isfinite(hi) && lo < p_pd && p_pd < hi))
    throw InvalidArgument("ContinueDoubled: the bounds must be finite with lo < " + Num(p_pd, 12) +
                          " < hi");
  {  // the checks at a bound where the system is valid (the branch may not reach the other)
    std::unique_ptr<System> at_hi = system.Clone();
    at_hi->SetParameterValue(parameter, hi);
    orbit_detail::CheckInputs(system, parameter, pd, section,
                              at_hi->ValidationError().empty() ? hi : lo, options);
  }
  const auto start = std::chrono::steady_clock::now();
  const std::string at = system.ParameterName(parameter) + " = " + Num(p_pd, 12);
  const PoincareSection doubled = Doubled(section);
  // The flip direction from DP at the point.
  Shooting shooting(system, options.shooting);
  if (options.palc.cancelled) shooting.flow().set_cancel(options.palc.cancelled);
  VectorXd r;
  PeriodicOrbit orbit;
  if (!shooting.Map(pd, orbit_detail::SectionFor(system, section, pd.z), true, &r, &orbit))
    return Failed("the PD orbit: " + orbit.message, doubled);
  VectorXd e;
  const double mu = FlipVector(orbit.monodromy, &e);
  const auto& fo = options.shooting.flow;
  const Tolerances tol = Tolerances::From(fo.rtol, fo.atol);
  if (!(std::abs(mu + 1) <= tol.FlipMultiplier()))
    return Failed(
        "no multiplier at -1 at " + at + " (nearest " + Num(mu, 6) + "): not a period doubling",
        doubled);
  // The first doubled orbit: z + h e, its projection on e held, p free.
  orbit_detail::OrbitProblem problem(system, parameter, pd, doubled, options);
  Palc palc(problem, options.palc);
  const int nu = problem.parameter_index();
  const VectorXd scale = options.palc.scale.size() ? options.palc.scale : VectorXd::Ones(nu + 1);
  const VectorXd z = problem.Unknowns(pd, p_pd);
  VectorXd t = VectorXd::Zero(nu + 1);
  t.head(nu) = e;
  const double h = options.palc.ds;
  const PalcCorrection c = palc.Correct(z + h * t.cwiseProduct(scale), t.normalized());
  if (!c.ok) return Failed("the first doubled orbit did not converge: " + c.why, doubled);
  // On the doubled branch P z' != z' (the two points of the 2-cycle).
  std::unique_ptr<System> q = system.Clone();
  q->SetParameterValue(parameter, c.u[nu]);
  shooting.set_system(*q);
  FlowPoint zq = pd;
  zq.z.head(nu) = c.u.head(nu);
  const bool mapped =
      shooting.Map(zq, orbit_detail::SectionFor(*q, section, zq.z), false, &r, &orbit);
  if (!mapped || !(r.norm() > tol.DoubledSplit() * h))
    return Failed("the first doubled orbit fell back onto the single orbit at " +
                      system.ParameterName(parameter) + " = " + Num(c.u[nu], 12),
                  doubled);
  // Away from the single orbit, holding the component of e that moves most.
  int fixed = 0;
  e.cwiseAbs().maxCoeff(&fixed);
  const VectorXd away = (c.u - z).cwiseQuotient(scale);
  OrbitBranch out = orbit_detail::TraceBranch(problem, system, parameter, c.u, fixed, away, p_pd,
                                              c.u[nu] >= p_pd ? hi : lo, options);
  out.evaluations += palc.evaluations();
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace stickslip
