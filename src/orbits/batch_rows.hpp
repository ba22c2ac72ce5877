// The worker scheme of the batched orbit entries (orbit_batch.cpp,
// system_batch.cpp): rows taken in blocks from a shared counter by at most
// `threads` workers of the bounded pool (parallel/pool.hpp), one worker per
// `thread_rows` rows at most; one worker runs on the calling thread, which
// alone calls the cancel hook and the progress callback.
#pragma once

#include <atomic>
#include <cstddef>
#include <functional>
#include <string>

namespace stickslip::batch_detail {

struct RowsRun {
  int threads = 0;
  bool cancelled = false;
  std::string error;  ///< no worker could start, or a worker's exception
};

class RowQueue;
RowsRun RunRows(RowQueue& queue, int threads, std::size_t thread_rows,
                const std::function<bool()>& cancelled,
                const std::function<void(std::size_t)>& progress,
                const std::function<void(RowQueue&)>& work);

class RowQueue {
 public:
  RowQueue(std::size_t rows, std::size_t block) : rows_(rows), block_(block) {}
  /// The next block of rows [*begin, *end); false once none is left or stopped.
  bool Take(std::size_t* begin, std::size_t* end);
  /// n more rows done (reported to progress on the calling thread).
  void Done(std::size_t n);
  /// Whether the run is stopped; on the calling thread it polls the cancel hook.
  bool Cancelled();
  std::size_t done() const { return done_.load(std::memory_order_relaxed); }

 private:
  friend RowsRun RunRows(RowQueue&, int, std::size_t, const std::function<bool()>&,
                         const std::function<void(std::size_t)>&,
                         const std::function<void(RowQueue&)>&);
  std::size_t rows_, block_;
  std::atomic<std::size_t> next_{0}, done_{0};
  std::atomic<bool> stop_{false};
  const std::function<bool()>* hook_ = nullptr;                 // one worker only
  const std::function<void(std::size_t)>* progress_ = nullptr;  // one worker only
};

/// Runs work(queue) on min(BoundedThreads(threads), ceil(rows / thread_rows))
/// workers. cancelled and progress may be empty.
RowsRun RunRows(RowQueue& queue, int threads, std::size_t thread_rows,
                const std::function<bool()>& cancelled,
                const std::function<void(std::size_t)>& progress,
                const std::function<void(RowQueue&)>& work);

}  // namespace stickslip::batch_detail
