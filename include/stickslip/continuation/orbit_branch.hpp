// One branch driver for the periodic orbits of any system (system.hpp;
// docs/theory.md, "One branch driver"): pseudo-arclength continuation
// (palc.hpp) of the fixed points of a Poincare map (shooting.hpp),
//   F(u, p) = P(u; p) - u = 0,
// in the map's unknowns u (a stroboscopic section: the tangent block; an
// event section: the whole state, where DP - I stays regular because DP maps
// the flow direction to 0) and one parameter p of the system (the lens, an
// index). dF/du = DP - I from the variational equations and saltations;
// dF/dp by central differences of two plain runs. Special points between two
// rows, located on the branch by bisection (Kuznetsov 2004, ch. 10):
//   LP  prod (mu_i - 1) changes sign;
//   PD  prod (mu_i + 1) changes sign;
//   NS  prod_{i<j} (mu_i mu_j - 1) changes sign with a complex pair on the
//       unit circle there (the bialternate product's eigenvalues; a real pair
//       with mu_i mu_j = 1 is a neutral saddle, none);
//   GR, AD, CR, SL  the orbit's sticks or crossings per period change
//       (special_kind.hpp: named from the switches on either side);
//   CL  a contact's normal force reaches 0 on the orbit (the branch ends).
// A step across which a multiplier moves far is halved first, so two
// crossings in one step are both found. Where the corrector fails (a corner
// of the branch sharper than a right angle, as at the belt's grazing, or a
// jump of the map) the branch goes on from the orbit beyond, found by
// natural steps in p, and the edge between is bisected in p.
#pragma once

#include <complex>
#include <string>
#include <vector>

#include "stickslip/continuation/branch_status.hpp"
#include "stickslip/continuation/palc.hpp"
#include "stickslip/continuation/special_kind.hpp"
#include "stickslip/integrate/extrema.hpp"
#include "stickslip/orbits/shooting.hpp"

namespace stickslip {

/// The most clock turns per period of a branch's section (m <= 1000 forcing
/// periods, as a restart file's).
inline constexpr int kMaxPeriodMultiple = 1000;

/// Settings of ContinueOrbits, validated once.
struct OrbitBranchOptions {
  OrbitBranchOptions() = default;
  /// Every map on this flow (its step cap too: ShootingOptions(flow)).
  explicit OrbitBranchOptions(const FlowOptions& flow) : shooting(flow) {}
  ShootingOptions shooting;  ///< the start's Newton and every map's flow
  PalcOptions palc;          ///< on (u, p)
  /// Rows stop beyond this |z_i| of a displacement (a tangent component no
  /// other is the rate of: x, not x'; kUnbounded).
  double max_amplitude = 1e3;
  double locate_tol = 1e-12;  ///< special points: the bracket on the chord, relative
  /// Where the corrector fails (a corner sharper than a right angle, or a
  /// jump of the map): at most this many restarts from the orbit beyond,
  /// found by natural steps in p, with the edge between located and named.
  int max_jumps = 50;
  /// Empty if valid, else one line naming the offending value.
  std::string ValidationError() const;
};

/// One orbit of a branch.
struct OrbitRow {
  double p = 0;
  FlowPoint start;  ///< the section point, with its mode
  double period = 0;
  int sticks = 0, exits = 0, crossings = 0;  ///< per period
  Eigen::VectorXd lo, hi;                    ///< extremes of the tangent components
  std::vector<std::complex<double>> multipliers;
  bool stable = false;
  SpecialKind label = SpecialKind::kNone;  ///< special points only
  std::string description;                 ///< special points only: one line
};

struct OrbitBranch {
  BranchStatus status = BranchStatus::kStartFailed;
  std::string message;
  std::vector<OrbitRow> rows;     ///< the special points among them, in order
  std::vector<OrbitRow> special;  ///< LP, PD, NS, GR, AD, CR, SL and CL points, located
  int jumps = 0;                  ///< restarts across corners and jumps
  int evaluations = 0;            ///< of the map with its Jacobian
  double seconds = 0;
  /// The section the rows are fixed points of, at the branch's start (its
  /// returns and clock turns: a doubled branch's are twice the PD orbit's);
  /// set also where the start failed.
  PoincareSection section;
};

/// The extremes of components 0 and 1 (x and x') of a row (OrbitRow::lo,
/// hi); Extrema::Empty() where the shooting did not record them.
inline Extrema RowExtrema(const OrbitRow& r) { return ExtremaOf(r.lo, r.hi); }

/// The period multiple m of a branch: its section's clock turns.
inline int PeriodMultiple(const OrbitBranch& b) { return b.section.turns; }

/// The branch of the orbit through `guess` on `section` of `system`, in its
/// parameter `parameter` from its value in `system` to `to`. A stroboscopic
/// section's time follows the clock's frequency along the branch (its turns
/// stay). Throws InvalidArgument, naming the value, on an invalid system or
/// options (PALC's too), a parameter index out of range or one the system
/// does not depend on (System::ParameterError: mu_m under the coulomb law),
/// a guess that is not finite, `to` not finite or equal to the start's
/// value, an end where the system is invalid, or a section that is invalid
/// (Stroboscopic refuses m < 1) or has more than kMaxPeriodMultiple turns.
/// options.palc.cancelled (if set) is polled by the corrector loop, between
/// the jumps and inside every run of the flow.
OrbitBranch ContinueOrbits(const System& system, int parameter, const FlowPoint& guess,
                           const PoincareSection& section, double to,
                           const OrbitBranchOptions& options);

/// The branch through `start`, an orbit already computed at the system's
/// value of `parameter` (a restart: AUTO-07p's IRS), toward `to`. There is
/// no Newton with p held first (at a fold DP - I is singular): the first
/// correction holds the component of the branch's tangent (the null vector
/// of [F_u F_p] at start) that moves most, and the branch leaves along the
/// tangent oriented toward `to`. At a fold (an LP: pass side 1 or -1; the
/// tangent has no component in p there, |t_p| < 1e-4), it leaves along the
/// half `side` picks: the orientation whose largest component is positive,
/// or its opposite. side 0 (an ordinary point) always orients toward `to`.
/// The first row is the start, corrected. A branch cut short while
/// options.palc.cancelled() holds is kCancelled, whatever failed first.
/// Throws InvalidArgument as ContinueOrbits does, and for a side other than
/// -1, 0 or 1.
OrbitBranch ContinueOrbitsFrom(const System& system, int parameter, const FlowPoint& start,
                               const PoincareSection& section, double to, int side,
                               const OrbitBranchOptions& options);

/// Branch switching at a period doubling, for any system (AUTO-07p's ISW =
/// -1 at a PD label; Kuznetsov 2004, section 4.4): `system` at the PD's
/// parameter value, `pd` the PD orbit's section point (an OrbitRow's start)
/// and `section` its section. The orbits of twice the period form a
/// pitchfork of P^2 tangent to e, the eigenvector of DP's multiplier -1: the
/// doubled branch starts at pd + h e (h = options.palc.ds, scaled), is
/// corrected with its projection on e held, and is traced away from the
/// single orbit to whichever of lo, hi it opens toward, on the section of
/// twice the turns and returns. kStartFailed, with a message, where DP has
/// no multiplier near -1 or the start falls back onto the single orbit.
/// Throws InvalidArgument as ContinueOrbits does, and unless lo < p < hi.
OrbitBranch ContinueDoubled(const System& system, int parameter, const FlowPoint& pd,
                            const PoincareSection& section, double lo, double hi,
                            const OrbitBranchOptions& options);

}  // namespace stickslip
