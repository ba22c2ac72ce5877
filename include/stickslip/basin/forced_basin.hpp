// Basins of attraction on the stroboscopic section of the forced oscillator
// (issue 21 item 4): a grid of starts (x, x') at forcing phase 0, each
// iterated past a transient and classified by the attractor it reaches:
// a periodic orbit (period m forcing periods, its stick count), the stuck
// rest (v = 0, held for good), a chaotic attractor (largest Lyapunov
// exponent above zero by more than its error), or undecided (neither
// periodic within max_period nor chaotic, also after running on to max_keep
// periods: quasi-periodic or slow). Periodic
// attractors are told apart by their section points. Starts run on a bounded
// pool (threads, capped by the hardware threads); no exception crosses a thread.
#pragma once

#include <array>
#include <functional>
#include <string>
#include <vector>

#include "stickslip/chaos/lyapunov.hpp"
#include "stickslip/names.hpp"

namespace stickslip {

enum class AttractorKind { kPeriodic, kRest, kChaotic, kUndecided, kUnbounded, kFailed };
template <>
struct EnumNames<AttractorKind> {
  static constexpr NamedValue<AttractorKind> kTable[] = {
      {AttractorKind::kPeriodic, "periodic"},   {AttractorKind::kRest, "rest"},
      {AttractorKind::kChaotic, "chaotic"},     {AttractorKind::kUndecided, "undecided"},
      {AttractorKind::kUnbounded, "unbounded"}, {AttractorKind::kFailed, "failed"},
  };
};

struct Attractor {
  AttractorKind kind = AttractorKind::kUndecided;
  int m = 0;       ///< period in forcing periods (periodic)
  int sticks = 0;  ///< stick phases per m periods (periodic), per period rounded (chaotic)
  /// Stick phases per forcing period, the kept run's mean (chaotic: 0.66 on
  /// the seed basin's attractor, where `sticks` rounds it to 1).
  double sticks_per_period = 0;
  double x = 0, xdot = 0;  ///< a representative section point (smallest x of the cycle)
  /// Periodic: the cycle's m section points in the order the map visits them,
  /// from (x, xdot) on.
  std::vector<std::array<double, 2>> cycle;
  double lyapunov = 0;
  int starts = 0;  ///< grid starts that reach it
};

struct ForcedBasinOptions {
  /// nx's and ny's upper bound.
  static constexpr int kMaxSide = 2000;
  /// Bound of |x_lo|, |x_hi|, |xdot_lo|, |xdot_hi| (a finite box whose width
  /// cannot overflow: x_hi - x_lo = inf made every start nan).
  static constexpr double kMaxCorner = 1e6;
  int nx = 41, ny = 41;
  double x_lo = -1.5, x_hi = 1.5, xdot_lo = -1.5, xdot_hi = 1.5;
  LyapunovOptions iterate;  ///< transient, keep (the classification window), flow
  int max_period = 16;      ///< largest m looked for
  /// A start neither periodic nor chaotic over `keep` periods runs on from its
  /// end over 4x as many (the last `align` realigning the tangent), and again,
  /// while that stays <= max_keep: a weakly chaotic start needs more periods
  /// for its exponent to clear 3 errors (docs/studies.md, forced seed basins).
  int max_keep = 1024;
  int threads = 2;  ///< worker threads, capped by the hardware threads; 0: all of them
  double max_amplitude = 50;
  std::function<bool()> cancelled;                    ///< polled by the calling thread
  std::function<void(int done, int total)> progress;  ///< called on the calling thread
  ForcedBasinOptions() { iterate.transient = 300, iterate.keep = 64, iterate.align = 20; }
  std::string ValidationError() const;
};

struct ForcedBasinStart {
  double x = 0, xdot = 0;
  int attractor = -1;  ///< index into ForcedBasins::attractors; -1 not done
  double lyapunov = 0;
  std::string message;  ///< why, for kFailed
};

struct ForcedBasins {
  std::vector<ForcedBasinStart> starts;  ///< row-major: x fastest
  std::vector<Attractor> attractors;
  bool cancelled = false;
  int failed = 0;
  double seconds = 0;
  int threads = 0;    ///< worker threads that ran
  std::string error;  ///< not empty: no worker thread could start (nothing classified)
};

/// The attractor one run's kept section points show (o.max_period and the
/// tolerances of o.iterate.flow), as ClassifyForcedBasins decides per start:
/// periodic within max_period (m, sticks per m periods), rest, chaotic, undecided.
Attractor ClassifyAttractor(const ForcedModel& model, const StroboscopicRun& r,
                            const ForcedBasinOptions& o);

/// Throws InvalidArgument if the options are not valid.
ForcedBasins ClassifyForcedBasins(const ForcedModel& model, const ForcedBasinOptions& options);

}  // namespace stickslip
