// The one place where the library's numerical thresholds are defined. Every
// threshold a computation uses is a field here, derived from the user's rtol
// and atol (or a documented absolute floor); no other file holds a bare
// threshold literal (issue 19). docs/theory.md lists them.
#pragma once

#include <algorithm>

namespace stickslip {

struct Tolerances {
  double rtol = 1e-10;
  double atol = 1e-13;

  static Tolerances From(double rtol, double atol) {
    Tolerances t;
    t.rtol = rtol;
    t.atol = atol;
    return t;
  }

  // --- Integration, events and orbits (flow, steppers, shooting) ---
  /// Forced flow, slip leaving x' = v at a stick exit: x'' there below this
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
  /// Forced branches: a slip phase shorter than this fraction of the orbit's
  /// period at a located sliding point is the one adding-sliding creates
  /// (its length grows like sqrt(|p - p*|) <= 1e-5 within 1e-10; issue 20).
  double VanishingPhase() const { return 1e-4; }
  /// Forced branches: a crossing of x' = v this close to the stick band's edge
  /// (times 1 + the orbit's width) is on it at a located sliding point.
  double BandEdge() const { return std::max(1e-8, 1e3 * rtol); }
  /// Forced basins (chaos/forced_basin.hpp): stroboscopic points of one
  /// periodic cycle agree to this, relative to 1 + |z|: max(1e-6, 1e3 rtol).
  double SectionCycle() const { return std::max(1e-6, 1e3 * rtol); }
  /// ... and two periodic attractors are one if their points agree to max(1e-4, 1e5 rtol).
  double SameAttractor() const { return std::max(1e-4, 1e5 * rtol); }
  /// A start is chaotic if its largest exponent exceeds max(3 err, this floor) (1 / time).
  double ChaoticExponentFloor() const { return 1e-3; }
};

}  // namespace stickslip
