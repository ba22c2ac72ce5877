// The seed's estimates (section 3) and first-harmonic averaging; see estimates.hpp.
#include "stickslip/estimates/estimates.hpp"

#include <algorithm>
#include <boost/math/special_functions/lambert_w.hpp>
#include <cmath>
#include <memory>
#include <vector>

#include "estimates/seed_common.hpp"
#include "numerics/numbers.hpp"
#include "numerics/tolerances.hpp"
#include "stickslip/errors.hpp"

namespace stickslip {
using namespace seed_detail;  // NOLINT: the helpers shared with bound_fit.cpp
namespace {

// First t > 0 where y' of (3.22) equals r1, or NaN if y' climbs back above v
// after dropping below it (the comparison returns to the belt first) or t > 20 pi.
// y' = e^{a1 t} (v cos t + (a1 v - (1 + a1^2) y0) sin t) is (3.22) differentiated.
double FirstCrossing(double a1, double y0, double v, double r1) {
  auto yd = [&](double t) {
    return std::exp(a1 * t) * (v * std::cos(t) + (a1 * v - (1 + a1 * a1) * y0) * std::sin(t));
  };
  const double dt = Tolerances::kCrossingStep, t_max = Tolerances::kCrossingHorizon;
  bool below = false;
  for (double t = 0; t < t_max; t += dt) {
    const double next = yd(t + dt);
    if (next < v) below = true;
    if (below && next > v) return kNan;
    if (next > r1) continue;
    double lo = t, hi = t + dt;  // yd(lo) > r1 >= yd(hi)
    for (int i = 0; i < Tolerances::kCrossingBisectionCap && hi - lo > Tolerances::kCrossingWidth;
         ++i) {
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
    e.reason = std::string("a1 ") + Name(f1.status) + ": " + f1.reason;
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
    e.reason = std::string("a2 ") + Name(f2.status) + ": " + f2.reason;
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
