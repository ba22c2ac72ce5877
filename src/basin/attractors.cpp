// Basins on a Poincare section (basin/attractors.hpp): each start's kept
// section points decide its attractor; attractors are merged on the calling
// thread after the workers join, in grid order (deterministic).
#include "stickslip/basin/attractors.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <exception>

#include "numerics/numbers.hpp"
#include "numerics/tolerances.hpp"
#include "parallel/pool.hpp"
#include "stickslip/errors.hpp"

namespace stickslip {

std::string AttractorOptions::ValidationError(const System& s) const {
  const StartSlice& g = slice;
  const int dim = s.tangent_dimension();
  for (int c : g.components)
    if (c < 0 || c >= dim)
      return "the slice's component " + std::to_string(c) + " must lie in [0, " +
             std::to_string(dim - 1) + "]";
  if (g.components[0] == g.components[1]) return "the slice's two components must differ";
  if (g.base.size() != 0 && g.base.size() != s.dimension())
    return "the slice's base state has " + std::to_string(g.base.size()) +
           " components, the system " + std::to_string(s.dimension());
  if (g.n[0] < 1 || g.n[1] < 1 || g.n[0] > kMaxSide || g.n[1] > kMaxSide)
    return "nx and ny must lie in [1, " + std::to_string(kMaxSide) + "]";
  if (!(g.lo[0] < g.hi[0]) || !(g.lo[1] < g.hi[1]))
    return "the box must have " + s.StateName(g.components[0]) + " from < to and " +
           s.StateName(g.components[1]) + " from < to";
  for (double c : {g.lo[0], g.hi[0], g.lo[1], g.hi[1]})
    if (!(std::abs(c) <= kMaxCorner))
      return "the box's corners must be finite and within +-" + Num(kMaxCorner) + " (" +
             s.StateName(g.components[0]) + " from " + Num(g.lo[0]) + " to " + Num(g.hi[0]) + ", " +
             s.StateName(g.components[1]) + " from " + Num(g.lo[1]) + " to " + Num(g.hi[1]) + ")";
  if (max_period < 1 || max_period > iterate.keep / 2)
    return "max_period = " + std::to_string(max_period) + " must lie in [1, keep / 2]";
  if (threads < 0) return "threads = " + std::to_string(threads) + " must be >= 0";
  if (max_keep < 1) return "max_keep = " + std::to_string(max_keep) + " must be >= 1";
  if (s.clocks() > 1) return "a system with more than one clock has no one stroboscopic map";
  if (s.clocks() == 1 && surface)
    return "a system with a clock is classified on its stroboscopic section, not a surface";
  return iterate.ValidationError();
}

PoincareSection AttractorSection(const System& s, const AttractorOptions& o) {
  if (s.clocks() > 0) {
    const Eigen::VectorXd z =
        o.slice.base.size() ? o.slice.base : Eigen::VectorXd::Zero(s.dimension());
    return PoincareSection::Stroboscopic(s, z, 1);
  }
  PoincareSection p;
  p.kind = SectionKind::kSurface;
  p.surface = o.surface ? *o.surface : MaximaSection(s);
  return p;
}

namespace {

// max |u_i - w_i| <= tol (1 + sum |u_i|) on the tangent block.
bool Close(const Eigen::VectorXd& u, const Eigen::VectorXd& w, double tol) {
  return (u - w).lpNorm<Eigen::Infinity>() <= tol * (1 + u.lpNorm<1>());
}

// Whether the tangent field vanishes at the section point (the phase 0).
bool Vanishes(const System& s, const SectionPoint& q, double tol) {
  Eigen::VectorXd z = Eigen::VectorXd::Zero(s.dimension());
  z.head(s.tangent_dimension()) = q.z;
  return FieldVanishes(s, q.mode, z, tol);
}

// The stable rest point of the mode of the points (System::Rest) if every
// one lies within tol of it: a spiral onto steady sliding, whose returns
// agree to the cycle tolerance before they reach the rest point.
std::optional<Eigen::VectorXd> NearStableRest(const System& s, const std::vector<SectionPoint>& p,
                                              double tol) {
  Eigen::VectorXd rest = Eigen::VectorXd::Zero(s.dimension());  // no guess
  bool stable = false;
  if (p.empty() || !s.Rest(p.back().mode, rest, &stable) || !stable) return std::nullopt;
  const Eigen::VectorXd z = rest.head(s.tangent_dimension());
  for (const SectionPoint& q : p)
    if (q.exits > 0 || !Close(q.z, z, tol)) return std::nullopt;
  return z;
}

// The periodic (or rest) attractor of the cycle of length m the points close:
// rest where no contact leaves a stick and the field vanishes (to `cycle`),
// or a stable rest point lies within `same` of every point (then it is the
// attractor's point).
Attractor Cycle(const System& s, const std::vector<SectionPoint>& p, int m, double cycle,
                double same) {
  const int K = static_cast<int>(p.size());
  Attractor a;
  if (const auto rest = NearStableRest(s, p, same)) {
    a.kind = AttractorKind::kRest, a.m = 1;
    a.z = *rest, a.cycle = {*rest};
    return a;
  }
  bool rest = true;
  for (const SectionPoint& q : p) rest = rest && q.exits == 0 && Vanishes(s, q, cycle);
  a.kind = rest ? AttractorKind::kRest : AttractorKind::kPeriodic;
  a.m = m;
  int best = K - m;
  for (int k = K - m; k < K; ++k) {
    a.sticks += p[k].sticks;
    if (p[k].z[0] < p[best].z[0]) best = k;
  }
  a.z = p[best].z;
  for (int j = 0; j < m; ++j) a.cycle.push_back(p[K - m + (best - (K - m) + j) % m].z);
  a.sticks_per_period = static_cast<double>(a.sticks) / m;
  return a;
}

}  // namespace

Attractor ClassifyAttractor(const System& s, const SectionRun& r, const AttractorOptions& o) {
  const Tolerances tol = Tolerances::From(o.iterate.flow.rtol, o.iterate.flow.atol);
  Attractor a;
  a.z = Eigen::VectorXd::Zero(s.tangent_dimension());
  a.lyapunov = r.lyapunov;
  if (r.status == LyapunovStatus::kDiverged) return a.kind = AttractorKind::kUnbounded, a;
  if (r.status == LyapunovStatus::kContactOpen) return a.kind = AttractorKind::kContactLost, a;
  if (r.status == LyapunovStatus::kRest) {  // settled where no return follows
    a.kind = AttractorKind::kRest, a.m = 1;
    a.z = r.end.z.head(s.tangent_dimension());
    a.cycle = {a.z};
    return a;
  }
  if (r.status == LyapunovStatus::kNoReturn) return a;  // undecided
  if (r.status != LyapunovStatus::kDone) return a.kind = AttractorKind::kFailed, a;
  const auto& p = r.points;
  const int K = static_cast<int>(p.size());
  for (int m = 1; m <= o.max_period; ++m) {
    bool cycle = true;
    for (int k = 0; k + m < K && cycle; ++k) cycle = Close(p[k].z, p[k + m].z, tol.SectionCycle());
    if (!cycle) continue;
    Attractor c = Cycle(s, p, m, tol.SectionCycle(), tol.SameAttractor());
    c.lyapunov = r.lyapunov;
    return c;
  }
  double sticks = 0;
  for (const SectionPoint& q : p) sticks += q.sticks;
  a.sticks = static_cast<int>(std::lround(sticks / K));
  a.sticks_per_period = sticks / K;
  // Settling: every kept return on one side of the last (K >= kSettlingReturns)
  // with an exponent clearly off 0 (a spiral, not a torus of rotation near 0).
  const bool drifting =
      K >= Tolerances::kSettlingReturns && std::abs(r.lyapunov) > 3 * r.lyapunov_err;
  bool up = drifting, down = drifting;
  for (int k = 1; k < K; ++k)
    up = up && p[k].z[0] > p[k - 1].z[0], down = down && p[k].z[0] < p[k - 1].z[0];
  if (up || down) return a.kind = AttractorKind::kSettling, a;
  a.kind = r.lyapunov > std::max(3 * r.lyapunov_err, tol.ChaoticExponentFloor())
               ? AttractorKind::kChaotic
               : AttractorKind::kUndecided;
  return a;
}
namespace {

// One start's attractor: keep returns after the transient, then (while
// undecided) 4x as many from the end reached, up to o.max_keep.
Attractor ClassifyStart(const System& sys, const PoincareSection& section, const FlowPoint& start,
                        const AttractorOptions& o, const std::function<bool()>& cancelled,
                        SectionRun* r) {
  *r = IterateSection(sys, start, section, o.iterate, cancelled, o.max_amplitude);
  Attractor a = ClassifyAttractor(sys, *r, o);
  LyapunovOptions more = o.iterate;
  more.transient = more.align = o.iterate.align;
  while ((a.kind == AttractorKind::kUndecided || a.kind == AttractorKind::kSettling) &&
         r->status == LyapunovStatus::kDone && more.keep <= o.max_keep / 4) {
    more.keep *= 4;
    *r = IterateSection(sys, r->end, section, more, cancelled, o.max_amplitude);
    a = ClassifyAttractor(sys, *r, o);
  }
  return a;
}

// The index of a in the list (merged as the header says), appended if new.
int Merge(std::vector<Attractor>& list, const Attractor& a, double same) {
  for (size_t i = 0; i < list.size(); ++i) {
    const Attractor& b = list[i];
    if (b.kind != a.kind) continue;
    if (a.kind != AttractorKind::kPeriodic) return static_cast<int>(i);
    if (b.m == a.m && b.sticks == a.sticks && Close(a.z, b.z, same)) return static_cast<int>(i);
  }
  list.push_back(a);
  return static_cast<int>(list.size() - 1);
}

// The grid's starts, row-major (the first component fastest).
std::vector<AttractorStart> Starts(const StartSlice& g) {
  std::vector<AttractorStart> starts(static_cast<size_t>(g.n[0]) * g.n[1]);
  for (int j = 0; j < g.n[1]; ++j)
    for (int i = 0; i < g.n[0]; ++i) {
      AttractorStart& s = starts[static_cast<size_t>(j) * g.n[0] + i];
      const int at[2] = {i, j};
      for (int c = 0; c < 2; ++c)
        s.at[c] = g.n[c] == 1 ? (g.lo[c] + g.hi[c]) / 2
                              : g.lo[c] + (g.hi[c] - g.lo[c]) * at[c] / (g.n[c] - 1);
    }
  return starts;
}

// The flow's start at a grid point: the base state with the slice's two
// components, in Filippov's mode, at t = 0.
FlowPoint StartAt(const System& sys, const StartSlice& g, const AttractorStart& s) {
  FlowPoint z;
  z.z = g.base.size() ? g.base : Eigen::VectorXd::Zero(sys.dimension());
  z.z[g.components[0]] = s.at[0], z.z[g.components[1]] = s.at[1];
  z.mode = ModeOf(sys, z.z);
  return z;
}

}  // namespace

AttractorBasins ClassifyAttractors(const System& sys, const AttractorOptions& o) {
  const std::string e = o.ValidationError(sys);
  if (!e.empty()) throw InvalidArgument(e);
  const auto t0 = std::chrono::steady_clock::now();
  const PoincareSection section = AttractorSection(sys, o);
  AttractorBasins b;
  b.starts = Starts(o.slice);
  const int n = static_cast<int>(b.starts.size());
  std::vector<Attractor> found(n);
  std::vector<char> done_flag(n, 0);
  std::atomic<int> done{0};
  std::atomic<bool> stop{false};
  auto task = [&](int k) {
    try {
      SectionRun r;
      const Attractor a = ClassifyStart(
          sys, section, StartAt(sys, o.slice, b.starts[k]), o,
          [&stop] { return stop.load(std::memory_order_relaxed); }, &r);
      if (r.status == LyapunovStatus::kCancelled) return;
      found[k] = a;
      if (found[k].kind == AttractorKind::kFailed || r.status == LyapunovStatus::kNoReturn ||
          found[k].kind == AttractorKind::kContactLost)
        b.starts[k].message = r.message;  // why it failed, is undecided, or where contact was lost
    } catch (const std::exception& ex) {  // no exception leaves the worker
      found[k].kind = AttractorKind::kFailed;
      b.starts[k].message = ex.what();
    } catch (...) {
      found[k].kind = AttractorKind::kFailed;
      b.starts[k].message = "unknown exception";
    }
    done_flag[k] = 1;
    done.fetch_add(1);
  };
  const PoolRun pool = RunPool(n, o.threads, task, stop, [&] {
    if (o.cancelled && o.cancelled()) return true;
    if (o.progress) o.progress(done.load(), n);
    return false;
  });
  b.threads = pool.threads;
  b.error = pool.error;
  b.cancelled = stop.load();
  const double same = Tolerances::From(o.iterate.flow.rtol, o.iterate.flow.atol).SameAttractor();
  for (int k = 0; k < n; ++k) {
    if (!done_flag[k]) continue;
    if (found[k].z.size() == 0) found[k].z = Eigen::VectorXd::Zero(sys.tangent_dimension());
    const int id = Merge(b.attractors, found[k], same);
    ++b.attractors[id].starts;
    b.starts[k].attractor = id;
    b.starts[k].lyapunov = found[k].lyapunov;
    b.failed += found[k].kind == AttractorKind::kFailed;
  }
  b.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return b;
}

}  // namespace stickslip
