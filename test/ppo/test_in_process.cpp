// The trainer on real physics, in-process (LocalVecEnv over BatchedEnv, no ROS).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "jetbot_rl/env/local_vec_env.h"
#include "jetbot_rl/ppo/runner.h"

namespace jetbot_rl {
namespace ppo {
namespace {

std::unique_ptr<LocalVecEnv> jetbots(int num_envs) {
  EnvConfig config;
  config.num_envs = num_envs;
  config.num_threads = 1;
  return std::make_unique<LocalVecEnv>(
      std::make_unique<BatchedEnv>(RobotModel::fromUrdfFile(JETBOT_URDF), config));
}

TEST(InProcess, PpoLearnsToDriveTheJetbot) {
  auto env = jetbots(32);
  RunnerOptions o;
  o.iterations = 30;
  o.run_dir = (std::filesystem::temp_directory_path() / "jetbot_rl_test_in_process").string();
  std::filesystem::remove_all(o.run_dir);
  OnPolicyRunner runner(*env, PpoConfig(), o);
  runner.setLogger([](const std::string&) {});
  std::vector<double> rewards;
  runner.setIterationCallback(
      [&rewards](const IterationStats& s) { rewards.push_back(s.mean_reward_per_step); });
  const TrainingSummary s = runner.learn();
  EXPECT_TRUE(s.error.empty()) << s.error;
  ASSERT_EQ(rewards.size(), 30u);
  // A random policy drives at about 0.13 m/s; the maximum is 0.6 m/s.
  EXPECT_LT(rewards.front(), 0.25);
  EXPECT_GT(rewards.back(), rewards.front() + 0.15) << "first " << rewards.front();
  // The env's own counters saw every step, and the staggered starts spread the episode ends.
  EXPECT_EQ(env->env().state().step, 30u * 16u);
}

}  // namespace
}  // namespace ppo
}  // namespace jetbot_rl
