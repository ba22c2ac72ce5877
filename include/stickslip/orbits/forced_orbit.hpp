// Periodic orbits of the forced friction oscillator on the one shooting
// (orbits/shooting.hpp, docs/theory.md "One shooting"): fixed points of the
// stroboscopic map P^m, (x, x') at theta = 0 -> (x, x') m forcing periods
// later, and of the exit-phase map, from one stick exit to the `sticks`-th
// next. Both are sections of ForcedBelt (x, x', theta) and return the one
// PeriodicOrbit, its Floquet multipliers from the monodromy with saltations.
#pragma once

#include <complex>

#include "stickslip/orbits/shooting.hpp"
#include "stickslip/systems/forced/flow.hpp"

namespace stickslip {

/// Newton on P^m(z) - z = 0 from (x0, xdot0) at theta = 0. The orbit's start
/// is (x, x', 0) with its mode, its period m 2 pi / Omega, its monodromy DP^m
/// on (x, x'). The forced tools shoot with
/// ShootingOptions(ForcedBelt::FlowDefaults()). Throws InvalidArgument for
/// m < 1 or invalid options.
PeriodicOrbit ShootStroboscopic(const ForcedBelt& model, double x0, double xdot0, int m,
                                const ShootingOptions& options);

/// Newton on t' - t_e - m T = 0 from the exit time t_guess into exit_mode:
/// from a stick exit at t_e, on the band's edge x_e = +-mu_s - 2 beta v +
/// A cos(Omega t_e), x' = v, to the `sticks`-th next exit t'. The orbit's
/// start is that exit, t_e in [0, T), in the slip mode it leaves into; its one
/// multiplier is the exit map's dt'/dt_e (the others are 0: stick collapses
/// the state). Throws InvalidArgument for m, sticks < 1 or a stick exit_mode.
PeriodicOrbit ExitPhaseOrbit(const ForcedBelt& model, double t_guess, Mode exit_mode, int sticks,
                             int m, const ShootingOptions& options);

/// A forced orbit's period in forcing periods (its clock's turns).
int PeriodMultiple(const ForcedBelt& model, const PeriodicOrbit& o);

/// The extremes of x and x' of an orbit (PeriodicOrbit::lo, hi), else Empty().
inline Extrema OrbitExtrema(const PeriodicOrbit& o) { return ExtremaOf(o.lo, o.hi); }

/// Multipliers of a 2 x 2 monodromy, the larger modulus first.
void Multipliers(const Mat2& M, std::complex<double> out[2]);

}  // namespace stickslip
