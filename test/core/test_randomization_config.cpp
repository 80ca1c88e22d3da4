// Randomisation configurations: invalid ranges and what the robot cannot do are refused naming the
// parameter; the fields round-trip through YAML; the tribot is randomised too.
#include <functional>

#include "jetbot_rl/errors.h"
#include "randomization_test_util.h"

namespace jetbot_rl {
namespace {

using namespace test;

struct BadRange {
  const char* expected;  // text the error must contain
  std::function<void(EnvConfig&)> spoil;
};

TEST(Randomization, InvalidRangesAreRefusedNamingTheParameter) {
  const std::vector<BadRange> cases = {
      {"mass_scale = [1.2, 0.8]",
       [](EnvConfig& c) {
         c.randomization.mass_scale = {1.2, 0.8};
       }},
      {"mass_scale = [0, 1]",
       [](EnvConfig& c) {
         c.randomization.mass_scale = {0.0, 1.0};
       }},
      {"mass_scale = [1]", [](EnvConfig& c) { c.randomization.mass_scale = {1.0}; }},
      {"mass_scale = [nan, 1]",
       [](EnvConfig& c) {
         c.randomization.mass_scale = {std::nan(""), 1.0};
       }},
      {"wheel_friction = [-0.1, 1]",
       [](EnvConfig& c) {
         c.randomization.wheel_friction = {-0.1, 1.0};
       }},
      {"drive_gain_scale = [-1, 1]",
       [](EnvConfig& c) {
         c.randomization.drive_gain_scale = {-1.0, 1.0};
       }},
      {"effort_limit_scale = [1, inf]",
       [](EnvConfig& c) {
         c.randomization.effort_limit_scale = {1.0, INFINITY};
       }},
      {"wheel_radius_scale = [0, 1]",
       [](EnvConfig& c) {
         c.randomization.wheel_radius_scale = {0.0, 1.0};
       }},
      {"initial_yaw = [1, -1]",
       [](EnvConfig& c) {
         c.randomization.initial_yaw = {1.0, -1.0};
       }},
      {"initial_speed = [0, 1, 2]",
       [](EnvConfig& c) {
         c.randomization.initial_speed = {0.0, 1.0, 2.0};
       }},
      {"action_delay_steps = [3, 1]",
       [](EnvConfig& c) {
         c.randomization.action_delay_steps = {3, 1};
       }},
      {"action_delay_steps = [-1, 0]",
       [](EnvConfig& c) {
         c.randomization.action_delay_steps = {-1, 0};
       }},
      {"action_noise_std = -1", [](EnvConfig& c) { c.randomization.action_noise_std = -1.0; }},
      {"obs_noise_std = [0.1, -0.1, 0]",
       [](EnvConfig& c) {
         c.randomization.obs_noise_std = {0.1, -0.1, 0.0};
       }},
      {"motor_dead_zone = [0, 1]",
       [](EnvConfig& c) {
         c.motor.dead_zone = {0.0, 1.0};
       }},
      {"motor_trim = [0.9, 0.8]",
       [](EnvConfig& c) {
         c.motor.trim = {0.9, 0.8};
       }},
      {"motor_trim = [1, 1, 0.9]",
       [](EnvConfig& c) {
         c.motor.trim = {1.0, 1.0, 0.9};
       }},
      {"motor_dead_zone = [0, 0.1, 0.2, 0.1]",
       [](EnvConfig& c) {
         c.motor.dead_zone = {0.0, 0.1, 0.2, 0.1};
       }},
      {"motor_max_wheel_speed = -2", [](EnvConfig& c) { c.motor.max_wheel_speed = -2.0; }},
  };
  for (const auto& bad : cases) {
    EnvConfig config = smallConfig(1);
    bad.spoil(config);
    try {
      BatchedEnv env(jetbot(), config);
      ADD_FAILURE() << "accepted: " << bad.expected;
    } catch (const ConfigError& e) {
      EXPECT_NE(std::string(e.what()).find(bad.expected), std::string::npos) << e.what();
    }
  }
}

TEST(Randomization, ObservationNoiseNeedsOneStdOrOnePerComponent) {
  EnvConfig c = smallConfig(1);
  c.randomization.obs_noise_std = {0.1, 0.1};
  try {
    BatchedEnv env(jetbot(), c);
    ADD_FAILURE() << "accepted two values for three components";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("obs_noise_std = [0.1, 0.1]"), std::string::npos)
        << e.what();
    EXPECT_NE(std::string(e.what()).find("3"), std::string::npos) << e.what();
  }
  c.randomization.obs_noise_std = {0.1, 0.0, 0.2};
  EXPECT_NO_THROW(BatchedEnv(jetbot(), c));
}

TEST(Randomization, WhatTheRobotCannotDoIsRefusedNamingTheParameter) {
  // A wheel of two collision elements cannot be scaled.
  const std::string urdf = replaceOnce(
      jetbotUrdfText(), "<link name=\"left_wheel\">",
      "<link name=\"left_wheel\"><collision><geometry><sphere radius=\"0.01\"/></geometry>"
      "</collision>");
  EnvConfig c = smallConfig(1);
  c.randomization.wheel_radius_scale = {0.9, 1.1};
  try {
    BatchedEnv env(RobotModel::fromUrdfString(urdf), c);
    ADD_FAILURE() << "accepted a compound wheel";
  } catch (const ModelError& e) {
    EXPECT_NE(std::string(e.what()).find("left_wheel"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("wheel_radius_scale"), std::string::npos) << e.what();
  }
  EXPECT_NO_THROW(BatchedEnv(RobotModel::fromUrdfString(urdf), smallConfig(1)));
  // An initial speed needs the two wheels of a differential drive.
  EnvConfig one_wheel = smallConfig(1);
  one_wheel.dof_names = {"left_wheel_joint"};
  one_wheel.randomization.initial_speed = {0.1, 0.2};
  try {
    BatchedEnv env(jetbot(), one_wheel);
    ADD_FAILURE() << "accepted an initial speed for one wheel";
  } catch (const ModelError& e) {
    EXPECT_NE(std::string(e.what()).find("initial_speed"), std::string::npos) << e.what();
  }
}

TEST(Randomization, FieldsRoundTripThroughYaml) {
  EnvConfig c = everythingOn(3, 1);
  c.randomization.obs_noise_std = {0.01, 0.02, 0.5};
  EnvConfig back;
  fieldsFromYaml(fieldsToYaml(c), back);
  EXPECT_EQ(fieldsToYaml(back), fieldsToYaml(c));
  EXPECT_EQ(back.randomization.mass_scale, c.randomization.mass_scale);
  EXPECT_EQ(back.randomization.action_delay_steps, c.randomization.action_delay_steps);
  EXPECT_EQ(back.randomization.obs_noise_std, c.randomization.obs_noise_std);
  EXPECT_EQ(back.motor.trim, c.motor.trim);
  EXPECT_TRUE(back.motor.enabled);
  EnvConfig empty;
  fieldsFromYaml("obs_noise_std: []\n", empty);
  EXPECT_TRUE(empty.randomization.obs_noise_std.empty());
  EnvConfig single;
  fieldsFromYaml("obs_noise_std: 0.25  # one for every component\n", single);
  EXPECT_EQ(single.randomization.obs_noise_std, std::vector<double>{0.25});
  EXPECT_THROW(fieldsFromYaml("mass_scale: [1, x]\n", single), ConfigError);
}

}  // namespace
}  // namespace jetbot_rl
