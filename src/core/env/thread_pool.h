#pragma once

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <exception>
#include <functional>
#include <memory>
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

  /// First item of worker `worker`'s block when `count` items are split into size() contiguous
  /// blocks (worker size() gives `count`).
  int firstItemOf(int worker, int count) const {
    return static_cast<int>(static_cast<long long>(worker) * count / size());
  }
  /// Runs job(item, worker) once for every item in [0, count) on all workers: each takes its own
  /// block front to back, then takes the items still waiting from the back of the other blocks,
  /// so that one slow thread does not hold the whole run up. Which worker runs an item varies
  /// from run to run; rethrows the first exception a job threw.
  void runStealing(int count, const std::function<void(int, int)>& job);

 private:
  /// The items of a worker's block not yet taken in the current run: [front, back) packed into
  /// one word (front in the low half), so that the owner (front) and helpers (back) claim items
  /// with one compare-and-swap. One cache line each.
  struct alignas(64) Block {
    std::atomic<std::uint64_t> range{0};
  };

  void loop(int worker);

  std::vector<std::thread> threads_;
  std::unique_ptr<Block[]> blocks_;  // per worker, for runStealing()
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
