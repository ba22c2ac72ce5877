// The seed's estimates (section 3) and first-harmonic averaging; see estimates.hpp.
#include "stickslip/estimates/estimates.hpp"

#include <nlopt.h>

#include <algorithm>
#include <boost/math/special_functions/lambert_w.hpp>
#include <cmath>
#include <memory>
#include <vector>

#include "stickslip/errors.hpp"
#include "numerics/numbers.hpp"

namespace stickslip {
namespace {

// Messages give 6 digits (%.6g).
std::string Num6(double x) { return Num(x, 6); }

// Validates p and insists on the cubic law: (3.9)-(3.30) are for it alone.
void RequireCubic(const Params& p) {
  Validate(p);
  if (p.law != LawKind::kCubic)
    throw InvalidArgument(std::string("estimates: law '") + LawName(p.law) +
                          "' is not cubic; the seed's estimates (3.9-3.30) need the cubic law");
  if (p.k5 != 0)
    throw InvalidArgument("estimates: k5 = " + std::to_string(p.k5) +
                          ": the seed's estimates (3.9-3.30) are for the cubic law without k5");
}

// Linear coefficient of h (3.10): 2 beta - k1 + 3 k3 v^2 (the equilibrium's damping).
double LinearCoefficient(const Params& p) {
  return 2.0 * p.beta - p.k1() + 3.0 * p.k3() * p.v * p.v;
}

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

// NLopt's LD_SLSQP: it takes the m sampled constraints as one vector-valued
// inequality (nlopt_add_inequality_mconstraint) with exact gradients, and since
// objective and constraints are linear in a its QP subproblem is exact, so it
// lands on the active sample in a few iterations. (LN_COBYLA also accepts
// mconstraints but builds linear models from m + 1 evaluations for nothing here.)
BoundFit FitOne(Side side, const std::vector<double>& w_fit, const std::vector<double>& w_check,
                const BoundFitOptions& o) {
  BoundFit fit;
  NloptHandle opt(nlopt_create(NLOPT_LD_SLSQP, 1), &nlopt_destroy);
  if (!opt) throw ExternalError("nlopt_create(NLOPT_LD_SLSQP, 1) returned NULL");
  Problem pr{side, &w_fit};
  const std::vector<double> tol(w_fit.size(), 0.01 * o.check_tolerance);
  CheckNlopt(nlopt_set_min_objective(opt.get(), Objective, &pr), "nlopt_set_min_objective");
  CheckNlopt(nlopt_add_inequality_mconstraint(opt.get(), static_cast<unsigned>(w_fit.size()),
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
  fit.worst_violation = WorstViolation(side, w_check, a);
  fit.holds = fit.worst_violation <= o.check_tolerance;
  if (!fit.holds) fit.reason = "check grid violated by " + Num6(fit.worst_violation);
  return fit;
}

// n equally spaced points on [lo, hi], both ends included.
std::vector<double> Grid(double lo, double hi, int n) {
  std::vector<double> x(n);
  for (int i = 0; i < n; ++i) x[i] = lo + (hi - lo) * i / (n - 1);
  x[n - 1] = hi;
  return x;
}

template <class F>
std::vector<double> Map(const std::vector<double>& x, F f) {
  std::vector<double> y(x.size());
  std::transform(x.begin(), x.end(), y.begin(), f);
  return y;
}

// First t > 0 where y' of (3.22) equals r1, or NaN if y' climbs back above v
// after dropping below it (the comparison returns to the belt first) or t > 20 pi.
// y' = e^{a1 t} (v cos t + (a1 v - (1 + a1^2) y0) sin t) is (3.22) differentiated.
double FirstCrossing(double a1, double y0, double v, double r1) {
  auto yd = [&](double t) {
    return std::exp(a1 * t) * (v * std::cos(t) + (a1 * v - (1 + a1 * a1) * y0) * std::sin(t));
  };
  const double dt = 1e-3, t_max = 20 * M_PI;
  bool below = false;
  for (double t = 0; t < t_max; t += dt) {
    const double next = yd(t + dt);
    if (next < v) below = true;
    if (below && next > v) return kNan;
    if (next > r1) continue;
    double lo = t, hi = t + dt;  // yd(lo) > r1 >= yd(hi)
    for (int i = 0; i < 200 && hi - lo > 1e-15; ++i) {
      const double mid = 0.5 * (lo + hi);
      (yd(mid) > r1 ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
  }
  return kNan;
}

// The root s in (-1, 0) of (1 + s) e^{-s} = c, 0 < c < 1: with w = -(1 + s)
// it is w e^w = -c / e, w in (-1, 0), the principal Lambert W branch.
double NegativeRoot326(double c) { return -1.0 - boost::math::lambert_w0(-c / std::exp(1.0)); }

}  // namespace

double SeedH(const Params& p, double z) {
  RequireCubic(p);
  const double k3 = p.k3();
  return LinearCoefficient(p) * z - 3.0 * k3 * p.v * z * z + k3 * z * z * z;  // (3.10)
}

double SeedHPrime(const Params& p, double z) {
  RequireCubic(p);
  const double k3 = p.k3();
  return LinearCoefficient(p) - 6.0 * k3 * p.v * z + 3.0 * k3 * z * z;
}

double SeedEquilibrium(const Params& p) {
  RequireCubic(p);
  return p.mu_s - p.k1() * p.v + p.k3() * p.v * p.v * p.v;
}

double SeedVMax(const Params& p) {
  RequireCubic(p);
  const double num = p.k1() - 2.0 * p.beta;
  return num > 0 ? std::sqrt(num / (3.0 * p.k3())) : kNan;  // (3.16)
}

SeedRoots ComputeSeedRoots(const Params& p, SeedDForm form) {
  RequireCubic(p);
  SeedRoots r;
  r.v_max = SeedVMax(p);
  const double k3 = p.k3(), v = p.v;
  // (3.17); the seed prints 3 k3 v^3, the roots of h (3.10) need 3 k3 v^2.
  const double vpow = form == SeedDForm::kCorrected ? v * v : v * v * v;
  r.d = 1.5 * v * 1.5 * v - (2.0 * p.beta - p.k1() + 3.0 * k3 * vpow) / k3;
  if (!(r.d > 0)) {
    r.reason = "D = " + Num6(r.d) + " <= 0: h has no real roots besides 0";
    return r;
  }
  r.r1 = 1.5 * v - std::sqrt(r.d);
  r.r2 = 1.5 * v + std::sqrt(r.d);
  if (!(r.r1 < 0)) {
    r.reason = "r1 = " + Num6(r.r1) + " >= 0: v = " + Num6(v) +
               " is not below v_max = " + Num6(r.v_max) + " (3.16), the equilibrium is stable";
    return r;
  }
  r.applies = true;
  return r;
}

const char* BoundStatusName(BoundStatus s) {
  switch (s) {
    case BoundStatus::kFitted:
      return "fitted";
    case BoundStatus::kNoPositiveBound:
      return "no-positive-bound";
    case BoundStatus::kNotApplicable:
      return "not-applicable";
    case BoundStatus::kOptimizerFailed:
      return "optimizer-failed";
  }
  return "?";
}

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
                Map(Grid(r1, v, o.check_points), w1), o);
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
                Map(Grid(lo, r1, o.check_points), w2), o);
  b.a2.lo = lo;
  b.a2.hi = r1;
  if (x1_low >= r1 && b.a2.reason.empty())
    b.a2.reason = "x1_low = " + Num6(x1_low) + " >= r1 = " + Num6(r1) +
                  ": the orbit does not enter D2; fitted at the limit x1 -> r1 alone";
  return b;
}

SeedEstimate EstimateSeed(const Params& p, const SeedEstimateOptions& o) {
  RequireCubic(p);
  SeedEstimate e;
  e.bounds = FitSeedBounds(p, o.bounds);
  const double v = p.v, two_beta_v = 2.0 * p.beta * p.v;
  e.x_bar = SeedEquilibrium(p);
  e.x0 = p.mu_s - two_beta_v;  // stick exit (case 1)
  e.y0 = e.x0 - e.x_bar;
  e.y_stick_low = -p.mu_s - two_beta_v - e.x_bar;  // Omega in y
  const SeedRoots& roots = e.bounds.roots;
  if (!roots.applies) {
    e.reason = "roots: " + roots.reason;
    return e;
  }
  const double r1 = roots.r1, y0 = e.y0;
  e.velocity_amplitude = r1;  // section 4: "the negative zero is an estimate of the amplitude"
  const BoundFit& f1 = e.bounds.a1;
  if (f1.status != BoundStatus::kFitted || !f1.holds) {
    e.reason = std::string("a1 ") + BoundStatusName(f1.status) + ": " + f1.reason;
    return e;
  }
  const double a1 = f1.a;
  // After (3.30): the amplitude of (3.22) with e^{a1 t} dropped.
  e.displacement_bound = std::hypot(y0, v - a1 * y0);
  e.x_min_bound = e.x_bar - e.displacement_bound;
  e.x_max_bound = e.x_bar + e.displacement_bound;

  if (o.y1_rule == SeedY1Rule::kSmallA1) {
    // Text after (3.22): y1 ~ sqrt(y0^2 + (v - a1 y0)^2 - r1^2), for a1 << 1.
    const double rad = e.displacement_bound * e.displacement_bound - r1 * r1;
    if (rad < 0) {
      e.reason =
          "y1 (3.22): y0^2 + (v - a1 y0)^2 = " + Num6(e.displacement_bound * e.displacement_bound) +
          " < r1^2 = " + Num6(r1 * r1) + ": the a1 << 1 circle never reaches y' = r1";
      return e;
    }
    e.y1 = std::sqrt(rad);
  } else {
    const double t1 = FirstCrossing(a1, y0, v, r1);
    if (std::isnan(t1)) {
      e.reason = "y1 (3.22): y' returns to v (or t > 20 pi) before reaching r1";
      return e;
    }
    e.y1 = std::exp(a1 * t1) * (y0 * std::cos(t1) + (v - a1 * y0) * std::sin(t1));  // (3.22)
  }

  const BoundFit& f2 = e.bounds.a2;
  if (f2.status != BoundStatus::kFitted || !f2.holds) {
    e.reason = std::string("a2 ") + BoundStatusName(f2.status) + ": " + f2.reason;
    return e;
  }
  const double a2 = f2.a, y1 = e.y1;
  e.c = (1.0 + 2.0 * a2 * y1) * std::exp(-2.0 * a2 * y1);  // (3.26)
  if (!(e.c > 0 && e.c < 1)) {
    e.reason = "c (3.26) = " + Num6(e.c) + " is not in (0, 1): no second crossing of y' = r1";
    return e;
  }
  e.y2 = -y1 / (1.0 + a2 * y1);             // (3.27) as printed
  e.y2_pade = -y1 / (1.0 + 2.0 * a2 * y1);  // the same Pade step with s = 2 a2 y
  e.y2_exact = NegativeRoot326(e.c) / (2.0 * a2);
  // (3.28) with y = 0 and ydot_1 = r1; = r1^2 + (1 - c) / (2 a2^2) > r1^2.
  const double k = (2.0 * a2 * a2 * r1 * r1 + 1.0) / (2.0 * a2 * a2);
  const double ydm2 =
      std::exp(-2.0 * a2 * y1) *
          (r1 * r1 - (2.0 * a2 * y1 + 2.0 * a2 * a2 * r1 * r1 + 1.0) / (2.0 * a2 * a2)) +
      k;
  e.ydot_m = -std::sqrt(std::max(ydm2, 0.0));  // in D2, so below r1 < 0
  e.min_velocity_bound = r1 + e.ydot_m;        // "smallest slip velocity > r1 + ydot_m"

  // (3.30): y3 ~ -sqrt(y2^2 + (r1 - a1 y2)^2 - v^2), from (3.29) with a1 << 1.
  const double rad3 = e.y2 * e.y2 + (r1 - a1 * e.y2) * (r1 - a1 * e.y2) - v * v;
  if (rad3 < 0) {
    e.reason = "y3 (3.30): y2^2 + (r1 - a1 y2)^2 < v^2: the trajectory does not reach y' = v";
    return e;
  }
  e.y3 = -std::sqrt(rad3);
  e.y3_in_stick = e.y_stick_low <= e.y3 && e.y3 <= y0;
  e.applies = true;
  return e;
}

AveragingEstimate EstimateAveraging(const Params& p) {
  RequireCubic(p);
  AveragingEstimate e;
  const double k1 = p.k1(), k3 = p.k3(), v = p.v, two_beta = 2.0 * p.beta;
  e.hopf_speed = SeedVMax(p);
  e.hopf_beta = 0.5 * (k1 - 3.0 * k3 * v * v);  // a_ps = 0 at fixed v
  if (k1 > two_beta) e.grazing_speed = 2.0 * std::sqrt((k1 - two_beta) / (15.0 * k3));
  const double rad = k1 - two_beta - 3.0 * k3 * v * v;
  if (rad >= 0) e.amplitude = 2.0 * std::sqrt(rad / (3.0 * k3));
  if (!(rad > 0)) {
    e.reason = "k1 - 2 beta - 3 k3 v^2 = " + Num6(rad) +
               " <= 0: steady sliding is stable (v >= v_max), no limit cycle";
  } else if (e.amplitude >= v) {
    e.reason = "a_ps = " + Num6(e.amplitude) + " >= v = " + Num6(v) +
               ": the first-harmonic orbit reaches belt speed, so the orbit sticks";
  } else {
    e.applies = true;
  }
  return e;
}

}  // namespace stickslip
