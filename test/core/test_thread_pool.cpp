#include <gtest/gtest.h>

#include <atomic>
#include <stdexcept>

#include "env/thread_pool.h"

namespace jetbot_rl {
namespace {

TEST(ThreadPool, RunsEveryWorkerOncePerRun) {
  ThreadPool pool(3);
  for (int round = 0; round < 200; ++round) {
    std::atomic<int> mask{0};
    pool.run(3, [&](int w) { mask |= 1 << w; });
    ASSERT_EQ(mask.load(), 7);
  }
}

TEST(ThreadPool, FewerWorkersThanThreads) {
  ThreadPool pool(4);
  std::atomic<int> count{0};
  pool.run(2, [&](int w) {
    EXPECT_LT(w, 2);
    ++count;
  });
  EXPECT_EQ(count.load(), 2);
}

TEST(ThreadPool, RethrowsAWorkersException) {
  ThreadPool pool(2);
  EXPECT_THROW(pool.run(2,
                        [](int w) {
                          if (w == 1) throw std::runtime_error("boom");
                        }),
               std::runtime_error);
  std::atomic<int> count{0};
  pool.run(2, [&](int) { ++count; });  // still usable
  EXPECT_EQ(count.load(), 2);
}

}  // namespace
}  // namespace jetbot_rl
