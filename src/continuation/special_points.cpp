#include "continuation/special_points.hpp"

#include <algorithm>
#include <cmath>

#include "numerics/numbers.hpp"
#include "numerics/tolerances.hpp"

namespace stickslip {

double HopfDamping(const Params& p) { return Model(p).SteadySliding().damping; }

RootResult LocateHopf(const Params& base, const ParameterAxis& axis, double p0, double p1,
                      double d0, double d1, double tol) {
  return FindRoot([&](double q) { return HopfDamping(axis.At(base, q)); }, p0, p1, d0, d1, tol);
}

RootResult LocateHopf(const Params& base, const ParameterAxis& axis, double p0, double p1,
                      double tol) {
  return LocateHopf(base, axis, p0, p1, HopfDamping(axis.At(base, p0)),
                    HopfDamping(axis.At(base, p1)), tol);
}

SpecialPoint HopfPoint(const Params& at, double p) {
  const Model m(at);
  SpecialPoint sp;
  sp.kind = SpecialKind::kHopf;
  sp.p = p;
  sp.period = 2 * M_PI;  // lambda = +-i at the Hopf point
  sp.extrema = Extrema::Point(m.SteadySliding().x, 0.0);
  sp.x_start = sp.extrema.x_min;
  sp.multiplier_before = sp.multiplier_after = 1.0;
  const bool super = m.friction().D3Mu(m.v()) > 0;
  sp.description = std::string("Hopf point of steady sliding (2 beta + mu'(v) = 0), ") +
                   (super ? "supercritical (mu''' > 0)" : "subcritical (mu''' < 0)");
  return sp;
}

bool GrazingGap(OrbitFinder& finder, const Params& at, double* gap) {
  finder.set_model(Model(at));
  *gap = kNan;
  return finder.GrazingGap(gap) == OrbitStatus::kOk;
}

RootResult LocateGrazing(OrbitFinder& finder, const Params& base, const ParameterAxis& axis,
                         double p_in, double p_out, double gap_in, double gap_out, double tol) {
  bool ok = true;
  auto f = [&](double p) {
    double g = kNan;
    const bool fine = GrazingGap(finder, axis.At(base, p), &g);
    ok = ok && fine;
    return fine ? g : kNan;
  };
  RootResult r = FindRoot(f, p_in, p_out, gap_in, gap_out, tol);
  r.ok = r.ok && ok;
  return r;
}

bool GrazesInsideStickBand(const Model& m, const FlowResult& run) {
  // The slip field's fold on x' = v (x'' = 0; x'' falls by 1 per unit x): x0
  // where mu is continuous at s = 0, x0 - (mu_s - mu(0+)) where it jumps. The
  // touch is whichever of the two it is nearer to, at any tolerance: past the
  // midpoint, 2 (x0 - x) > jump (exact, as x0 - x > 0.5 jump was).
  const double x0 = m.ExitPoint()[0];
  const double x_fold = x0 + m.Acceleration(Mode::kSlipBelow, x0, m.v());
  const double jump = x0 - x_fold;
  return jump > Tolerances::kFoldJump * (1 + std::abs(x0)) && 2 * (x0 - run.z[0]) > jump;
}

SpecialPoint GrazingPoint(const Model& m, double p, const FlowResult& run) {
  const bool inside = GrazesInsideStickBand(m, run);
  const double x0 = m.ExitPoint()[0];
  const double mult_ps = run.jacobian.determinant();
  SpecialPoint sp;
  sp.kind = SpecialKind::kGrazing;
  sp.p = p;
  sp.period = run.t + (inside ? (x0 - run.z[0]) / m.v() : 0.0);  // stick, seed eq. (3.6)
  sp.extrema.x_min = std::min(run.extrema.x_min, run.z[0]);
  sp.extrema.x_max = std::max(run.extrema.x_max, x0);
  sp.extrema.xdot_min = run.extrema.xdot_min;
  sp.extrema.xdot_max = m.v();  // the orbit touches the stick set x' = v
  sp.multiplier_before = 0.0;
  sp.multiplier_after = inside ? kNan : mult_ps;
  sp.x_start = x0;
  sp.xdot_start = m.v();
  sp.description = inside ? "grazing inside the stick band at x = " + Num(run.z[0]) +
                                ": the orbit disappears (no periodic orbit beyond)"
                          : "grazing-sliding: stick phase vanishes; multiplier 0 on the "
                            "stick-slip side, " +
                                Num(mult_ps) + " on the pure-slip side";
  return sp;
}

SpecialPoint FoldPoint(double p, const FlowResult& run, const std::string& what) {
  SpecialPoint lp;
  lp.kind = SpecialKind::kFold;
  lp.p = p;
  lp.period = run.t;
  lp.extrema = run.extrema;
  lp.x_start = run.z[0];
  lp.xdot_start = run.z[1];
  lp.description = what;
  return lp;
}

bool LocateFold(const CurveFunction& g, double a0, double p0, double a1, double p1, bool minimum,
                double p_scale, double* a_fold, double* p_fold) {
  bool ok = true;
  // p(a) on the curve by a secant on G(a, .) from the chord's p.
  auto p_of_a = [&](double a) {
    const double t = (a - a0) / (a1 - a0);
    double q0 = p0 + t * (p1 - p0), q1 = q0 + Tolerances::kFoldSecantStep * p_scale;
    double g0 = 0, g1 = 0;
    if (!g(a, q0, &g0) || !g(a, q1, &g1)) {
      ok = false;
      return q0;
    }
    for (int it = 0; it < Tolerances::kFoldSecantCap &&
                     std::abs(q1 - q0) > Tolerances::kFoldSecantTol * p_scale;
         ++it) {
      if (g1 == g0) break;
      const double q2 = q1 - g1 * (q1 - q0) / (g1 - g0);
      q0 = q1;
      g0 = g1;
      q1 = q2;
      if (!g(a, q1, &g1)) {
        ok = false;
        break;
      }
    }
    return minimum ? q1 : -q1;
  };
  const RootResult r = FindMinimum(p_of_a, std::min(a0, a1), std::max(a0, a1),
                                   Tolerances::kFoldAmplitudeTol * std::max(1.0, std::abs(a1)));
  if (!ok || !r.ok) return false;
  *a_fold = r.x;
  *p_fold = minimum ? r.fx : -r.fx;
  return true;
}

}  // namespace stickslip
