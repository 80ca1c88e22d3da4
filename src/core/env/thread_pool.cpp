#include "env/thread_pool.h"

#include <algorithm>

namespace jetbot_rl {
namespace {

constexpr std::uint64_t pack(int front, int back) {
  return static_cast<std::uint64_t>(static_cast<std::uint32_t>(back)) << 32 |
         static_cast<std::uint32_t>(front);
}

/// Takes the first (or, from the back, the last) item of a block's untaken range; -1 when empty.
int claim(std::atomic<std::uint64_t>& range, bool from_back) {
  std::uint64_t r = range.load(std::memory_order_relaxed);
  for (;;) {
    const int front = static_cast<int>(r & 0xffffffffu);
    const int back = static_cast<int>(r >> 32);
    if (front >= back) return -1;
    const std::uint64_t rest = from_back ? pack(front, back - 1) : pack(front + 1, back);
    if (range.compare_exchange_weak(r, rest, std::memory_order_relaxed)) {
      return from_back ? back - 1 : front;
    }
  }
}

}  // namespace

ThreadPool::ThreadPool(int size) : blocks_(std::make_unique<Block[]>(std::max(size, 1))) {
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

// Worker w runs its own block front to back, then takes items from the back of the others'
// blocks: a thread that was held up (a descheduled core, slower items) no longer holds the whole
// run up, and a helper never works next to the block's owner.
void ThreadPool::runStealing(int count, const std::function<void(int, int)>& job) {
  const int workers = size();
  for (int w = 0; w < workers; ++w) {
    blocks_[w].range.store(pack(firstItemOf(w, count), firstItemOf(w + 1, count)),
                           std::memory_order_relaxed);
  }
  run(workers, [this, workers, &job](int w) {
    for (int i; (i = claim(blocks_[w].range, false)) >= 0;) job(i, w);
    for (int k = 1; k < workers; ++k) {
      auto& range = blocks_[(w + k) % workers].range;
      for (int i; (i = claim(range, true)) >= 0;) job(i, w);
    }
  });
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
