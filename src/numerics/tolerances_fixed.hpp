// The second part of the library's thresholds (numerics/tolerances.hpp):
// absolute constants, free of rtol and atol, that Tolerances inherits (so
// they read Tolerances::kX). docs/theory.md lists them.
#pragma once

#include <cmath>

namespace stickslip {

struct FixedTolerances {
  // --- Estimates, model bounds and the forced oscillator's rounding ---
  // Seed estimates (estimates.cpp FirstCrossing): y' of (3.22) is sampled
  // every kCrossingStep up to t = kCrossingHorizon, and the crossing bisected
  // to an interval of kCrossingWidth (a few ulp of t).
  static constexpr double kCrossingStep = 1e-3, kCrossingHorizon = 20 * M_PI;
  static constexpr double kCrossingWidth = 1e-15;
  // Newton2 (numerics/newton2.hpp) defaults: stop below kNewton2Tol; forward
  // differences of step kNewton2Step (about sqrt(eps) times the scale).
  static constexpr double kNewton2Tol = 1e-13, kNewton2Step = 1e-7;
  // Model::NoPeriodicOrbit: the energy bound's margins (relative to psi(v),
  // and on the damping), well above rounding: the bound only skips searches.
  static constexpr double kNoOrbitMargin = 1e-9;
  // Forced scan: stroboscopic points within kSameStrobe (relative) are one
  // orbit (far above the orbits' 1e-12, far below two orbits' spacing).
  static constexpr double kSameStrobe = 1e-6;
  // Orbit search (orbit_search.hpp): a box of starts not given is the extent
  // of a run of kSearchBoxPeriods clock periods from its centre, times
  // kSearchBoxGrowth, and at least kSearchBoxFloor (1 + |centre|).
  static constexpr double kSearchBoxPeriods = 10, kSearchBoxGrowth = 1.5;
  static constexpr double kSearchBoxFloor = 1e-3;
  // Attractors (basin/attractors.hpp): kept returns monotone in component 0
  // are settling only from this many on (a random sequence of K is monotone
  // with probability 2 / K!).
  static constexpr int kSettlingReturns = 8;
  // Forced exit map: |dg/dt| below kExitMapFold is a fold (the map's slope 1).
  static constexpr double kExitMapFold = 1e-14;
  // Forced shooting: det(DP^m - I) below kSingularShooting (1 + max |a_ij|) is
  // singular (a multiplier at 1).
  static constexpr double kSingularShooting = 1e-15;
  // Forced Taylor roots: deflated coefficients below kDeflateUlps (n + 1)
  // kDeflateEps scale are rounding (64 ulp per degree).
  static constexpr double kDeflateUlps = 64, kDeflateEps = 2.2e-16;
  // Orbit branches: dP/dp by central differences of step kBranchDifference
  // max(1, |p|) (about cbrt(eps): truncation and rounding balanced).
  static constexpr double kBranchDifference = 6e-6;
  // Chart curves: an accepted point whose test function (not its map) exceeds
  // the residual bound is kept within this many corrector tolerances of the
  // test's zero (|test| / |grad test|; measured 1.6e-11 to 5e-11 on the
  // seed_forced chart's doubled PD curves, test gradient 250 to 390).
  static constexpr double kCurveTestSteps = 10;
  // R1 on an LP curve, R2 on a PD curve: two multipliers within this of +1
  // (-1) at the located point (else the NS test's zero is another pair's).
  static constexpr double kResonantPair = 1e-3;
  // Chart curves: a way whose accepted points advance less than
  // kCurveCreepStep of the rectangle kCurveCreepSteps times in a row ends
  // there (on the Stribeck chart with max_m 8 two PD curves crept 2400 steps
  // of about 1e-7 toward a kink: 78 s; chain2's PD curve crept 6 steps).
  static constexpr double kCurveCreepStep = 1e-6;
  static constexpr int kCurveCreepSteps = 20;
  // Orbit branches: the edge search behind a failed chord steps at least
  // kBranchEdgeStep (1 + |p|), and a switched branch's kBranchEdgeStep |range|.
  static constexpr double kBranchEdgeStep = 1e-6;
  // A restart's start is a fold where |t_p| of the branch's unit tangent is
  // below this (ContinueOrbitsFrom): t_p vanishes like sqrt(|p - p_fold|), so
  // a fold located to 1e-12 has |t_p| near 1e-6.
  static constexpr double kFoldTangent = 1e-4;
  // Orbit branches: a branch back past its start by kBranchTurnBack times the
  // range has left it (a turn within rounding of the start is not).
  static constexpr double kBranchTurnBack = 1e-3;
  // Orbit branches: an event bracket wider than kBranchEdgeGap locate_tol
  // (1 + |p| + |x|) straddles a jump of the map, and two edges within it (in
  // p) are one (the two halves of a symmetric orbit reach the band together).
  static constexpr double kBranchEdgeGap = 1e3;
  // Orbit branches: a step across which a multiplier moves more than
  // kBranchMultiplierStep, or (once) one within it of -1, +1 or the unit
  // circle, is halved before the test functions' signs are compared (two
  // crossings in one step, issue 35); an NS point's pair lies within
  // kBranchTorusPair of the unit circle (a located one: 1e-9).
  static constexpr double kBranchMultiplierStep = 0.1, kBranchTorusPair = 1e-6;
  // Forcing phase: Omega t within kPhaseUlps 1e-15 (1 + |Omega t|) of 2 pi is 0.
  static constexpr double kPhaseRounding = 1e-15, kPhaseUlps = 8;

  // --- Iteration caps (scripts/check_limits.py: compared integers) ---
  // Most bound a loop that its own test (a width, a step) ends first; the cap
  // only keeps a pathological input from spinning.
  // Event roots (poly_roots.cpp): Newton steps on a step polynomial, then
  // bisections of the bracket until it is two neighbouring doubles.
  static constexpr int kPolyNewtonCap = 100, kPolyBisectionCap = 200;
  // LP on a branch (special_points.cpp): secant steps of p(a) to kFoldSecantTol.
  static constexpr int kFoldSecantCap = 30;
  // SmallestDisturbance (basin.cpp): halvings of [0, 1] locating x = xbar on
  // a step's Hermite cubic (a fixed count: 2^-60, below rounding).
  static constexpr int kDisturbanceHalvings = 60;
  // Seed estimates (estimates.cpp FirstCrossing): bisections to kCrossingWidth.
  static constexpr int kCrossingBisectionCap = 200;
  // Orbit branches: bisections of a bracket to its tol.
  static constexpr int kBranchBisectionCap = 60;
  // Orbit branches: halvings of a step between two rows (kBranchMultiplierStep).
  static constexpr int kBranchSplitDepth = 6;
  // Orbit branches: changes of the switching sequence located between two rows.
  static constexpr int kBranchEdges = 4;
  // Orbit branches: natural steps (doubling) along one switching sequence
  // where the corrector fails, before its orbits count as going on.
  static constexpr int kBranchEdgeWalk = 6;
  // Orbit branches: how far (in steps of a chord's eighth) the edge behind a
  // failed chord is searched for, either way.
  static constexpr int kBranchEdgeReach = 256;
  // Orbit branches: the natural step behind a failed chord is this share of
  // its parameter span.
  static constexpr int kBranchEdgeSteps = 8;
  // Orbit branches: an edge with no orbit beyond is classified from a run
  // this many locate_tol (1 + |p|) past it.
  static constexpr int kBranchBeyondEdge = 10;
  // Orbit branches: natural steps that confirm an orbit of one switching
  // sequence while its edge is bisected in p.
  static constexpr int kBranchConfirmSteps = 4;
  // Orbit branches: periods of the settling run beyond an edge where Newton
  // from the edge's orbit finds no orbit of another sequence.
  static constexpr int kBranchSettlePeriods = 200;
  // Orbit branches: an event section's map that has not returned within
  // this many periods of the last map that did has no return (the flow's
  // max_return_time, 2000, is hundreds of a branch's periods).
  static constexpr double kBranchReturnPeriods = 20;
  // Chart regions (chart_regions.cpp): section-map returns from the exit
  // point before a run neither decayed nor settled is judged (kRegionLive).
  static constexpr int kRegionMapReturns = 150;
  // Report files (io/report.cpp): attempts at a fresh temporary name.
  static constexpr int kTempFileAttempts = 100;
  // The flow (flow/engine.cpp): switches in a row at one t (to rounding)
  // before switching that does not advance t is a failure (a stick entered
  // and left at once, a few contacts in turn; 8 as the forced flow had),
  // plus two per contact (k blocks in step, each switching in turn).
  static constexpr int kSwitchStalls = 8;

  // Orbit branches: two runs' switches within this share of the period of
  // each other are the same switch (an edge's orbit and a run just past it).
  static constexpr double kBranchSwitchTime = 1e-6;
  // Orbit branches: near an edge, an orbit whose period differs by more than
  // this share (plus twice the parameter's relative step) from the last one's
  // is another orbit, not the edge's (chain2 at kc = 0.2: its in-step orbit,
  // 19 % longer, 1e-7 beyond the last row; 0.2 let it pass).
  static constexpr double kBranchEdgePeriod = 0.05;
  // Orbit branches: a special point of one label located again within this
  // times (1 + |p|) in p and (1 + |z|) in the state (max norm) is the same
  // point: the branch came around a closed curve (special points lie within
  // locate_tol of theirs; a doubled branch's two phase copies differ in z).
  static constexpr double kBranchSamePoint = 1e-8;
  // Steady sliding (steady_branch.cpp): an eigenvalue with |Im| below this
  // times (1 + |lambda|) is real, so its crossing of 0 is LP, not HB.
  static constexpr double kSteadyRealPair = 1e-9;
  // Settling (orbits/settle.cpp): two stick exits of one contact within this
  // (max norm, relative to 1 + |z|) close a cycle; Newton then refines it.
  static constexpr double kSettleRecur = 1e-4;
  // Settling: the run goes in this many pieces, each keeping only the stick
  // exits the recurrence needs (a bound on the switches held).
  static constexpr int kSettleChunks = 64;
  // Autonomous orbit scan (orbits/autonomous_search.cpp): a stick exit of a
  // run within this of an earlier one of its contact (as kSettleRecur) is a
  // guess for Newton on that section.
  static constexpr double kScanRecur = 1e-3;
  // Settling a system with a clock: at most this many clock turns (a run
  // call per turn; a transient of 1e9 turns would not end).
  static constexpr double kSettleMaxTurns = 1e7;

  // --- The flow's rounding windows (flow/engine.cpp) ---
  // A start in stick lies on its surface and within its band to this times
  // (1 + |speed| + limit): a few ulp (64 eps) of the state's rounding.
  static constexpr double kEventRounding = 64 * 2.220446049250313e-16;
};

}  // namespace stickslip
