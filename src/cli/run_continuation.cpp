#include "cli/run_continuation.hpp"

#include <chrono>
#include <condition_variable>
#include <exception>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "stickslip/branch_report.hpp"
#include "stickslip/errors.hpp"
#include "stickslip/report.hpp"

namespace stickslip::cli {
namespace {

// What the continuation's worker thread shares with the main thread.
struct Shared {
  std::mutex m;
  std::condition_variable cv;
  bool done = false, abandoned = false;
  bool cancel = false;              // set by the main thread on a signal or --max_time
  std::vector<BranchPoint> points;  // as reported, for an abandoned run
  double last = 0;
  bool periodic = false;     // a periodic orbit has been reported
  double last_periodic = 0;  // where the last one was
  bool searching = false;    // the last point reported is steady sliding: between branches
  ContinuationResult result;
  std::exception_ptr error;
};

// The library polls cancellation between CVODE returns, and one return can
// take seconds on a stiff model (v_m = 1e-6): past this grace after a signal
// or --max_time, the app goes on with the points reported so far and leaves
// the worker behind (it ends with the process, ExitLeavingWorker).
constexpr double kGraceSeconds = 2.0;

}  // namespace

// Runs the continuation on a worker thread with cancellation and progress; an
// InvalidArgument escaping the library after validation is a numerical
// failure (exit 1). *abandoned: the worker is still running.
ContinuationResult RunContinuation(const Params& base, ContinuationOptions opts, RunControl& run,
                                   bool* abandoned) {
  auto sh = std::make_shared<Shared>();
  sh->last = opts.from;
  const std::string param = opts.param;
  // Polled after every integration step (a few microseconds): no clock here.
  // The main thread below reads the clock every 50 ms and sets sh->cancel.
  opts.cancelled = [sh, &run] {
    std::lock_guard<std::mutex> lock(sh->m);
    return sh->abandoned || sh->cancel || run.Signalled();
  };
  opts.progress = [sh, &run, opts](const BranchPoint& pt) {
    std::lock_guard<std::mutex> lock(sh->m);
    if (sh->abandoned) return;
    sh->searching = pt.kind == PointKind::kEquilibrium;
    if (!sh->searching) sh->periodic = true, sh->last_periodic = pt.p;
    sh->last = pt.p;
    sh->points.push_back(pt);
    if (run.ProgressDue())
      run.Progress(opts.param + " = " + FormatNumber(pt.p) + " (" + PointKindName(pt.kind) + ")",
                   (pt.p - opts.from) / (opts.to - opts.from),
                   static_cast<double>(sh->points.size()), "points");
  };
  run.Phase("continuing");
  std::thread worker([sh, base, opts] {
    ContinuationResult r;
    std::exception_ptr error;
    try {
      r = Continue(base, opts);
    } catch (...) {
      error = std::current_exception();
    }
    std::lock_guard<std::mutex> lock(sh->m);
    sh->result = std::move(r);
    sh->error = error;
    sh->done = true;
    sh->cv.notify_all();
  });
  std::unique_lock<std::mutex> lock(sh->m);
  double cancelled_at = -1;
  while (!sh->done && !sh->abandoned) {
    sh->cv.wait_for(lock, std::chrono::milliseconds(50));
    if (sh->done) break;
    // Steady sliding is reported whole between branches: after it the library
    // is searching, not at its last row.
    const std::string at = param + " = " + FormatNumber(sh->last_periodic);
    run.Heartbeat(!sh->periodic   ? std::string("searching for a periodic orbit")
                  : sh->searching ? "searching for more periodic orbits (last found at " + at + ")"
                                  : "last periodic orbit at " + at);
    if (cancelled_at < 0 && run.Cancelled()) {
      cancelled_at = run.Elapsed();
      sh->cancel = true;
    }
    if (cancelled_at >= 0 && run.Elapsed() > cancelled_at + kGraceSeconds) sh->abandoned = true;
  }
  *abandoned = !sh->done;
  lock.unlock();
  if (*abandoned) {
    worker.detach();
  } else {
    worker.join();
  }
  ContinuationResult r;
  if (sh->done && sh->error) {
    try {
      std::rethrow_exception(sh->error);
    } catch (const InvalidArgument& e) {
      throw Error("numerical failure in the continuation near " + param + " = " +
                  FormatNumber(sh->last) + ": " + e.what());
    }
  }
  if (sh->done) {
    r = std::move(sh->result);
  } else {
    r.points = sh->points;
    r.status = ContinuationStatus::kCancelled;
  }
  // Where the branch stopped, not where it was headed: the last periodic point.
  if (r.status == ContinuationStatus::kCancelled) {
    const BranchPoint* at = nullptr;
    for (const auto& pt : r.points)
      if (pt.kind != PointKind::kEquilibrium) at = &pt;
    r.message = (at ? "cancelled at " + param + " = " + FormatNumber(at->p)
                    : std::string("cancelled before the first periodic orbit")) +
                " (" + run.Reason() + ")" +
                (*abandoned ? "; the library did not return within 2 s, special points lost" : "");
  }
  DropNonFinite(&r, param);
  return r;
}

}  // namespace stickslip::cli
