// The seed's bounds a1 (3.18) and a2 (3.20) fitted by NLopt; see estimates.hpp.
#include <nlopt.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include "estimates/seed_common.hpp"
#include "stickslip/errors.hpp"
#include "stickslip/estimates/estimates.hpp"

namespace stickslip {
using namespace seed_detail;  // NOLINT: the helpers shared with estimates.cpp
namespace {

void ValidateOptions(const BoundFitOptions& o) {
  if (o.fit_points < 3)
    throw InvalidArgument("fit_points = " + std::to_string(o.fit_points) + " must be >= 3");
  if (o.check_points < o.fit_points)
    throw InvalidArgument("check_points = " + std::to_string(o.check_points) +
                          " must be >= fit_points = " + std::to_string(o.fit_points));
  if (!(o.check_tolerance > 0) || !std::isfinite(o.check_tolerance))
    throw InvalidArgument("check_tolerance = " + Num6(o.check_tolerance) + " must be finite, > 0");
  if (!(o.xtol_abs > 0) || !std::isfinite(o.xtol_abs))
    throw InvalidArgument("xtol_abs = " + Num6(o.xtol_abs) + " must be finite, > 0");
  if (o.max_evaluations <= 0)
    throw InvalidArgument("max_evaluations = " + std::to_string(o.max_evaluations) +
                          " must be > 0");
  if (std::isinf(o.x1_low))
    throw InvalidArgument("x1_low = " + Num6(o.x1_low) + " must be finite (or NaN: 2 r1)");
}

// Move-only owner of an nlopt_opt (nlopt_destroy on scope exit).
using NloptHandle = std::unique_ptr<nlopt_opt_s, decltype(&nlopt_destroy)>;

void CheckNlopt(nlopt_result r, const char* call) {
  if (r < 0) throw ExternalError(std::string(call) + " failed with nlopt_result " + Num6(r));
}

// One scalar a constrained by sampled values w_i of the seed's inequality,
// divided by its positive weight so that every constraint is in units of a:
//   kLower (a1, 3.18): a >= w_i, tightest = smallest a, c_i = w_i - a <= 0;
//   kUpper (a2, 3.20): a <= w_i, tightest = largest a,  c_i = a - w_i <= 0.
enum class Side { kLower, kUpper };
struct Problem {
  Side side;
  const std::vector<double>* w;
  int evaluations = 0;
};
double Violation(Side side, double w, double a) { return side == Side::kLower ? w - a : a - w; }

double Objective(unsigned, const double* x, double* grad, void* data) {
  auto* pr = static_cast<Problem*>(data);
  ++pr->evaluations;
  const double s = pr->side == Side::kLower ? 1.0 : -1.0;  // minimise a, or maximise it
  if (grad) grad[0] = s;
  return s * x[0];
}

void Constraints(unsigned m, double* result, unsigned, const double* x, double* grad, void* data) {
  const auto* pr = static_cast<const Problem*>(data);
  for (unsigned i = 0; i < m; ++i) {
    result[i] = Violation(pr->side, (*pr->w)[i], x[0]);
    if (grad) grad[i] = pr->side == Side::kLower ? -1.0 : 1.0;
  }
}

double WorstViolation(Side side, const std::vector<double>& w, double a) {
  double worst = -HUGE_VAL;
  for (double wi : w) worst = std::max(worst, Violation(side, wi, a));
  return worst;
}

// The check grid, Grid(lo, hi, n) mapped by w, streamed: the same samples
// without the two vectors of n (200001 by default) per fit.
template <class W>
struct CheckGrid {
  double lo, hi;
  int n;
  W w;
  double Worst(Side side, double a) const {
    double worst = -HUGE_VAL;
    for (int i = 0; i < n; ++i) {
      const double x = i == n - 1 ? hi : lo + (hi - lo) * i / (n - 1);
      worst = std::max(worst, Violation(side, w(x), a));
    }
    return worst;
  }
};

// The samples that can bind: every c_i = +-(w_i - a) has the same gradient, so
// a sample more than tol inside the extreme one is implied by it, and dropping
// it leaves the feasible set {a : c_i <= 0 for all i} as it is (an exact presolve;
// NLopt then solves an LP of one or a few rows instead of fit_points rows).
std::vector<double> Binding(Side side, const std::vector<double>& w, double tol) {
  const bool lower = side == Side::kLower;
  const double extreme =
      lower ? *std::max_element(w.begin(), w.end()) : *std::min_element(w.begin(), w.end());
  std::vector<double> kept;
  for (double wi : w)
    if (lower ? wi >= extreme - tol : wi <= extreme + tol) kept.push_back(wi);
  return kept;
}

// NLopt's LD_SLSQP: it takes the m sampled constraints as one vector-valued
// inequality (nlopt_add_inequality_mconstraint) with exact gradients, and since
// objective and constraints are linear in a its QP subproblem is exact, so it
// lands on the active sample in a few iterations. (LN_COBYLA also accepts
// mconstraints but builds linear models from m + 1 evaluations for nothing here.)
template <class W>
BoundFit FitOne(Side side, const std::vector<double>& w_fit, const CheckGrid<W>& check,
                const BoundFitOptions& o) {
  BoundFit fit;
  NloptHandle opt(nlopt_create(NLOPT_LD_SLSQP, 1), &nlopt_destroy);
  if (!opt) throw ExternalError("nlopt_create(NLOPT_LD_SLSQP, 1) returned NULL");
  const std::vector<double> active = Binding(side, w_fit, 0.01 * o.check_tolerance);
  Problem pr{side, &active};
  const std::vector<double> tol(active.size(), 0.01 * o.check_tolerance);
  CheckNlopt(nlopt_set_min_objective(opt.get(), Objective, &pr), "nlopt_set_min_objective");
  CheckNlopt(nlopt_add_inequality_mconstraint(opt.get(), static_cast<unsigned>(active.size()),
                                              Constraints, &pr, tol.data()),
             "nlopt_add_inequality_mconstraint");
  CheckNlopt(nlopt_set_lower_bounds1(opt.get(), 0.0), "nlopt_set_lower_bounds1");  // a >= 0
  CheckNlopt(nlopt_set_xtol_abs1(opt.get(), o.xtol_abs), "nlopt_set_xtol_abs1");
  CheckNlopt(nlopt_set_maxeval(opt.get(), o.max_evaluations), "nlopt_set_maxeval");
  double a = 0.0, f = 0.0;
  const nlopt_result r = nlopt_optimize(opt.get(), &a, &f);
  fit.nlopt_code = r;
  fit.evaluations = pr.evaluations;
  // ROUNDOFF_LIMITED still returns the best point; the feasibility test below judges it.
  if (r < 0 && r != NLOPT_ROUNDOFF_LIMITED) {
    fit.status = BoundStatus::kOptimizerFailed;
    fit.reason = "nlopt_optimize (LD_SLSQP) returned " + Num6(r);
    return fit;
  }
  const double sampled = WorstViolation(side, w_fit, a);
  if (sampled > o.check_tolerance) {
    // c_i grows with a for kUpper: if a = 0 already violates, no a >= 0 satisfies.
    const bool none = side == Side::kUpper && WorstViolation(side, w_fit, 0.0) > 0;
    fit.status = none ? BoundStatus::kNoPositiveBound : BoundStatus::kOptimizerFailed;
    fit.reason =
        none ? "no a > 0 satisfies the sampled inequality (min bound " +
                   Num6(*std::min_element(w_fit.begin(), w_fit.end())) + " <= 0)"
             : "NLopt stopped at a = " + Num6(a) + " violating a sample by " + Num6(sampled);
    return fit;
  }
  if (!(a > o.xtol_abs)) {
    fit.status = BoundStatus::kNoPositiveBound;
    fit.reason = "the optimal a = " + Num6(a) + " is not positive";
    return fit;
  }
  fit.status = BoundStatus::kFitted;
  fit.a = a;
  fit.worst_violation = check.Worst(side, a);
  fit.holds = fit.worst_violation <= o.check_tolerance;
  if (!fit.holds) fit.reason = "check grid violated by " + Num6(fit.worst_violation);
  return fit;
}

}  // namespace

SeedBounds FitSeedBounds(const Params& p, const BoundFitOptions& o) {
  RequireCubic(p);
  ValidateOptions(o);
  SeedBounds b;
  b.roots = ComputeSeedRoots(p);
  if (!b.roots.applies) {
    b.a1.reason = b.a2.reason = b.roots.reason;
    return b;
  }
  const double A = LinearCoefficient(p), k3 = p.k3(), v = p.v;
  const double r1 = b.roots.r1, r2 = b.roots.r2;

  // a1 (3.18): 0 >= x1 h(x1) >= x1 h1^(x1) = -a1 x1^2 on D1 = [r1, v]. The left
  // part holds since h <= 0 on [0, r2] and >= 0 on [r1, 0]. Dividing the right
  // part by x1^2 > 0: a1 >= -h(x1)/x1 = -(A - 3 k3 v x1 + k3 x1^2) (extended to
  // x1 = 0 by continuity). By (3.19) a1 bounds the growth of W from above, so
  // the tightest bound is the SMALLEST such a1.
  auto w1 = [&](double x) { return -(A - 3.0 * k3 * v * x + k3 * x * x); };
  b.a1 = FitOne(Side::kLower, Map(Grid(r1, v, o.fit_points), w1),
                CheckGrid<decltype(w1)>{r1, v, o.check_points, w1}, o);
  b.a1.lo = r1;
  b.a1.hi = v;

  // a2 (3.20): x1 h(x1) > x1 h2^(x1) = -a2 x1 (x1^2 - r1^2) on D2 = {x1 < r1}.
  // Dividing by -x1 (x1^2 - r1^2) > 0: a2 < q(x1) = -h(x1) / (x1^2 - r1^2)
  // = -k3 x1 (x1 - r2) / (x1 + r1) (h = k3 x1 (x1 - r1)(x1 - r2), factor
  // x1 - r1 cancelled, so q extends continuously to x1 = r1). By (3.20) a2 is a
  // decay rate bounding W' from above, so the tightest bound is the LARGEST a2.
  // D2 is unbounded; we sample [x1_low, r1]. Fallback x1_low = 2 r1: the seed
  // estimates x'_min by r1 itself, so 2 r1 leaves a factor-2 margin. (For the
  // cubic law q increases as x1 decreases, so the binding sample is x1 -> r1
  // and a2 = k3 sqrt(D) for any x1_low; the lower end only decides the range.)
  const double x1_low = std::isnan(o.x1_low) ? 2.0 * r1 : o.x1_low;
  const double lo = std::min(x1_low, r1);
  auto w2 = [&](double x) { return -k3 * x * (x - r2) / (x + r1); };
  b.a2 = FitOne(Side::kUpper, Map(Grid(lo, r1, o.fit_points), w2),
                CheckGrid<decltype(w2)>{lo, r1, o.check_points, w2}, o);
  b.a2.lo = lo;
  b.a2.hi = r1;
  if (x1_low >= r1 && b.a2.reason.empty())
    b.a2.reason = "x1_low = " + Num6(x1_low) + " >= r1 = " + Num6(r1) +
                  ": the orbit does not enter D2; fitted at the limit x1 -> r1 alone";
  return b;
}

}  // namespace stickslip
