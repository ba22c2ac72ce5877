// A bounded pool of worker threads (issue 35): at most the machine's hardware
// threads run, however many tasks or threads a caller asks for, and a thread
// that cannot be started is a status, never std::terminate. Tasks never throw
// across a thread: one that does is recorded as the run's error.
#pragma once

#include <atomic>
#include <functional>
#include <string>

namespace stickslip {

/// The machine's hardware threads (std::thread::hardware_concurrency), >= 1.
int HardwareThreads();

/// requested capped by HardwareThreads(); 0 or less asks for all of them.
int BoundedThreads(long long requested);

struct PoolRun {
  int threads = 0;    ///< worker threads that ran (0: none could start)
  std::string error;  ///< why no thread started, or a task's escaped exception
  bool ok() const { return error.empty(); }
};

/// Runs task(k) for k = 0 .. tasks - 1, each once, on min(BoundedThreads(threads),
/// tasks) workers that take the next k until none is left or `stop` is set.
/// The calling thread waits, calling poll() every 20 ms (on it alone: a
/// cancel hook, progress); poll returning true sets `stop`. It returns as soon
/// as the last worker ends (not at the next 20 ms tick). A thread that
/// fails to start leaves the tasks to those that did; if none did, no task
/// runs and error says why.
PoolRun RunPool(int tasks, int threads, const std::function<void(int)>& task,
                std::atomic<bool>& stop, const std::function<bool()>& poll);

}  // namespace stickslip
