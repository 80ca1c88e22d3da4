// Same seed and actions give the same observations bit for bit, whatever the thread count.
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
