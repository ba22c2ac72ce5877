// Two-parameter curves of periodic orbits (chart/orbit_curve.hpp).
#include "chart/orbit_curve.hpp"

#include <algorithm>
#include <cmath>

#include "numerics/tolerances.hpp"
#include "stickslip/errors.hpp"

namespace stickslip {

using Eigen::MatrixXd;
using Eigen::VectorXd;

namespace {

int TestIndex(CurveKind kind) {
  switch (kind) {
    case CurveKind::kFold:
      return 0;
    case CurveKind::kPeriodDoubling:
      return 1;
    case CurveKind::kTorus:
      return 2;
    default:
      throw InvalidArgument(std::string("a curve of periodic orbits is LP, PD or NS, not ") +
                            Name(kind));
  }
}

}  // namespace

OrbitCurveProblem::OrbitCurveProblem(const System& system, int p1, int p2, const FlowPoint& start,
                                     const PoincareSection& section, CurveKind kind,
                                     const OrbitBranchOptions& options)
    : options_(options),
      orbit_(system, p1, start, section, options_),
      p2_(p2),
      nu_(orbit_.parameter_index()),
      kind_(kind) {
  TestIndex(kind);  // throws for HB, GR
  if (options_.palc.cancelled) orbit_.shooting().flow().set_cancel(options_.palc.cancelled);
}

double OrbitCurveProblem::Test(const OrbitRow& r) const {
  return orbit_detail::RowTest(r, TestIndex(kind_));
}

VectorXd OrbitCurveProblem::Unknowns(const OrbitRow& row, double p2) const {
  VectorXd u(nu_ + 2);
  u.head(nu_ + 1) = orbit_.Unknowns(row.start, row.p);
  u[nu_ + 1] = p2;
  return u;
}

std::string OrbitCurveProblem::DomainError(const VectorXd& u) const {
  if (!u.allFinite()) return "a point that is not finite";
  orbit_.set_held(p2_, u[nu_ + 1]);
  return orbit_.DomainError(u.head(nu_ + 1));
}

bool OrbitCurveProblem::At(const VectorXd& u, VectorXd* r, double* test, std::string* why) {
  *why = DomainError(u);
  if (!why->empty()) return false;
  PeriodicOrbit o;
  if (!orbit_.MapOf(u.head(nu_ + 1), true, r, &o, why)) return false;
  *test = Test(orbit_detail::RowOf(o, u[nu_]));
  return true;
}

bool OrbitCurveProblem::Residual(const VectorXd& u, double* residual, std::string* why) {
  VectorXd r;
  double test = 0;
  if (!At(u, &r, &test, why)) return false;
  *residual = std::max(r.lpNorm<Eigen::Infinity>(), std::abs(test));
  return std::isfinite(*residual);
}

bool OrbitCurveProblem::Sample(const VectorXd& u, OrbitRow* row, double* test, std::string* why,
                               std::vector<ModeSet>* modes) {
  *why = DomainError(u);
  if (!why->empty()) return false;
  PeriodicOrbit o;
  VectorXd r;
  if (!orbit_.MapOf(u.head(nu_ + 1), true, &r, &o, why)) return false;
  *row = orbit_detail::RowOf(o, u[nu_]);
  *test = Test(*row);
  if (modes) *modes = o.modes;
  return true;
}

bool OrbitCurveProblem::Evaluate(const VectorXd& u, VectorXd* f, MatrixXd* jac, std::string* why) {
  *why = DomainError(u);
  if (!why->empty()) return false;
  VectorXd f0;
  MatrixXd j0;
  if (!orbit_.Evaluate(u.head(nu_ + 1), &f0, &j0, why)) {
    last_failure_ = *why, last_status_ = orbit_.last_failure();
    return false;
  }
  f->resize(nu_ + 1);
  f->head(nu_) = f0;
  (*f)[nu_] = Test(orbit_.Row());
  jac->setZero(nu_ + 1, nu_ + 2);
  jac->topLeftCorner(nu_, nu_ + 1) = j0;
  // The test's row and dF/dp2: central differences (one-sided where one
  // side fails: the domain's edge).
  VectorXd rp, rm;
  for (int i = 0; i < nu_ + 2; ++i) {
    const double d = Tolerances::kBranchDifference * std::max(1.0, std::abs(u[i]));
    VectorXd up = u, dn = u;
    up[i] += d, dn[i] -= d;
    double tp = 0, tm = 0;
    std::string wp, wm;
    const bool okp = At(up, &rp, &tp, &wp), okm = At(dn, &rm, &tm, &wm);
    if (!okp && !okm) {
      *why = "the test function's derivative: " + wp;
      DomainError(u);  // p2 back to u's
      return false;
    }
    if (!okp) up = u, tp = (*f)[nu_], rp = f0;
    if (!okm) dn = u, tm = (*f)[nu_], rm = f0;
    const double h = up[i] - dn[i];
    (*jac)(nu_, i) = (tp - tm) / h;
    if (i == nu_ + 1) jac->col(i).head(nu_) = (rp - rm) / h;
  }
  DomainError(u);  // the held p2 back to u's
  return jac->allFinite();
}

}  // namespace stickslip
