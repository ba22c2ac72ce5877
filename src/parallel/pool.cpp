#include "parallel/pool.hpp"

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <system_error>
#include <thread>
#include <vector>

namespace stickslip {

int HardwareThreads() { return std::max(1u, std::thread::hardware_concurrency()); }

int BoundedThreads(long long requested) {
  const int hw = HardwareThreads();
  return requested <= 0 ? hw : static_cast<int>(std::min<long long>(requested, hw));
}

PoolRun RunPool(int tasks, int threads, const std::function<void(int)>& task,
                std::atomic<bool>& stop, const std::function<bool()>& poll) {
  PoolRun r;
  if (tasks <= 0) return r;
  std::atomic<int> next{0}, running{0};
  std::mutex error_mutex, done_mutex;
  std::condition_variable done;  // the last worker's exit ends the caller's wait at once
  std::string escaped;
  auto work = [&] {
    for (int k; !stop.load() && (k = next.fetch_add(1)) < tasks;) {
      try {
        task(k);
      } catch (const std::exception& e) {  // no exception crosses a thread
        const std::lock_guard<std::mutex> lock(error_mutex);
        if (escaped.empty()) escaped = "task " + std::to_string(k) + ": " + e.what();
      } catch (...) {
        const std::lock_guard<std::mutex> lock(error_mutex);
        if (escaped.empty()) escaped = "task " + std::to_string(k) + ": unknown exception";
      }
    }
    {
      const std::lock_guard<std::mutex> lock(done_mutex);
      running.fetch_sub(1);
    }
    done.notify_all();
  };
  const int want = std::min(BoundedThreads(threads), tasks);
  std::vector<std::thread> workers;
  workers.reserve(want);
  std::string start_error;
  for (int t = 0; t < want; ++t) {
    running.fetch_add(1);
    try {
      workers.emplace_back(work);
    } catch (const std::system_error& e) {  // EAGAIN: threads or memory exhausted
      running.fetch_sub(1);
      start_error = e.what();
      break;
    }
  }
  r.threads = static_cast<int>(workers.size());
  if (r.threads == 0) {
    r.error = "no worker thread could start (" + start_error + ")";
    return r;
  }
  std::unique_lock<std::mutex> lock(done_mutex);
  while (!done.wait_for(lock, std::chrono::milliseconds(20), [&] { return running.load() == 0; })) {
    lock.unlock();
    if (poll && !stop.load() && poll()) stop = true;
    lock.lock();
  }
  lock.unlock();
  for (std::thread& w : workers) w.join();
  r.error = escaped;
  return r;
}

}  // namespace stickslip
