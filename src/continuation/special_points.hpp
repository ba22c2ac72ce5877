// Special points of a one-parameter family as plain functions: the test
// function that vanishes there, its locator on a bracket, and the record.
//   HB  Hopf point of steady sliding: 2 beta + mu'(v) = 0 (linearised seed eq. 3.5);
//   GR  grazing-sliding: the slip phase from the exit point (x0, v) touches
//       x' = v without crossing (seed, case 1; di Bernardo et al. 2008);
//   LP  fold of a solution curve G(a, p) = 0: an extremum of p(a).
#pragma once

#include <functional>
#include <string>

#include "numerics/roots.hpp"
#include "stickslip/continuation/continuation.hpp"
#include "stickslip/orbits/orbit.hpp"
#include "stickslip/systems/belt/parameter_axis.hpp"

namespace stickslip {

/// 2 beta + mu'(v): the damping of steady sliding, > 0 where it is stable.
double HopfDamping(const Params& p);
/// The Hopf point between p0 and p1 on the axis (Brent), given the damping
/// d0, d1 at the ends with d0 d1 <= 0. ok is false without a sign change.
RootResult LocateHopf(const Params& base, const ParameterAxis& axis, double p0, double p1,
                      double d0, double d1, double tol);
RootResult LocateHopf(const Params& base, const ParameterAxis& axis, double p0, double p1,
                      double tol);
/// HB at p: steady sliding with lambda = +-i, so period 2 pi, multiplier 1;
/// supercritical when mu''' > 0.
SpecialPoint HopfPoint(const Params& at, double p);

/// Grazing test function at p (OrbitFinder::GrazingGap, with p's model): the
/// largest x' on the first return from (x0, v), switching ignored, minus v.
/// False if the integration fails.
bool GrazingGap(OrbitFinder& finder, const Params& at, double* gap);
/// The grazing point between p_in and p_out (Brent on GrazingGap), given the
/// gap at both ends. ok is false without a sign change or if a gap fails.
RootResult LocateGrazing(OrbitFinder& finder, const Params& base, const ParameterAxis& axis,
                         double p_in, double p_out, double gap_in, double gap_out, double tol);
/// Where the grazing orbit (the first-return run from the exit point, stopped
/// at its largest x') touches x' = v: at the exit point (x0, v) a pure-slip
/// orbit continues the branch; strictly inside the stick band (the coulomb
/// law, whose slip field jumps at the exit: the fold x = mu_k - 2 beta v of
/// the slip field) nothing is born and the orbit disappears.
bool GrazesInsideStickBand(const Model& m, const FlowResult& run);
/// GR at p from that run (variational), the same whichever way the branch
/// reached it: multiplier_before is the stick-slip side's (0), multiplier_after
/// the pure-slip side's, det of the run's Jacobian (Liouville), or nan where
/// the orbit disappears; period and extent include the stick from the touch to
/// the exit point.
SpecialPoint GrazingPoint(const Model& m, double p, const FlowResult& run);

/// LP at p, described by `what`, with the orbit's extent from run.
SpecialPoint FoldPoint(double p, const FlowResult& run, const std::string& what);
/// The fold of the curve G(a, p) = 0 between two of its points (a0, p0) and
/// (a1, p1) on either side of it: the extremum of p(a) (Brent's fmin), p(a)
/// by a secant on G(a, .) from p_scale 1e-6 apart. minimum: the fold is a
/// minimum of p. False if an evaluation of G fails or fmin does not converge.
using CurveFunction = std::function<bool(double a, double p, double* g)>;
bool LocateFold(const CurveFunction& g, double a0, double p0, double a1, double p1, bool minimum,
                double p_scale, double* a_fold, double* p_fold);

}  // namespace stickslip
