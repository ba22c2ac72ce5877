// The response grid (stickslip/chart/response_grid.hpp). Rows are tasks of a
// bounded pool (parallel/pool.hpp); no exception crosses a thread.
#include "stickslip/chart/response_grid.hpp"

#include <atomic>
#include <chrono>
#include <exception>
#include <memory>

#include "numerics/numbers.hpp"
#include "parallel/pool.hpp"
#include "stickslip/errors.hpp"
#include "stickslip/flow/switching.hpp"

namespace stickslip {

std::string ResponseOptions::ValidationError(const System& system) const {
  if (n1 < 1 || n2 < 1 || n1 > kMaxSide || n2 > kMaxSide)
    return "the response grid's sides " + std::to_string(n1) + " x " + std::to_string(n2) +
           " must lie in [1, " + std::to_string(kMaxSide) + "]";
  if (!(attractor.max_amplitude > 0)) return "max_amplitude must be > 0";
  return attractor.ValidationError(system);
}

FlowPoint BeltStart(const System& s) {
  if (const std::string e = ContactVelocityError(s); !e.empty()) throw InvalidArgument(e);
  FlowPoint p{0, Eigen::VectorXd::Zero(s.dimension()), ModeSet()};
  for (int c = 0; c < s.contacts(); ++c) OntoSurface(s.Contact(c), p.z);
  p.mode = ModeOf(s, p.z);
  return p;
}

namespace {

// One row of cells, p2 = g.x2[j], each from the end of the one before.
class Row {
 public:
  Row(const System& base, const SystemPlane& pl, const ResponseOptions& o, ResponseGrid& g,
      std::vector<std::string>& why, const std::function<bool()>& poll)
      : base_(base), pl_(pl), o_(o), g_(g), why_(why), poll_(poll) {}
  void operator()(int j) const;

 private:
  const System& base_;
  const SystemPlane& pl_;
  const ResponseOptions& o_;
  ResponseGrid& g_;
  std::vector<std::string>& why_;
  const std::function<bool()>& poll_;
};

void Row::operator()(int j) const {
  std::unique_ptr<System> s;
  const AttractorOptions& bo = o_.attractor;
  FlowPoint z;
  bool fresh = true;
  for (int i = 0; i < g_.n1 && !poll_(); ++i) {
    const size_t k = static_cast<size_t>(j) * g_.n1 + i;
    try {
      if (!s) s = base_.Clone();
      s->SetParameterValue(pl_.p1, g_.x1[i]);
      s->SetParameterValue(pl_.p2, g_.x2[j]);
      if (const std::string e = s->ValidationError(); !e.empty()) throw InvalidArgument(e);
      if (fresh) z = BeltStart(*s);
      const FlowPoint start{0, z.z, ModeOf(*s, z.z)};
      const SectionRun r =
          IterateSection(*s, start, AttractorSection(*s, bo), bo.iterate, poll_, bo.max_amplitude);
      if (r.status == LyapunovStatus::kCancelled) return;
      g_.cells[k] = ClassifyAttractor(*s, r, bo);
      g_.lyapunov_err[k] = r.lyapunov_err;
      fresh = r.status != LyapunovStatus::kDone && r.status != LyapunovStatus::kRest;
      if (!fresh) z = r.end;
      if (g_.cells[k].kind == AttractorKind::kFailed) why_[k] = r.message;
    } catch (const std::exception& ex) {
      g_.cells[k].kind = AttractorKind::kFailed;
      why_[k] = ex.what();
      fresh = true;
    }
    g_.done[k] = 1;
  }
}

}  // namespace

ResponseGrid Responses(const System& system, const SystemPlane& pl, const ResponseOptions& o) {
  std::string e = pl.ValidationError(system);
  if (e.empty()) e = o.ValidationError(system);
  if (!e.empty()) throw InvalidArgument(e);
  const auto t0 = std::chrono::steady_clock::now();
  ResponseGrid g;
  g.n1 = o.n1, g.n2 = o.n2;
  for (int i = 0; i < g.n1; ++i) g.x1.push_back(pl.from1 + (i + 0.5) * (pl.to1 - pl.from1) / g.n1);
  for (int j = 0; j < g.n2; ++j) g.x2.push_back(pl.from2 + (j + 0.5) * (pl.to2 - pl.from2) / g.n2);
  const size_t n = static_cast<size_t>(g.n1) * g.n2;
  g.cells.assign(n, Attractor());
  g.lyapunov_err.assign(n, 0);
  g.done.assign(n, 0);
  std::vector<std::string> why(n);
  std::atomic<bool> stop{false};
  const std::function<bool()> poll = [&stop] { return stop.load(std::memory_order_relaxed); };
  const PoolRun pool = RunPool(g.n2, o.attractor.threads, Row(system, pl, o, g, why, poll), stop,
                               [&o] { return o.cancelled && o.cancelled(); });
  g.cancelled = stop.load();
  g.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (!pool.ok() && pool.threads == 0) {  // no thread started: every cell failed, and why
    g.failed = static_cast<int>(n), g.failure = pool.error;
    return g;
  }
  if (!pool.ok()) {  // a task's escaped error (none expected: each cell catches its own)
    g.failed = 1, g.failure = pool.error;
    for (size_t k = 0; k < n; ++k)
      g.failed += g.done[k] && g.cells[k].kind == AttractorKind::kFailed;
    return g;
  }
  for (size_t k = 0; k < n; ++k) {
    if (!g.done[k] || g.cells[k].kind != AttractorKind::kFailed) continue;
    if (g.failed++ == 0)
      g.failure = "response cell " + system.ParameterName(pl.p1) + " = " + Num(g.x1[k % g.n1], 6) +
                  ", " + system.ParameterName(pl.p2) + " = " + Num(g.x2[k / g.n1], 6) + ": " +
                  why[k];
  }
  return g;
}

}  // namespace stickslip
