#include "batch_rows.hpp"

#include <algorithm>
#include <exception>

#include "parallel/pool.hpp"

namespace stickslip::batch_detail {

bool RowQueue::Take(std::size_t* begin, std::size_t* end) {
  if (stop_.load()) return false;
  *begin = next_.fetch_add(block_);
  if (*begin >= rows_) return false;
  *end = std::min(rows_, *begin + block_);
  return true;
}

void RowQueue::Done(std::size_t n) {
  const std::size_t done = done_.fetch_add(n, std::memory_order_relaxed) + n;
  if (progress_ && *progress_) (*progress_)(done);
}

bool RowQueue::Cancelled() {
  if (hook_ && *hook_ && !stop_.load(std::memory_order_relaxed) && (*hook_)()) stop_ = true;
  return stop_.load(std::memory_order_relaxed);
}

RowsRun RunRows(RowQueue& queue, int threads, std::size_t thread_rows,
                const std::function<bool()>& cancelled,
                const std::function<void(std::size_t)>& progress,
                const std::function<void(RowQueue&)>& work) {
  RowsRun run;
  const int workers = static_cast<int>(std::min<std::size_t>(
      BoundedThreads(threads), (queue.rows_ + thread_rows - 1) / thread_rows));
  if (workers <= 1) {  // on this thread: no thread to start
    queue.hook_ = &cancelled;
    queue.progress_ = &progress;
    try {
      work(queue);
    } catch (const std::exception& e) {  // as the pool reports a task's exception
      run.error = std::string("task 0: ") + e.what();
    }
    run.threads = 1;
  } else {
    const PoolRun pool = RunPool(
        workers, workers, [&](int) { work(queue); }, queue.stop_,
        [&] {
          if (progress) progress(queue.done());
          return cancelled && cancelled();
        });
    run.threads = pool.threads;
    run.error = pool.error;
  }
  run.cancelled = queue.stop_.load();
  return run;
}

}  // namespace stickslip::batch_detail
