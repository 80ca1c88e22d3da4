// The Isaac Lab DirectRLEnv step order: time-outs, rewards, auto-reset, final observations.
#include <cmath>

#include "test_util.h"

namespace jetbot_rl {
namespace {

using namespace test;

float norm3(const float* v) { return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); }

TEST(StepSemantics, SeedConfigurationMatchesIsaacLab) {
  BatchedEnv env(jetbot(), EnvConfig());
  EXPECT_EQ(env.numEnvs(), 100);
  EXPECT_EQ(env.obsDim(), 3);
  EXPECT_EQ(env.actionDim(), 2);
  EXPECT_DOUBLE_EQ(env.controlDt(), 1.0 / 60.0);
  EXPECT_EQ(env.maxEpisodeLength(), 300);
}

TEST(StepSemantics, EnvOriginsFormACentredSquareGrid) {
  BatchedEnv env(jetbot(), EnvConfig());
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (int i = 0; i < env.numEnvs(); ++i) {
    sum += env.view(i).origin();
    for (int j = 0; j < i; ++j)
      EXPECT_GE((env.view(i).origin() - env.view(j).origin()).norm(), 4.0 - 1e-9);
  }
  EXPECT_NEAR(sum.norm(), 0.0, 1e-9);
  EXPECT_NEAR((env.view(1).origin() - env.view(0).origin()).norm(), 4.0, 1e-12);
  EXPECT_NEAR((env.view(10).origin() - env.view(0).origin()).norm(), 4.0, 1e-12);
}

TEST(StepSemantics, RewardIsTheNormOfTheObservation) {
  BatchedEnv env(jetbot(), smallConfig(4));
  for (int s = 0; s < 400; ++s) {
    const StepResult& r = env.step(randomActions(4, s));
    std::size_t ended = 0;
    for (int e = 0; e < 4; ++e) {
      // An ended env's reward belongs to its final observation, not to the new episode's first.
      const bool was_reset =
          ended < r.reset_env_ids.size() && r.reset_env_ids[ended] == uint32_t(e);
      const float* obs = was_reset ? &r.final_observations[3 * ended++] : &r.observations[3 * e];
      ASSERT_NEAR(r.rewards[e], norm3(obs), 1e-6f * (1.0f + r.rewards[e])) << "step " << s;
    }
  }
}

TEST(StepSemantics, EpisodesTimeOutAfter299StepsAndAutoReset) {
  BatchedEnv env(jetbot(), smallConfig(2));
  const auto actions = uniformActions(env, 15.0f, 15.0f);
  const std::vector<float> rest = env.state().observations;
  std::vector<std::vector<float>> first_episode;
  for (int s = 1; s <= 299; ++s) {
    const StepResult& r = env.step(actions);
    first_episode.push_back(r.observations);
    if (s < 299) {
      ASSERT_EQ(r.episode_steps[0], uint32_t(s));
      ASSERT_FALSE(r.truncated[0]);
      ASSERT_TRUE(r.reset_env_ids.empty());
    } else {
      EXPECT_TRUE(r.truncated[0] && r.truncated[1]);
      EXPECT_FALSE(r.terminated[0] || r.terminated[1]);
      EXPECT_EQ(r.episode_steps[0], 0u);
      ASSERT_EQ(r.reset_env_ids, (std::vector<uint32_t>{0, 1}));
      ASSERT_EQ(r.final_observations.size(), 6u);
      // The final observation is the moving robot's; the new one is the rest state's.
      EXPECT_NEAR(r.final_observations[0], 15.0f * 0.03f, 0.03f);
      EXPECT_TRUE(bitEqual(r.observations, rest));
    }
  }
  // The second episode repeats the first bit for bit: reset leaves nothing behind.
  for (int s = 0; s < 298; ++s) {
    const StepResult& r = env.step(actions);
    ASSERT_TRUE(bitEqual(r.observations, first_episode[s])) << "step " << s;
  }
  EXPECT_TRUE(env.step(actions).truncated[0]);
}

TEST(StepSemantics, ResetOfOneEnvLeavesTheOthersBitIdentical) {
  BatchedEnv a(jetbot(), smallConfig(3)), b(jetbot(), smallConfig(3));
  for (int s = 0; s < 120; ++s) {
    if (s == 50) {
      const StepResult& r = a.reset({1});
      EXPECT_EQ(r.episode_steps[1], 0u);
      EXPECT_EQ(r.episode_steps[0], 50u);
    }
    a.step(randomActions(3, s));
    b.step(randomActions(3, s));
    ASSERT_TRUE(bitEqual(envObs(a, 0), envObs(b, 0))) << "step " << s;
    ASSERT_TRUE(bitEqual(envObs(a, 2), envObs(b, 2))) << "step " << s;
    if (s >= 50) {
      ASSERT_EQ(a.state().episode_steps[1], uint32_t(s - 49));
    }
  }
}

TEST(StepSemantics, AResetEnvReplaysLikeAFreshOne) {
  BatchedEnv a(jetbot(), smallConfig(1)), fresh(jetbot(), smallConfig(1));
  for (int s = 0; s < 77; ++s) a.step(randomActions(1, s, 7));
  a.reset({0});
  EXPECT_TRUE(bitEqual(a.state().observations, fresh.state().observations));
  for (int s = 0; s < 100; ++s) {
    a.step(randomActions(1, s));
    fresh.step(randomActions(1, s));
    ASSERT_TRUE(bitEqual(a.state().observations, fresh.state().observations)) << "step " << s;
  }
}

TEST(StepSemantics, ResetReturnsZeroRewardsAndNoEndedEnvs) {
  BatchedEnv env(jetbot(), smallConfig(2));
  for (int s = 0; s < 10; ++s) env.step(uniformActions(env, 10.0f, 10.0f));
  const StepResult& r = env.reset();
  EXPECT_EQ(r.rewards, std::vector<float>(2, 0.0f));
  EXPECT_TRUE(r.reset_env_ids.empty());
  EXPECT_EQ(r.episode_steps, std::vector<uint32_t>(2, 0u));
}

TEST(StepSemantics, LinkPosesIncludeTheEnvOrigin) {
  BatchedEnv env(jetbot(), smallConfig(4));
  const auto poses = env.view(3).linkPoses();
  ASSERT_EQ(poses.size(), 4u);  // base_link, caster_link, left_wheel, right_wheel
  EXPECT_EQ(poses[0].link, "base_link");
  const Eigen::Vector3d expected = env.view(3).origin() + Eigen::Vector3d(0, 0, 0.03);
  EXPECT_NEAR((poses[0].pose.translation() - expected).norm(), 0.0, 1e-4);
}

}  // namespace
}  // namespace jetbot_rl
