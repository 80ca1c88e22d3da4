#include "thread_pool.h"

namespace jetbot_rl {

ThreadPool::ThreadPool(int size) {
  for (int w = 1; w < size; ++w) threads_.emplace_back(&ThreadPool::loop, this, w);
}

ThreadPool::~ThreadPool() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stop_ = true;
  }
  start_.notify_all();
  for (auto& t : threads_) t.join();
}

void ThreadPool::run(int workers, const std::function<void(int)>& job) {
  workers = std::max(1, std::min(workers, size()));
  {
    std::lock_guard<std::mutex> lock(mutex_);
    job_ = &job;
    active_workers_ = workers;
    pending_ = workers - 1;
    error_ = nullptr;
    ++generation_;
  }
  if (workers > 1) start_.notify_all();
  std::exception_ptr own_error;
  try {
    job(0);
  } catch (...) {
    own_error = std::current_exception();
  }
  std::unique_lock<std::mutex> lock(mutex_);
  done_.wait(lock, [this] { return pending_ == 0; });
  job_ = nullptr;
  if (own_error) std::rethrow_exception(own_error);
  if (error_) std::rethrow_exception(error_);
}

void ThreadPool::loop(int worker) {
  unsigned long seen = 0;
  for (;;) {
    const std::function<void(int)>* job;
    {
      std::unique_lock<std::mutex> lock(mutex_);
      start_.wait(lock, [&] { return stop_ || (generation_ != seen && worker < active_workers_); });
      if (stop_) return;
      seen = generation_;
      job = job_;
    }
    std::exception_ptr error;
    try {
      (*job)(worker);
    } catch (...) {
      error = std::current_exception();
    }
    std::lock_guard<std::mutex> lock(mutex_);
    if (error && !error_) error_ = error;
    if (--pending_ == 0) done_.notify_one();
  }
}

}  // namespace jetbot_rl
