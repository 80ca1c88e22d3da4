// Same seed and actions give the same observations bit for bit, whatever the thread count.
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <thread>

#include "test_util.h"

namespace jetbot_rl {
namespace {

using namespace test;

TEST(Determinism, ThreadCountsOneAndTwoAgreeBitForBit) {
  BatchedEnv one(jetbot(), smallConfig(7, 1)), two(jetbot(), smallConfig(7, 2));
  ASSERT_EQ(two.numThreads(), 2);
  for (int s = 0; s < 350; ++s) {
    const StepResult& a = one.step(randomActions(7, s));
    const StepResult& b = two.step(randomActions(7, s));
    ASSERT_TRUE(bitEqual(a.observations, b.observations)) << "step " << s;
    ASSERT_TRUE(bitEqual(a.rewards, b.rewards)) << "step " << s;
    ASSERT_TRUE(bitEqual(a.final_observations, b.final_observations)) << "step " << s;
  }
}

TEST(Determinism, AnEnvDoesNotDependOnTheRestOfTheBatch) {
  BatchedEnv alone(jetbot(), smallConfig(1)), crowd(jetbot(), smallConfig(5, 2));
  for (int s = 0; s < 200; ++s) {
    auto actions = randomActions(5, s, 3);
    crowd.step(actions);
    alone.step(std::vector<float>(actions.begin() + 6, actions.begin() + 8));  // env 3's
    ASSERT_TRUE(bitEqual(alone.state().observations, envObs(crowd, 3))) << "step " << s;
  }
}

/// The seed task, but env 0's first reward waits until another thread than the caller (worker 0,
/// the owner of env 0's block) has stepped an env of that block: the step goes on only if idle
/// workers take envs from a busy one.
class StealingProbe : public VelocityTask {
 public:
  StealingProbe(int block_end) : block_end_(block_end), caller_(std::this_thread::get_id()) {}
  float reward(int env, const RootState& state) const override {
    std::unique_lock<std::mutex> lock(mutex_);
    if (env > 0 && env < block_end_ && std::this_thread::get_id() != caller_) {
      helped_ = true;
      helped_cv_.notify_all();
    }
    if (env == 0 && !waited_) {
      waited_ = true;
      waited_ok_ = helped_cv_.wait_for(lock, std::chrono::seconds(20), [this] { return helped_; });
    }
    return VelocityTask::reward(env, state);
  }
  bool helped() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return helped_ && waited_ok_;
  }

 private:
  const int block_end_;
  const std::thread::id caller_;
  mutable std::mutex mutex_;
  mutable std::condition_variable helped_cv_;
  mutable bool helped_ = false, waited_ = false, waited_ok_ = false;
};

TEST(Determinism, EnvsSteppedByAnotherWorkerAgreeBitForBit) {
  BatchedEnv one(jetbot(), smallConfig(8, 1));
  auto probe = std::make_unique<StealingProbe>(4);  // worker 0 of 2 owns envs 0-3
  const StealingProbe& seen = *probe;
  BatchedEnv two(jetbot(), smallConfig(8, 2), std::move(probe));
  for (int s = 0; s < 100; ++s) {
    const StepResult& a = one.step(randomActions(8, s));
    const StepResult& b = two.step(randomActions(8, s));
    ASSERT_TRUE(bitEqual(a.observations, b.observations)) << "step " << s;
    ASSERT_TRUE(bitEqual(a.rewards, b.rewards)) << "step " << s;
  }
  EXPECT_TRUE(seen.helped()) << "no env of worker 0's block was stepped by worker 1";
}

TEST(Determinism, DifferentActionsGiveDifferentObservations) {
  // Guards the tests above against comparing constants.
  BatchedEnv a(jetbot(), smallConfig(2)), b(jetbot(), smallConfig(2));
  a.step(randomActions(2, 0, 1));
  b.step(randomActions(2, 0, 2));
  for (int s = 1; s < 20; ++s) {
    a.step(randomActions(2, s, 1));
    b.step(randomActions(2, s, 2));
  }
  EXPECT_FALSE(bitEqual(a.state().observations, b.state().observations));
}

}  // namespace
}  // namespace jetbot_rl
