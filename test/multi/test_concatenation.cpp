// Two env nodes stepped as one batch (connectEnvs: a MultiVecEnv of RosVecEnvs) give, bit for
// bit, the concatenation of what each node gives alone with its derived seed.
#include <gtest/gtest.h>
#include <ros/ros.h>

#include <cstring>
#include <random>

#include "jetbot_rl/env/multi_vec_env.h"
#include "jetbot_rl/ros/client/connect_envs.h"

namespace jetbot_rl {
namespace {

constexpr double kTimeout = 30.0;
constexpr int kSteps = 60;

bool bitEqual(const std::vector<float>& a, const std::vector<float>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0;
}

std::vector<float> actionsFor(int step, int num_envs) {
  std::mt19937 gen(static_cast<unsigned>(step));
  std::uniform_real_distribution<float> target(-20.0f, 20.0f);
  std::vector<float> a(static_cast<std::size_t>(num_envs) * 2);
  for (auto& x : a) x = target(gen);
  return a;
}

/// Observations and rewards of kSteps steps from a reset with `seed`.
std::vector<std::vector<float>> rollout(VecEnv& env, std::int64_t seed, int offset, int count) {
  std::vector<std::vector<float>> out;
  const int n = env.spec().num_envs;
  out.push_back(env.reset(seed).observations);
  for (int s = 0; s < kSteps; ++s) {
    const std::vector<float> all = actionsFor(s, 5);
    const std::vector<float> mine(all.begin() + 2 * offset, all.begin() + 2 * (offset + count));
    EXPECT_EQ(static_cast<int>(mine.size()), 2 * n);
    const StepResult& r = env.step(mine);
    out.push_back(r.observations);
    out.push_back(r.rewards);
  }
  return out;
}

TEST(Concatenation, TwoNodesAsOneBatchAreTheNodesAlone) {
  std::vector<std::vector<float>> together, a, b;
  {
    const auto multi = connectEnvs({"jetbot_env_a", "jetbot_env_b"}, true, kTimeout, nullptr);
    ASSERT_EQ(multi->spec().num_envs, 5);
    together = rollout(*multi, 11, 0, 5);
  }
  {
    const auto alone = connectEnvs({"jetbot_env_a"}, true, kTimeout, nullptr);
    a = rollout(*alone, MultiVecEnv::partSeed(11, 0), 0, 3);
  }
  {
    const auto alone = connectEnvs({"jetbot_env_b"}, true, kTimeout, nullptr);
    b = rollout(*alone, MultiVecEnv::partSeed(11, 1), 3, 2);
  }
  ASSERT_EQ(together.size(), a.size());
  for (std::size_t i = 0; i < together.size(); ++i) {
    std::vector<float> joined = a[i];
    joined.insert(joined.end(), b[i].begin(), b[i].end());
    ASSERT_TRUE(bitEqual(together[i], joined)) << "row " << i;
  }
  // The seeds matter: node b alone with node a's seed gives other commands.
  const auto alone = connectEnvs({"jetbot_env_b"}, true, kTimeout, nullptr);
  EXPECT_FALSE(bitEqual(alone->reset(11).observations, b[0]));
}

}  // namespace
}  // namespace jetbot_rl

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_concatenation");
  ros::NodeHandle nh;  // keeps the node up while the test's VecEnvs come and go
  return RUN_ALL_TESTS();
}
