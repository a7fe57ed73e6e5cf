#include "thread_pool.hpp"

namespace pxflow {

ThreadPool::ThreadPool(int threads) {
  const unsigned cores = std::thread::hardware_concurrency();
  size_ = threads > 0 ? threads : static_cast<int>(cores > 0 ? cores : 1);
}

ThreadPool::~ThreadPool() {
  {
    const std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_all();
  for (auto& t : helpers_) t.join();
}

void ThreadPool::for_each(std::size_t n, const std::function<void(std::size_t)>& task) {
  if (size_ == 1 || n <= 1) {  // nothing to spread: no hand-off cost
    for (std::size_t i = 0; i < n; ++i) task(i);
    return;
  }
  if (helpers_.empty())
    for (int i = 1; i < size_; ++i) helpers_.emplace_back([this] { worker_loop(); });
  {
    const std::lock_guard lock(mutex_);
    task_ = &task;
    count_ = n;
    next_ = finished_ = 0;
    error_ = nullptr;
    ++generation_;
  }
  wake_.notify_all();
  drain();
  std::unique_lock lock(mutex_);
  done_.wait(lock, [&] { return finished_ == count_; });
  task_ = nullptr;
  if (error_) std::rethrow_exception(error_);
}

void ThreadPool::drain() {
  std::unique_lock lock(mutex_);
  while (task_ && next_ < count_) {
    const std::size_t i = next_++;
    const auto* task = task_;
    lock.unlock();
    std::exception_ptr failure;
    try {
      (*task)(i);
    } catch (...) {
      failure = std::current_exception();
    }
    lock.lock();
    if (failure && !error_) error_ = failure;
    if (++finished_ == count_) done_.notify_all();
  }
}

void ThreadPool::worker_loop() {
  std::size_t seen = 0;
  for (;;) {
    {
      std::unique_lock lock(mutex_);
      wake_.wait(lock, [&] { return stopping_ || (generation_ != seen && task_); });
      if (stopping_) return;
      seen = generation_;
    }
    drain();
  }
}

}  // namespace pxflow
