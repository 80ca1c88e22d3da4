// ~get_randomization's answers on message types, without a master.
#include <gtest/gtest.h>

#include <algorithm>
#include <type_traits>

#include "jetbot_rl/ros/common/msg_fields.h"
#include "jetbot_rl/ros/env_node/randomization_service.h"
#include "jetbot_rl/ros/env_node/sim_clock.h"

namespace jetbot_rl {
namespace {

BatchedEnv makeEnv(const EnvConfig& config) {
  return BatchedEnv(RobotModel::fromUrdfFile(JETBOT_URDF), config);
}

EnvConfig randomized(int num_envs) {
  EnvConfig c;
  c.num_envs = num_envs;
  c.num_threads = 1;
  c.randomization.mass_scale = {0.5, 2.0};
  c.randomization.initial_yaw = {-1.0, 1.0};
  c.randomization.action_delay_steps = {0, 4};
  c.motor.enabled = true;
  c.motor.trim = {0.8, 1.2};
  return c;
}

TEST(RandomizationService, TheMessageHoldsEveryFieldOfTheDrawAndItsOwnFourBesides) {
  // The draw's field list is its one typing: the message has an array of every field's name,
  // and besides them only what the answer itself says.
  const std::vector<std::string> msg_fields =
      msgFieldNames(ros::message_traits::Definition<EnvRandomization>::value());
  std::vector<std::string> expected{"header", "step", "env_ids", "num_dofs"};
  for (const std::string& name : fieldNames(RandomizationDraw())) expected.push_back(name);
  std::vector<std::string> sorted = msg_fields;
  std::sort(sorted.begin(), sorted.end());
  std::sort(expected.begin(), expected.end());
  EXPECT_EQ(sorted, expected);
  // Every scalar of the draw has a range of its name to be drawn from.
  const std::vector<std::string> ranges = fieldNames(RandomizationConfig());
  const RandomizationDraw draw;
  visitFields(draw, [&](const char* name, const auto& value, const auto&, const char*) {
    if (std::is_arithmetic_v<std::decay_t<decltype(value)>>) {
      EXPECT_NE(std::find(ranges.begin(), ranges.end(), name), ranges.end()) << name;
    }
  });
}

TEST(RandomizationService, AnswersTheListedEnvsInOrder) {
  BatchedEnv env = makeEnv(randomized(5));
  env.step(std::vector<float>(10, 1.0f));
  env.step(std::vector<float>(10, 1.0f));
  GetRandomization::Request req;
  req.env_ids = {3, 0};
  GetRandomization::Response res;
  answerGetRandomization(env, req, res);
  ASSERT_TRUE(res.success) << res.message;
  const EnvRandomization& m = res.randomization;
  EXPECT_EQ(m.step, 2u);
  EXPECT_EQ(m.header.stamp, simTime(2, env.controlDt()));
  EXPECT_EQ(m.env_ids, (std::vector<std::uint32_t>{3, 0}));
  ASSERT_EQ(m.num_dofs, 2u);
  ASSERT_EQ(m.motor_trim.size(), 4u);
  ASSERT_EQ(m.motor_dead_zone.size(), 4u);
  for (std::size_t i = 0; i < 2; ++i) {
    const RandomizationDraw r = env.view(static_cast<int>(m.env_ids[i])).randomization();
    EXPECT_EQ(m.mass_scale.at(i), r.mass_scale);
    EXPECT_EQ(m.wheel_friction.at(i), r.wheel_friction);
    EXPECT_EQ(m.drive_gain_scale.at(i), r.drive_gain_scale);
    EXPECT_EQ(m.effort_limit_scale.at(i), r.effort_limit_scale);
    EXPECT_EQ(m.wheel_radius_scale.at(i), r.wheel_radius_scale);
    EXPECT_EQ(m.initial_yaw.at(i), r.initial_yaw);
    EXPECT_EQ(m.initial_speed.at(i), r.initial_speed);
    EXPECT_EQ(m.action_delay_steps.at(i), static_cast<std::uint32_t>(r.action_delay_steps));
    EXPECT_EQ(m.motor_trim.at(2 * i), r.motor_trim[0]);
    EXPECT_EQ(m.motor_trim.at(2 * i + 1), r.motor_trim[1]);
    EXPECT_EQ(m.motor_dead_zone.at(2 * i + 1), r.motor_dead_zone[1]);
  }
  EXPECT_NE(m.mass_scale[0], m.mass_scale[1]);
}

TEST(RandomizationService, NoIdsMeanAllEnvsAndOffGivesTheDefaults) {
  EnvConfig off;
  off.num_envs = 3;
  off.num_threads = 1;
  BatchedEnv env = makeEnv(off);
  GetRandomization::Request req;
  GetRandomization::Response res;
  answerGetRandomization(env, req, res);
  ASSERT_TRUE(res.success);
  const EnvRandomization& m = res.randomization;
  EXPECT_EQ(m.env_ids, (std::vector<std::uint32_t>{0, 1, 2}));
  EXPECT_EQ(m.mass_scale, std::vector<double>(3, 1.0));
  EXPECT_EQ(m.wheel_friction, std::vector<double>(3, 1.0));
  EXPECT_EQ(m.initial_speed, std::vector<double>(3, 0.0));
  EXPECT_EQ(m.action_delay_steps, std::vector<std::uint32_t>(3, 0));
  EXPECT_EQ(m.num_dofs, 0u);
  EXPECT_TRUE(m.motor_trim.empty());
}

TEST(RandomizationService, UnknownOrRepeatedIdsAreRefusedWithoutValues) {
  BatchedEnv env = makeEnv(randomized(2));
  for (const std::vector<std::uint32_t>& ids :
       {std::vector<std::uint32_t>{0, 2}, std::vector<std::uint32_t>{1, 1}}) {
    GetRandomization::Request req;
    req.env_ids = ids;
    GetRandomization::Response res;
    answerGetRandomization(env, req, res);
    EXPECT_FALSE(res.success);
    EXPECT_NE(res.message.find(ids == std::vector<std::uint32_t>{0, 2} ? "id 2 is out of range"
                                                                       : "id 1 is listed twice"),
              std::string::npos)
        << res.message;
    EXPECT_TRUE(res.randomization.env_ids.empty());
    EXPECT_TRUE(res.randomization.mass_scale.empty());
  }
}

}  // namespace
}  // namespace jetbot_rl
