#pragma once

#include <condition_variable>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace jetbot_rl {

/// Fixed worker threads with blocking (not spinning) hand-offs; the caller is worker 0.
class ThreadPool {
 public:
  /// Starts size - 1 threads (size >= 1).
  explicit ThreadPool(int size);
  ~ThreadPool();
  ThreadPool(const ThreadPool&) = delete;
  ThreadPool& operator=(const ThreadPool&) = delete;

  int size() const { return static_cast<int>(threads_.size()) + 1; }
  /// Runs job(w) for w in [0, workers) concurrently, workers <= size(); returns when all are
  /// done and rethrows the first exception a job threw.
  void run(int workers, const std::function<void(int)>& job);

 private:
  void loop(int worker);

  std::vector<std::thread> threads_;
  std::mutex mutex_;
  std::condition_variable start_;
  std::condition_variable done_;
  const std::function<void(int)>* job_ = nullptr;
  int active_workers_ = 0;
  int pending_ = 0;
  unsigned long generation_ = 0;
  bool stop_ = false;
  std::exception_ptr error_;
};

}  // namespace jetbot_rl
