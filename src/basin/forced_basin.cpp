// Basins on the stroboscopic section (basin/forced_basin.hpp): each start's
// kept section points decide its attractor; attractors are merged on the
// calling thread after the workers join, in grid order (deterministic).
#include "stickslip/basin/forced_basin.hpp"

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

std::string ForcedBasinOptions::ValidationError() const {
  if (nx < 1 || ny < 1 || nx > kMaxSide || ny > kMaxSide)
    return "nx and ny must lie in [1, " + std::to_string(kMaxSide) + "]";
  if (!(x_lo < x_hi) || !(xdot_lo < xdot_hi))
    return "the box must have x_min < x_max and xdot_min < xdot_max";
  for (double c : {x_lo, x_hi, xdot_lo, xdot_hi})
    if (!(std::abs(c) <= kMaxCorner))
      return "the box's corners must be finite and within +-" + Num(kMaxCorner) + " (x from " +
             Num(x_lo) + " to " + Num(x_hi) + ", x' from " + Num(xdot_lo) + " to " + Num(xdot_hi) +
             ")";
  if (max_period < 1 || max_period > iterate.keep / 2)
    return "max_period = " + std::to_string(max_period) + " must lie in [1, keep / 2]";
  if (threads < 0) return "threads = " + std::to_string(threads) + " must be >= 0";
  if (max_keep < 1) return "max_keep = " + std::to_string(max_keep) + " must be >= 1";
  return iterate.ValidationError();
}

Attractor ClassifyAttractor(const ForcedModel& model, const StroboscopicRun& r,
                            const ForcedBasinOptions& o) {
  const Tolerances tol = Tolerances::From(o.iterate.flow.rtol, o.iterate.flow.atol);
  Attractor a;
  a.lyapunov = r.lyapunov;
  if (r.status == LyapunovStatus::kDiverged) return a.kind = AttractorKind::kUnbounded, a;
  if (r.status != LyapunovStatus::kDone) return a.kind = AttractorKind::kFailed, a;
  const auto& p = r.points;
  const int K = static_cast<int>(p.size());
  auto close = [](const SectionPoint& u, const SectionPoint& w, double tol) {
    return std::max(std::abs(u.x - w.x), std::abs(u.xdot - w.xdot)) <=
           tol * (1 + std::abs(u.x) + std::abs(u.xdot));
  };
  for (int m = 1; m <= o.max_period; ++m) {
    bool cycle = true;
    for (int k = 0; k + m < K && cycle; ++k) cycle = close(p[k], p[k + m], tol.SectionCycle());
    if (!cycle) continue;
    bool stuck = model.v() == 0;
    for (const SectionPoint& q : p) stuck = stuck && q.mode == Mode::kStick && q.exits == 0;
    a.kind = stuck ? AttractorKind::kRest : AttractorKind::kPeriodic;
    a.m = m;
    int best = K - m;
    for (int k = K - m; k < K; ++k) {
      a.sticks += p[k].sticks;
      if (p[k].x < p[best].x) best = k;
    }
    a.x = p[best].x, a.xdot = p[best].xdot;
    for (int j = 0; j < m; ++j) {
      const SectionPoint& q = p[K - m + (best - (K - m) + j) % m];
      a.cycle.push_back({q.x, q.xdot});
    }
    a.sticks_per_period = static_cast<double>(a.sticks) / m;
    return a;
  }
  double sticks = 0;
  for (const SectionPoint& q : p) sticks += q.sticks;
  a.sticks = static_cast<int>(std::lround(sticks / K));
  a.sticks_per_period = sticks / K;
  a.kind = r.lyapunov > std::max(3 * r.lyapunov_err, tol.ChaoticExponentFloor())
               ? AttractorKind::kChaotic
               : AttractorKind::kUndecided;
  return a;
}

namespace {

// One start's attractor: keep periods after the transient, then (while
// undecided) 4x as many from the end reached, up to o.max_keep.
Attractor ClassifyStart(const ForcedModel& model, const ForcedBasinStart& s,
                        const ForcedBasinOptions& o, const std::function<bool()>& cancelled,
                        StroboscopicRun* r) {
  *r = IterateStroboscopic(model, ForcedStart(model, 0, s.x, s.xdot), o.iterate, cancelled,
                           o.max_amplitude);
  Attractor a = ClassifyAttractor(model, *r, o);
  LyapunovOptions more = o.iterate;
  more.transient = more.align = o.iterate.align;
  while (a.kind == AttractorKind::kUndecided && more.keep <= o.max_keep / 4) {
    more.keep *= 4;
    *r = IterateStroboscopic(model, r->end, more, cancelled, o.max_amplitude);
    a = ClassifyAttractor(model, *r, o);
  }
  return a;
}

// The index of a in the list (merged as the header says), appended if new.
int Merge(std::vector<Attractor>& list, const Attractor& a, double same) {
  for (size_t i = 0; i < list.size(); ++i) {
    const Attractor& b = list[i];
    if (b.kind != a.kind) continue;
    if (a.kind != AttractorKind::kPeriodic) return static_cast<int>(i);
    if (b.m == a.m && b.sticks == a.sticks &&
        std::max(std::abs(a.x - b.x), std::abs(a.xdot - b.xdot)) <=
            same * (1 + std::abs(a.x) + std::abs(a.xdot)))
      return static_cast<int>(i);
  }
  list.push_back(a);
  return static_cast<int>(list.size() - 1);
}

}  // namespace

ForcedBasins ClassifyForcedBasins(const ForcedModel& model, const ForcedBasinOptions& o) {
  const std::string e = o.ValidationError();
  if (!e.empty()) throw InvalidArgument(e);
  const auto t0 = std::chrono::steady_clock::now();
  ForcedBasins b;
  const int n = o.nx * o.ny;
  b.starts.resize(n);
  std::vector<Attractor> found(n);
  std::vector<char> done_flag(n, 0);
  for (int j = 0; j < o.ny; ++j)
    for (int i = 0; i < o.nx; ++i) {
      ForcedBasinStart& s = b.starts[j * o.nx + i];
      s.x = o.nx == 1 ? (o.x_lo + o.x_hi) / 2 : o.x_lo + (o.x_hi - o.x_lo) * i / (o.nx - 1);
      s.xdot = o.ny == 1 ? (o.xdot_lo + o.xdot_hi) / 2
                         : o.xdot_lo + (o.xdot_hi - o.xdot_lo) * j / (o.ny - 1);
    }
  std::atomic<int> done{0};
  std::atomic<bool> stop{false};
  auto task = [&](int k) {
    try {
      StroboscopicRun r;
      const Attractor a = ClassifyStart(
          model, b.starts[k], o, [&stop] { return stop.load(std::memory_order_relaxed); }, &r);
      if (r.status == LyapunovStatus::kCancelled) return;
      found[k] = a;
      if (found[k].kind == AttractorKind::kFailed) b.starts[k].message = r.message;
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
  for (int k = 0; k < n; ++k) {
    if (!done_flag[k]) continue;
    const int id =
        Merge(b.attractors, found[k],
              Tolerances::From(o.iterate.flow.rtol, o.iterate.flow.atol).SameAttractor());
    ++b.attractors[id].starts;
    b.starts[k].attractor = id;
    b.starts[k].lyapunov = found[k].lyapunov;
    b.failed += found[k].kind == AttractorKind::kFailed;
  }
  b.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return b;
}

}  // namespace stickslip
