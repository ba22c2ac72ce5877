// The forced chart's response grid (stickslip/chart/forced_chart.hpp): each
// row (p2 fixed) swept along p1 as an orbit diagram does, every cell starting
// from the end state of the one before (from rest at the row's first cell and
// after a failure), classified by ClassifyAttractor (basin/attractors.hpp).
// Rows are tasks of a bounded pool (parallel/pool.hpp); no exception crosses a thread.
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <exception>

#include "numerics/numbers.hpp"
#include "parallel/pool.hpp"
#include "stickslip/chart/forced_chart.hpp"

namespace stickslip {

ResponseGrid ForcedResponseGrid(const ForcedParams& base, const ForcedChartOptions& o,
                                bool* cancelled) {
  const Plane& pl = o.plane;
  ResponseGrid g;
  g.n1 = o.n1, g.n2 = o.n2;
  for (int i = 0; i < g.n1; ++i) g.x1.push_back(pl.from1 + (i + 0.5) * pl.width1() / g.n1);
  for (int j = 0; j < g.n2; ++j) g.x2.push_back(pl.from2 + (j + 0.5) * pl.width2() / g.n2);
  const size_t n = static_cast<size_t>(g.n1) * g.n2;
  g.cells.assign(n, Attractor());
  g.lyapunov_err.assign(n, 0);
  g.done.assign(n, 0);
  std::vector<std::string> why(n);
  AttractorOptions bo;  // the classifier's settings
  bo.iterate = o.iterate, bo.iterate.flow = o.flow, bo.max_period = o.max_period;
  bo.max_amplitude = o.max_amplitude;
  std::atomic<bool> stop{false};
  auto poll = [&] {
    if (stop.load(std::memory_order_relaxed)) return true;
    return false;
  };
  auto row = [&](int j) {
    FlowPoint z;
    bool fresh = true;
    for (int i = 0; i < g.n1 && !poll(); ++i) {
      const size_t k = static_cast<size_t>(j) * g.n1 + i;
      try {
        const ForcedModel model(pl.At(base, g.x1[i], g.x2[j]));
        if (fresh) z = ForcedStart(model, 0, 0, model.v());
        const SectionRun r = IterateStroboscopic(model, ForcedStart(model, 0, z.z[0], z.z[1]),
                                                 bo.iterate, poll, o.max_amplitude);
        if (r.status == LyapunovStatus::kCancelled) return;
        g.cells[k] = ClassifyAttractor(model, r, bo);
        g.lyapunov_err[k] = r.lyapunov_err;
        fresh = r.status != LyapunovStatus::kDone;
        if (!fresh) z = r.end;
        if (g.cells[k].kind == AttractorKind::kFailed) why[k] = r.message;
      } catch (const std::exception& ex) {
        g.cells[k].kind = AttractorKind::kFailed;
        why[k] = ex.what();
        fresh = true;
      }
      g.done[k] = 1;
    }
  };
  const PoolRun pool = RunPool(g.n2, o.threads, row, stop, [&] {
    return o.cancelled && o.cancelled();  // polled on the calling thread only
  });
  *cancelled = stop.load();
  if (!pool.ok() && pool.threads == 0) {  // no thread started: every cell failed, and why
    g.failed = static_cast<int>(n), g.failure = pool.error;
    return g;
  }
  for (size_t k = 0; k < n; ++k) {
    if (!g.done[k] || g.cells[k].kind != AttractorKind::kFailed) continue;
    if (g.failed++ == 0)
      g.failure = std::string("response cell ") + pl.p1.name() + " = " + Num(g.x1[k % g.n1], 6) +
                  ", " + pl.p2.name() + " = " + Num(g.x2[k / g.n1], 6) + ": " + why[k];
  }
  return g;
}

}  // namespace stickslip
