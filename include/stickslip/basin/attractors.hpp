// Basins of attraction of any system on a Poincare section (issue 21 item 4,
// issue 31 item 6): a grid of starts on a 2-D slice of the state space, each
// iterated past a transient and classified by the attractor it reaches: a
// periodic orbit (period m returns, its stick count), rest (a cycle where the
// field vanishes: stuck on a belt at rest, or settled on steady sliding), a
// chaotic attractor (largest Lyapunov exponent above zero by more than its
// error), unbounded, or undecided (neither periodic within max_period nor
// chaotic, also after running on to max_keep returns: quasi-periodic or
// slow). The section is the stroboscopic one of a forced system (one clock
// period) or a surface of an autonomous one (by default the maxima of
// component 0). Periodic attractors are told apart by their section points.
// Starts run on a bounded pool (threads, capped by the hardware threads); no
// exception crosses a thread.
#pragma once

#include <array>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "stickslip/chaos/lyapunov.hpp"
#include "stickslip/names.hpp"

namespace stickslip {

/// What a start reaches. kContactLost: a contact's normal force reached 0 on
/// the way (the block lifts off; the model ends there), an outcome, not a
/// failure. kSettling: the kept returns still drift one way in component 0
/// (a slow spiral onto or off a rest point or cycle, next to an HB or NS):
/// not yet decided, and neither chaos nor a torus.
enum class AttractorKind {
  kPeriodic,
  kRest,
  kChaotic,
  kUndecided,
  kUnbounded,
  kFailed,
  kContactLost,
  kSettling
};
template <>
struct EnumNames<AttractorKind> {
  static constexpr NamedValue<AttractorKind> kTable[] = {
      {AttractorKind::kPeriodic, "periodic"},        {AttractorKind::kRest, "rest"},
      {AttractorKind::kChaotic, "chaotic"},          {AttractorKind::kUndecided, "undecided"},
      {AttractorKind::kUnbounded, "unbounded"},      {AttractorKind::kFailed, "failed"},
      {AttractorKind::kContactLost, "contact-lost"}, {AttractorKind::kSettling, "settling"},
  };
};

/// Whether a start or cell of this kind has a measured Lyapunov exponent
/// (not a failed, unbounded or contact-lost one, whose run ended early).
inline bool HasExponent(AttractorKind k) {
  return k != AttractorKind::kFailed && k != AttractorKind::kUnbounded &&
         k != AttractorKind::kContactLost;
}

struct Attractor {
  AttractorKind kind = AttractorKind::kUndecided;
  int m = 0;       ///< period in returns (periodic, rest)
  int sticks = 0;  ///< stick phases per m returns (periodic), per return rounded (chaotic)
  /// Stick phases per return, the kept run's mean (chaotic: 0.66 on the seed
  /// basin's attractor, where `sticks` rounds it to 1).
  double sticks_per_period = 0;
  /// A representative section point on the tangent block: the cycle's point
  /// of smallest component 0 (periodic, rest), else zeros.
  Eigen::VectorXd z;
  /// Periodic: the cycle's m section points in the order the map visits them,
  /// from z on.
  std::vector<Eigen::VectorXd> cycle;
  double lyapunov = 0;
  int starts = 0;  ///< grid starts that reach it
};

/// Starts on a 2-D slice: components (i, j) of the state span the box, the
/// others are the base state's (clocks: the starts' phase).
struct StartSlice {
  std::array<int, 2> components{0, 1};
  Eigen::VectorXd base;  ///< empty: zeros
  std::array<double, 2> lo{-1.5, -1.5}, hi{1.5, 1.5};
  std::array<int, 2> n{41, 41};  ///< starts per side, ends included
};

struct AttractorOptions {
  /// Each side's upper bound.
  static constexpr int kMaxSide = 2000;
  /// Bound of the box's corners (a finite box whose width cannot overflow:
  /// hi - lo = inf made every start nan).
  static constexpr double kMaxCorner = 1e6;
  StartSlice slice;
  /// The map's section: empty gives the stroboscopic section of a system
  /// with a clock, else MaximaSection.
  std::optional<Section> surface;
  LyapunovOptions iterate;  ///< transient, keep (the classification window), flow
  int max_period = 16;      ///< largest m looked for
  /// A start neither periodic nor chaotic over `keep` returns runs on from its
  /// end over 4x as many (the last `align` realigning the tangent), and again,
  /// while that stays <= max_keep: a weakly chaotic start needs more returns
  /// for its exponent to clear 3 errors (docs/studies.md, forced seed basins).
  int max_keep = 1024;
  int threads = 2;  ///< worker threads, capped by the hardware threads; 0: all of them
  double max_amplitude = 50;
  std::function<bool()> cancelled;                    ///< polled by the calling thread
  std::function<void(int done, int total)> progress;  ///< called on the calling thread
  AttractorOptions() { iterate.transient = 300, iterate.keep = 64, iterate.align = 20; }
  /// Empty if valid (for this system), else one line naming the offending value.
  std::string ValidationError(const System& system) const;
};

struct AttractorStart {
  std::array<double, 2> at{0, 0};  ///< the slice's two components
  int attractor = -1;              ///< index into AttractorBasins::attractors; -1 not done
  double lyapunov = 0;
  std::string message;  ///< why, for kFailed
};

struct AttractorBasins {
  std::vector<AttractorStart> starts;  ///< row-major: the first component fastest
  std::vector<Attractor> attractors;
  bool cancelled = false;
  int failed = 0;
  double seconds = 0;
  int threads = 0;    ///< worker threads that ran
  std::string error;  ///< not empty: no worker thread could start (nothing classified)
};

/// The map the options iterate for this system (see AttractorOptions::surface).
PoincareSection AttractorSection(const System& system, const AttractorOptions& o);

/// The attractor one run's kept section points show (o.max_period and the
/// tolerances of o.iterate.flow), as ClassifyAttractors decides per start.
Attractor ClassifyAttractor(const System& system, const SectionRun& r, const AttractorOptions& o);

/// Throws InvalidArgument if the options are not valid for the system.
AttractorBasins ClassifyAttractors(const System& system, const AttractorOptions& options);

}  // namespace stickslip
