// A small fixed pool for the host-side backends (CPU kernels, the GAP8 model): spreads the
// items of a batch (frame pairs, model runs) over workers.
// Each item is written by exactly one worker into its own place, so the output bytes do not
// depend on the thread count or on scheduling.
#pragma once
#include <condition_variable>
#include <cstddef>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace pxflow {

class ThreadPool {
 public:
  // `threads` workers in all, the calling thread included; 0 = every core of this machine.
  explicit ThreadPool(int threads);
  ~ThreadPool();
  ThreadPool(const ThreadPool&) = delete;
  ThreadPool& operator=(const ThreadPool&) = delete;

  int size() const { return size_; }

  // Calls task(i) once for every i in [0, n), spread over the workers, and returns when all
  // are done. Rethrows the first exception a task threw (the other items still run).
  void for_each(std::size_t n, const std::function<void(std::size_t)>& task);

 private:
  void worker_loop();
  void drain();  // runs items until none is left

  int size_ = 1;
  std::vector<std::thread> helpers_;  // started on first use, size_ - 1 of them
  std::mutex mutex_;
  std::condition_variable wake_, done_;
  const std::function<void(std::size_t)>* task_ = nullptr;
  std::size_t count_ = 0, next_ = 0, finished_ = 0;
  std::size_t generation_ = 0;
  bool stopping_ = false;
  std::exception_ptr error_;
};

}  // namespace pxflow
