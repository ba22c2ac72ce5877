#include "cli/run_continuation.hpp"

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <deque>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "stickslip/errors.hpp"
#include "stickslip/io/branch_report.hpp"
#include "stickslip/io/report.hpp"

namespace stickslip::cli {
namespace {

// What the continuation's worker thread shares with the main thread. The
// worker is always joined: no reference it holds outlives the call.
struct Shared {
  std::mutex m;
  std::condition_variable cv;
  bool done = false;
  // Set by the main thread on a signal or --max_time; read without the lock
  // after every integration step (an atomic: no mutex per step).
  std::atomic<bool> cancel{false};
  // As reported, for a run that failed by an exception; a deque grows without
  // copying what it holds (a dense branch reports thousands of points).
  std::deque<BranchPoint> points;
  double last = 0;
  bool periodic = false;     // a periodic orbit has been reported
  double last_periodic = 0;  // where the last one was
  bool searching = false;    // the last point reported is steady sliding: between branches
  ContinuationResult result;
};

// Continue() with every failure turned into a status: no exception leaves the
// worker thread (an InvalidArgument after validation is a numerical failure).
ContinuationResult ContinueAsStatus(const Params& base, const ContinuationOptions& opts,
                                    Shared& sh) {
  std::string why;
  try {
    return Continue(base, opts);
  } catch (const std::exception& e) {
    why = e.what();
  } catch (...) {
    why = "unknown exception";
  }
  ContinuationResult r;
  r.param = opts.param;  // the tables' parameter column
  std::lock_guard<std::mutex> lock(sh.m);
  r.points.assign(sh.points.begin(), sh.points.end());
  r.status = ContinuationStatus::kFailed;
  r.message = "numerical failure in the continuation near " + opts.param.name() + " = " +
              FormatNumber(sh.last) + ": " + why;
  return r;
}

}  // namespace

// Runs the continuation on a worker thread with cancellation and progress;
// the main thread polls the clock and prints the heartbeat meanwhile.
ContinuationResult RunContinuation(const Params& base, ContinuationOptions opts, RunControl& run) {
  auto sh = std::make_shared<Shared>();
  sh->last = opts.from;
  const std::string param = opts.param.name();
  // Polled after every integration step (a few microseconds): no clock here.
  // The main thread below reads the clock every 50 ms and sets sh->cancel.
  opts.cancelled = [sh, &run] {
    return sh->cancel.load(std::memory_order_relaxed) || run.Signalled();
  };
  opts.progress = [sh, &run, opts](const BranchPoint& pt) {
    std::lock_guard<std::mutex> lock(sh->m);
    sh->searching = pt.kind == PointKind::kEquilibrium;
    if (!sh->searching) sh->periodic = true, sh->last_periodic = pt.p;
    sh->last = pt.p;
    sh->points.push_back(pt);
    if (run.ProgressDue())
      run.Progress(opts.param.name() + " = " + FormatNumber(pt.p) + " (" + Name(pt.kind) + ")",
                   (pt.p - opts.from) / (opts.to - opts.from),
                   static_cast<double>(sh->points.size()), "points");
  };
  run.Phase("continuing");
  std::thread worker([sh, &base, &opts] {
    ContinuationResult r = ContinueAsStatus(base, opts, *sh);
    std::lock_guard<std::mutex> lock(sh->m);
    sh->result = std::move(r);
    sh->done = true;
    sh->cv.notify_all();
  });
  {
    std::unique_lock<std::mutex> lock(sh->m);
    while (!sh->done) {
      sh->cv.wait_for(lock, std::chrono::milliseconds(50));
      if (sh->done) break;
      // Steady sliding is reported whole between branches: after it the
      // library is searching, not at its last row.
      const std::string at = param + " = " + FormatNumber(sh->last_periodic);
      run.Heartbeat(!sh->periodic ? std::string("searching for a periodic orbit")
                    : sh->searching
                        ? "searching for more periodic orbits (last found at " + at + ")"
                        : "last periodic orbit at " + at);
      if (run.Cancelled()) sh->cancel = true;
    }
  }
  worker.join();
  ContinuationResult r = std::move(sh->result);
  // Where the branch stopped, not where it was headed: the last periodic point.
  if (r.status == ContinuationStatus::kCancelled) {
    const BranchPoint* at = nullptr;
    for (const auto& pt : r.points)
      if (pt.kind != PointKind::kEquilibrium) at = &pt;
    r.message = (at ? "cancelled at " + param + " = " + FormatNumber(at->p)
                    : std::string("cancelled before the first periodic orbit")) +
                " (" + run.Reason() + ")";
  }
  DropNonFinite(&r);
  return r;
}

}  // namespace stickslip::cli
