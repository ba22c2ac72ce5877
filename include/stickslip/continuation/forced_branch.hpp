// The forced oscillator's branches on the one branch driver (orbit_branch.hpp):
// the stroboscopic residual P^m(z; p) - z = 0 in (x, x', p) of ForcedBelt,
// started from its parameters and a guess (x, x') at theta = 0. The rows,
// special points (LP, PD, NS, GR, AD, CR, SL: special_kind.hpp) and statuses
// are the driver's; a row's start is (x, x', theta).
#pragma once

#include <complex>
#include <string>
#include <vector>

#include "stickslip/continuation/branch_status.hpp"
#include "stickslip/continuation/orbit_branch.hpp"
#include "stickslip/continuation/palc.hpp"
#include "stickslip/names.hpp"
#include "stickslip/orbits/forced_orbit.hpp"
#include "stickslip/systems/belt/parameter_axis.hpp"

namespace stickslip {

/// The extremes of x and x' of a row (OrbitRow::lo, hi); Extrema::Empty()
/// where the shooting did not record them.
inline Extrema RowExtrema(const OrbitRow& r) { return ExtremaOf(r.lo, r.hi); }

/// The period multiple m of a branch: its section's clock turns.
inline int PeriodMultiple(const OrbitBranch& b) { return b.section.turns; }

/// m's upper bound (1000 forcing periods, as a restart file's).
inline constexpr int kMaxPeriodMultiple = 1000;

/// Traces the branch of m-periodic orbits (m in [1, kMaxPeriodMultiple])
/// through the orbit near (x_guess, xdot_guess) at p = from toward p = to.
/// The forced tools pass OrbitBranchOptions(ForcedBelt::FlowDefaults()).
/// Throws InvalidArgument on invalid parameters, options or a non-finite
/// guess. options.palc.cancelled (if set) is polled before every correction.
OrbitBranch ContinueForced(const ForcedBeltParams& base, ParameterAxis axis, double from, double to,
                           double x_guess, double xdot_guess, int m,
                           const OrbitBranchOptions& options);

/// Branch switching at a period doubling (AUTO-07p's ISW = -1 at a PD label).
/// at_pd holds the PD point's parameters (axis.Get(at_pd) = p_PD),
/// (x0, xdot0) its stroboscopic point and m its period multiple. The
/// 2m-periodic branch starts at z + h e (e the eigenvector of the multiplier
/// -1 of DP^m, h = options.palc.ds, scaled), corrected with its projection on
/// e held (p free: the 2m orbits form a pitchfork of P^2m, p - p_PD ~ h^2),
/// and is traced away from the m orbit to whichever bound, lo or hi, it opens
/// toward. Rows have 2m. Status kStartFailed with a message if
/// the point has no multiplier near -1 or the start falls back onto the m
/// orbit. Throws InvalidArgument on invalid parameters, options or bounds
/// (lo < p_PD < hi).
OrbitBranch ContinueDoubled(const ForcedBeltParams& at_pd, ParameterAxis axis, double x0,
                            double xdot0, double lo, double hi, int m,
                            const OrbitBranchOptions& options);

}  // namespace stickslip
