// The one place where the library's numerical thresholds are defined. Every
// threshold a computation uses is a field here, derived from the user's rtol
// and atol (or a documented absolute floor); no other file holds a bare
// threshold literal (issue 19). docs/theory.md lists them.
#pragma once

#include <algorithm>
#include <cmath>

#include "numerics/tolerances_fixed.hpp"

namespace stickslip {

// FixedTolerances (tolerances_fixed.hpp): the rtol-free constants of the
// estimates, the forced oscillator's rounding and the iteration caps.
struct Tolerances : FixedTolerances {
  double rtol = 1e-10;
  double atol = 1e-13;

  static Tolerances From(double rtol, double atol) {
    Tolerances t;
    t.rtol = rtol;
    t.atol = atol;
    return t;
  }

  // --- Integration, events and orbits (flow, steppers, shooting) ---
  // Rounding-level windows are multiples of the unit roundoff; they scale
  // with max(1, |t|) (times) or the state's size, never with rtol.
  static constexpr double kEps = 2.2e-16;  // the unit roundoff DBL_EPSILON, rounded

  /// The tolerances the tools accept (FlowOptions::ValidationError): rtol in
  /// [kRtolMin, kTolMax], atol in [kAtolMin, kTolMax]; the Flow itself takes
  /// rtol down to kFlowRtolMin. CVODE needs rtol >= kCvodeRtolMin and atol >=
  /// kCvodeAtolMin (below, CVODE stalls).
  static constexpr double kRtolMin = 1e-14, kAtolMin = 1e-16, kTolMax = 1e-2;
  static constexpr double kFlowRtolMin = 1e-16;
  static constexpr double kCvodeRtolMin = 1e-13, kCvodeAtolMin = 1e-15;
  /// The flow's stop time advances in chunks this long: CVODE needs a finite
  /// stop time, and t + 1e9 keeps 1e-7 resolution in t.
  static constexpr double kStopTimeChunk = 1e9;
  /// An output time within this of a segment start is the switch's sample
  /// there (about 45 eps: a switch time carries a few roundings).
  static double OutputAtStart(double t) { return 1e-14 * Scale(t); }
  /// A root within this of the segment start is the start surface, to
  /// rounding, not an event (about 4500 eps: a root at the start, located
  /// by a stepper after a restart, is off by a few steps' roundings).
  static double EventAtStart(double t) { return 1e-12 * Scale(t); }
  /// A start in stick lies on its surface and within (or on) its static
  /// limit to this (kEventRounding of the contact's scale).
  static double StickStart(double speed, double limit) {
    return kEventRounding * (1 + std::abs(speed) + std::abs(limit));
  }
  /// A slipping contact past its surface at a switch by up to this many
  /// StickStart bands lost its root to rounding (it arrives then); farther
  /// past, an event was lost and the run fails.
  static constexpr double kLostEventBand = 1e3;
  /// Roots at one instant, to this: the same root again (64 eps).
  static double RootRepeat(double t) { return 64 * kEps * Scale(t); }
  /// A stepper's stop time (and a root at the step end) within this of t:
  /// reached (about 3.6 eps).
  static double StepEndRounding(double t) { return 8e-16 * Scale(t); }
  /// Dense output accepts t this far outside the last step (about 1.8 eps).
  static double DenseOutputSlack(double t) { return 4e-16 * Scale(t); }
  /// The step of a Taylor series whose higher coefficients all vanish (at
  /// rest exactly): any finite length, bounded so the stop time still comes.
  static constexpr double kTaylorRestStep = 1e3;
  /// Taylor orders above Jorba & Zou's p for the seed law's recurrences
  /// (TaylorField::ExtraOrder): at order p + 6 with the step that keeps JZ's
  /// error per step, an orbit takes 10 steps instead of 18 (docs/benchmarks.md).
  static constexpr int kTaylorExtraOrderCubic = 6;
  /// A root function exactly 0 is biased by this (CVODE's root finder
  /// needs a sign): smaller than any state, so it moves no root.
  static constexpr double kRootZeroBias = 1e-300;
  /// At rest on steady sliding: |x'| within this. Integration noise is ~atol
  /// in x' (10 atol), never below rounding of the scale (64 eps scale).
  double RestBandVelocity(double scale) const { return RestBandVelocity(scale, atol); }
  static double RestBandVelocity(double scale, double atol) {
    return std::max(64 * kEps * scale, 10 * atol);
  }
  /// At rest: |x''| within this. x'' = -x + mu(v) is a difference of nearly
  /// equal terms of size scale, so its noise is ~atol + rtol scale.
  double RestBandAcceleration(double scale) const {
    return RestBandAcceleration(scale, rtol, atol);
  }
  static double RestBandAcceleration(double scale, double rtol, double atol) {
    return std::max(64 * kEps * scale, 10 * (atol + rtol * scale));
  }

  /// Pure-slip shooting (seed section 4): a Newton step on the section
  /// amplitude a is polished once more while above the integration noise,
  /// 0.1 rtol max(1, a) (a tenth: the polish then cannot be the error).
  double ShootingPolish(double a) const { return 0.1 * rtol * Scale(a); }
  /// Pure-slip shooting: an amplitude below this has collapsed onto the
  /// equilibrium (at the defaults 1e3 rtol; the section is then noise).
  static constexpr double kCollapsedAmplitude = 1e-10;
  /// Pure-slip scan: the sign change of G is bisected to this, relative to
  /// the bracket end (Newton polishes it afterwards to newton_tol).
  static constexpr double kScanBracket = 1e-9;
  /// Newton stall (numerics/stall.hpp): from the third iteration, a step
  /// within kStallBand of the tolerance that no longer halves is the noise
  /// floor (Deuflhard 2004, section 2.1: monotonicity test, ratio 1/2).
  static constexpr double kStallBand = 1e3;
  static constexpr double kStallRatio = 0.5;
  static constexpr int kStallFirstIteration = 3;

  /// Pure-slip shooting: an amplitude past this factor times max(a_guess,
  /// v + mu_s + 1) is implausible (|x'| < v + a bit bounds a pure-slip orbit).
  static constexpr double kPlausibleAmplitude = 10;
  /// Pure-slip shooting: a first guess that sticks shrinks by this factor
  /// (1 %: the largest slipping amplitude is usually near the guess).
  static constexpr double kStickShrink = 0.99;
  /// Pure-slip shooting: a Newton step may shrink a to this fraction at most
  /// (keeps a > 0, the section right of the equilibrium).
  static constexpr double kMinAmplitudeRatio = 0.2;
  static constexpr double kMaxAmplitudeDrop = 0.8;  // 1 - kMinAmplitudeRatio
  /// Orbit scan: G's integration noise is this times rtol (1 + |xbar| + a) / a
  /// (three digits of margin over one return's error).
  static constexpr double kScanNoise = 1e3;
  /// Orbit scan: a sign change of G is located (Brent) to this relative to a.
  static constexpr double kScanRoot = 1e-10;
  /// Orbit scan: two orbits whose amplitudes agree to this (relative to
  /// max(1, a)) are one (Newton leaves them within newton_tol).
  static constexpr double kSameOrbit = 1e-7;
  /// Orbit scan: the smallest sticking amplitude is bisected to this.
  static constexpr double kStickingBisection = 1e-10;

  /// Event roots on a step polynomial (poly_roots.cpp): rounding of the
  /// Bernstein conversion and halvings, a few ulp of scale per degree.
  static double PolyMargin(int degree, double scale) { return 2.0 * (degree + 1) * kEps * scale; }
  /// The quadratic and cubic bounds (poly_roots.hpp) square coefficients:
  /// they judge only a polynomial whose sum |c_k| lies within these, where no
  /// product of two of them that matters overflows or underflows.
  static bool PolyBoundsApply(double scale) { return scale >= 1e-100 && scale <= 1e100; }
  /// An interval of u in [0, 1] this narrow is one point (about 1.8 eps).
  static double PolyWidth(double u) { return 4e-16 * Scale(u); }
  /// Newton on a step polynomial stops at a step below this (quadratic
  /// convergence leaves an error far below rounding).
  static constexpr double kPolyNewtonStep = 1e-9;
  /// The probe left of a Newton root that checks the sign change (3.6 eps,
  /// plus an absolute 1e-17 for u near 0).
  static double PolyProbe(double u) { return 8e-16 * Scale(u) + 1e-17; }

  static double Scale(double t) { return std::max(1.0, t < 0 ? -t : t); }
  /// Flow, slip leaving x' = v at a stick exit: x'' there below this
  /// times the state's scale is rounding (64 machine epsilons; rtol-free).
  static constexpr double SurfaceRounding() { return 64 * 2.220446049250313e-16; }

  // --- Continuation, charts and basins ---
  /// PALC corrector stopping tolerance: max(1e-13, 10 rtol) (issue 23).
  double Corrector() const { return std::max(1e-13, 10 * rtol); }
  /// A branch is on a range end when within on_end * scale of it (a floor
  /// near the double precision of p, not a tolerance).
  double on_end = 1e-13;
  /// Chart start points: Brent on a sample line to chart_root times its
  /// length (rounding of the line's parameter).
  double chart_root = 1e-13;
  /// HB curves: corrector tolerance (exact derivatives: Newton converges to
  /// rounding).
  double hopf_corrector = 1e-15;
  /// Other chart curves (GR): corrector tolerance on the scaled update
  /// (TraceOptions::tol's default; the point returned is the one before the
  /// last update, so this bounds its error).
  double chart_corrector = 1e-12;
  /// Codimension-two points within same_point times the rectangle's size are
  /// one point (found again from the other side of a curve).
  double same_point = 1e-8;
  /// Step of an LP curve beside its GH point: section amplitude of its first
  /// point (a^2 ~ distance from GH).
  double fold_start_amplitude = 0.02;
  /// Chart grazing and fold chords: forward-difference step in the plane,
  /// times the rectangle's size (about sqrt of the map's error at rtol 1e-11
  /// ... 1e-14).
  double chart_difference = 1e-7;
  /// System chart: two curves of one kind and period within this fraction of
  /// the rectangle are one (a seed found again on another seed line).
  double chart_same_curve = 2e-3;
  /// System chart: two GR curves of one period whose inner ends lie within
  /// this fraction of the rectangle meet at a double grazing (GG; seed_forced:
  /// 8e-7 apart, two touches of x' = v at once).
  double chart_double_grazing = 1e-4;
  /// System chart curves: a section point within this of x' = v is near the
  /// stick phase (the map is not smooth there): the section moves on.
  double curve_section_near_stick = 1e-3;
  /// Chart curves of orbits (any system): an accepted point's residual (orbit and test
  /// function, max norm) above this is no root: the way ends there.
  double curve_residual = 1e-8;
  /// The one chart's bound on an accepted point's residual: curve_residual, or
  /// 1e3 rtol where the flow's own error is larger (the test is a product of
  /// multipliers from a run at rtol).
  double CurveResidual() const { return std::max(curve_residual, 1e3 * rtol); }
  /// System chart curves: an accepted point whose corrector moved it more
  /// than this times the step off the predictor (scaled, across the last
  /// tangent) left the branch: the way ends there (on the seed_forced chart
  /// curves stay below 0.23, jumps measured 7.2 to 972: docs/limits.md).
  double curve_branch_offset = 0.5;
  /// System chart curves: the end of a curve where it leaves its branch
  /// (a sliding point), bisected on the last step to this (scaled arclength).
  double chart_end_bisection = 1e-10;
  /// System chart curves: an m orbit whose point comes back after d < m
  /// periods to within this (max norm) has period d: no m curve there.
  double curve_lower_period = 1e-6;
  /// System chart curves: the corrector's tolerance on the scaled update,
  /// max(1e-11, 10 rtol) (the differenced Jacobian's noise; 1e-12 stalled).
  double SystemCurveCorrector() const { return std::max(1e-11, 10 * rtol); }
  /// Basins: a start within on_belt * (1 + v) of x' = v is on the belt
  /// surface (rounding of the start's coordinates).
  double on_belt = 1e-12;
  /// Basins: a capped run within SteadySnap() of stable steady sliding, in x
  /// and in x' (absolute), ended on it: 1e4 atol (1e-9 at the default atol).
  double SteadySnap() const { return 1e4 * atol; }
  /// Chart curves: smallest PALC step, times max_step.
  double chart_min_step = 1e-6;
  /// A chart curve's start on the border: a way leaves the rectangle if a
  /// step of border_probe (scaled) along it does.
  double border_probe = 1e-6;
  /// A start point within near_curve of a traced curve (scaled by the
  /// rectangle) is on it.
  double near_curve = 2e-3;
  /// Chart regions, the section map iterated from the exit point: decayed
  /// below map_decay a0, settled within map_settle a0 (a0 its first amplitude).
  double map_decay = 1e-3, map_settle = 1e-7;
  /// A pure-slip Newton that ends at an amplitude below on_equilibrium
  /// (mu_s + v) ended on steady sliding.
  double on_equilibrium = 1e-6;
  /// Parameters within same_p max(1, range) of a stick-slip span are in it.
  double same_p = 1e-12;
  /// Pure-slip rows at one p whose amplitudes agree within same_amplitude
  /// max(1, a) are one row.
  double same_amplitude = 1e-6;
  /// Orbit branches: a slip phase shorter than this fraction of the orbit's
  /// period at a located sliding point is the one adding-sliding creates
  /// (its length grows like sqrt(|p - p*|) <= 1e-5 within 1e-10; issue 20).
  double VanishingPhase() const { return 1e-4; }
  /// Orbit branches: a crossing of x' = v this close to the stick band's edge
  /// (times 1 + the orbit's width) is on it at a located sliding point.
  double BandEdge() const { return std::max(1e-8, 1e3 * rtol); }
  /// Basins on a section (basin/attractors.hpp): section points of one
  /// periodic cycle agree to this, relative to 1 + |z|: max(1e-6, 1e3 rtol).
  double SectionCycle() const { return std::max(1e-6, 1e3 * rtol); }
  /// ... and two periodic attractors are one if their points agree to max(1e-4, 1e5 rtol).
  double SameAttractor() const { return std::max(1e-4, 1e5 * rtol); }
  /// A start is chaotic if its largest exponent exceeds max(3 err, this floor) (1 / time).
  double ChaoticExponentFloor() const { return 1e-3; }
  /// PD switching: the point's multiplier must lie within this of -1
  /// (a located PD has it within 1e-9; issue 20).
  double FlipMultiplier() const { return 1e-3; }
  /// PD switching: the first point of the doubled branch is on it (not
  /// back on the m orbit) if |P^m z - z| exceeds this times the offset h.
  double DoubledSplit() const { return 0.5; }
  /// Orbit branches: one-sided slopes of P^m in p that differ by more than
  /// this times (1 + the kept one) straddle a jump of the map, not a kink.
  static constexpr double kJumpSlopeRatio = 100;

  // Continuation steps (continuation/: the branch tracers share these).
  // Steps of a stick-slip branch: halve when an orbit measure changes by more
  // than kHalveAbove * max_step, grow by kGrow when it changes by less than
  // kGrowBelow * max_step.
  static constexpr double kHalveAbove = 5, kGrowBelow = 2, kGrow = 1.5;
  // A pure-slip branch ends at a Hopf point below this section amplitude (closer,
  // shooting loses accuracy), if a Hopf point lies within kNearHopf * range or
  // within kHopfSlack times the distance to where a^2, extrapolated linearly,
  // vanishes. A step that would end it from above kHopfFrom * kAmplitudeEnd is
  // halved instead.
  static constexpr double kAmplitudeEnd = 0.02, kNearHopf = 0.05, kHopfSlack = 2, kHopfFrom = 2;
  // Pure-slip corrector: at most kMaxCorrector Newton steps (stall test:
  // NewtonConverged in palc.hpp); the step grows (kGrow) after a correction in
  // at most kFastCorrector steps.
  static constexpr int kMaxCorrector = 8, kFastCorrector = 3;
  // A row is read at its p: one more Newton step in a at fixed p when the
  // amplitude's correction -G / G_a exceeds kPolish * rtol * max(1, a).
  static constexpr double kPolish = 0.1;
  // A pure-slip step that sticks looks for a grazing point when the last orbit
  // came within kNearTouch * max(kNearTouchMin, v) of the belt speed, or the
  // step is within kSmallStep * min_step; the search grows by kSearchGrow over
  // at most kSearchSteps steps.
  static constexpr double kNearTouch = 0.1, kNearTouchMin = 0.05, kSmallStep = 4, kSearchGrow = 1.5;
  static constexpr int kSearchSteps = 12;
  // Grazing points closer than kSameGrazing * locate_tol are the same point.
  static constexpr double kSameGrazing = 1e3;
  // Probes beside a grazing point, as max(fraction * range, factor * locate_tol):
  // stick-slip side, pure-slip side. The pure-slip probe also stays
  // kSlipProbeRtol * rtol * range away: the grazing point is the gap's root, the
  // probe a shooting, and the two place the touch as far apart as their
  // integration errors (8e-5 in v for stribeck, cvode, rtol 1e-4).
  static constexpr double kStickProbe = 1e-6, kStickProbeTol = 10;
  static constexpr double kSlipProbe = 1e-4, kSlipProbeTol = 100, kSlipProbeRtol = 10;
  // Smallest scale of p-steps, relative to max(1, |p|) (BranchContext::LocalScale).
  static constexpr double kMinScale = 1e-3;
  // Landing on a range end: the step guess never below this amplitude.
  static constexpr double kLandMinAmplitude = 1e-3;
  // A stick-slip branch within kAtRangeEnd max(1, |p|) of its end is there (5 eps).
  static constexpr double kAtRangeEnd = 1e-15;
  // Pure-slip dG/dp: forward-difference step max(this, sqrt(rtol)) (scaled).
  static constexpr double kBranchDifferenceFloor = 1e-7;
  // LP on a branch (special_points.cpp): the slip field's fold is a jump when
  // wider than kFoldJump (1 + |x0|); p(a) by a secant from a step of
  // kFoldSecantStep to kFoldSecantTol (times the p scale); the fold's amplitude
  // by Brent to kFoldAmplitudeTol max(1, |a|).
  static constexpr double kFoldJump = 1e-9, kFoldSecantStep = 1e-6, kFoldSecantTol = 1e-14;
  static constexpr double kFoldAmplitudeTol = 1e-7;
  // Chart curves, finite differences: HB curve d/dp of a law parameter, step
  // kHopfDifference max(|p|, kHopfDifferenceFloor); LP curve d/da, step
  // kFoldAmplitudeStep max(a, kFoldAmplitudeFloor) (the plane: chart_difference).
  static constexpr double kHopfDifference = 1e-6, kHopfDifferenceFloor = 1e-3;
  static constexpr double kFoldAmplitudeStep = 1e-4, kFoldAmplitudeFloor = 1e-2;
  // Chart GR-HB points (grazing_curve.cpp): Newton2 in the plane to this, with
  // difference steps of kGrazingNewtonStep.
  static constexpr double kGrazingNewtonTol = 1e-12, kGrazingNewtonStep = 1e-6;
  // Chart region faces, in the unit square: vertices within kFaceSnap are one;
  // segments whose cross product is below kFaceParallel |a||b| are parallel
  // (ends snap as vertices), below kFaceCollinear |a||b| collinear; a segment
  // shorter than kSegmentMinLength is none.
  static constexpr double kFaceSnap = 1e-9, kFaceParallel = 1e-14, kFaceCollinear = 1e-12;
  static constexpr double kSegmentMinLength = 1e-12;
  // Chart segments: a polyline end within kEndSnap (of the rectangle's sides)
  // of the border or of another end is joined to it (chart_segments.hpp).
  static constexpr double kEndSnap = 2e-3;
  // ContinuationOptions::locate_tol must lie in (0, kLocateTolMax).
  static constexpr double kLocateTolMax = 1e-3;

  // --- Limits round two: the decimal-form thresholds (scripts/check_limits.py) ---
  // PALC: a last chord within kClosedCurveGap chord lengths of the first point closes the curve.
  static constexpr double kClosedCurveGap = 0.1;
  // Shooting: a Newton step over kNewtonCap (1 + |z|) is cut to it (damped Newton).
  static constexpr double kNewtonCap = 0.5;
  // Shooting: Newton's evaluations seek the orbit's extremes once an update is below
  // kSeekExtrema sqrt(tol) (1 + |z|): quadratic convergence then ends within about two more.
  static constexpr double kSeekExtrema = 100;
  // Batched stroboscopic orbits: a fixed point of P^m is one of P^d if P^d moves it by at most
  // kLeastPeriod (1 + |z|) (the Newton tolerance's 1e-12 times the map's error growth).
  static constexpr double kLeastPeriod = 1e-8;
  // Their transient runs at this rtol and atol (at least): it only has to bring the run within
  // the recurrence tolerance (1e-3) of the attractor; the orbit is then shot at full accuracy.
  static constexpr double kSettle = 1e-8;
  // Chart regions: a section-map run still above kRegionLive a0 after its cap oscillates.
  static constexpr double kRegionLive = 0.5;
};

}  // namespace stickslip
