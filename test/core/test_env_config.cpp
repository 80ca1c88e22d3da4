// Every configuration field is validated, and the error names the field and its value.
#include <functional>

#include "jetbot_rl/errors.h"
#include "test_util.h"

namespace jetbot_rl {
namespace {

struct BadField {
  const char* expected;  // text the error must contain
  std::function<void(EnvConfig&)> spoil;
};

TEST(EnvConfig, DefaultsAreValid) { EXPECT_NO_THROW(EnvConfig().validate()); }

/// Each case's config is refused by validate() and by the env, naming the field and value.
void expectRefused(const std::vector<BadField>& cases) {
  for (const auto& bad : cases) {
    EnvConfig config;
    bad.spoil(config);
    try {
      config.validate();
      ADD_FAILURE() << "accepted: " << bad.expected;
    } catch (const ConfigError& e) {
      EXPECT_NE(std::string(e.what()).find(bad.expected), std::string::npos) << e.what();
    }
    // The environment itself refuses it too.
    EXPECT_THROW(BatchedEnv(test::jetbot(), config), ConfigError) << bad.expected;
  }
}

TEST(EnvConfig, EveryInvalidFieldIsNamed) {
  const std::vector<BadField> cases = {
      {"num_envs = 0", [](EnvConfig& c) { c.num_envs = 0; }},
      {"num_envs = -3", [](EnvConfig& c) { c.num_envs = -3; }},
      {"env_spacing = -1", [](EnvConfig& c) { c.env_spacing = -1.0; }},
      {"env_spacing = nan", [](EnvConfig& c) { c.env_spacing = std::nan(""); }},
      {"physics_dt = 0", [](EnvConfig& c) { c.physics_dt = 0.0; }},
      {"physics_dt = 0.5", [](EnvConfig& c) { c.physics_dt = 0.5; }},
      {"decimation = 0", [](EnvConfig& c) { c.decimation = 0; }},
      {"episode_length_s = -5", [](EnvConfig& c) { c.episode_length_s = -5.0; }},
      {"episode_length_s = 0.01", [](EnvConfig& c) { c.episode_length_s = 0.01; }},
      {"dof_names = left_wheel_joint",
       [](EnvConfig& c) {
         c.dof_names = {"left_wheel_joint", "left_wheel_joint"};
       }},
      {"num_threads = -1", [](EnvConfig& c) { c.num_threads = -1; }},
      {"drive_gain = 0", [](EnvConfig& c) { c.drive_gain = 0.0; }},
      {"effort_limit = -1", [](EnvConfig& c) { c.effort_limit = -1.0; }},
      {"solver_iterations = 0", [](EnvConfig& c) { c.solver_iterations = 0; }},
  };
  expectRefused(cases);
}

TEST(EnvConfig, WheelAndCasterFieldsAreValidated) {
  const std::vector<BadField> cases = {
      {"wheel_velocity_limit = -1", [](EnvConfig& c) { c.wheel_velocity_limit = -1.0; }},
      {"wheel_velocity_limit = nan", [](EnvConfig& c) { c.wheel_velocity_limit = std::nan(""); }},
      {"caster_friction = -0.5", [](EnvConfig& c) { c.caster_friction = -0.5; }},
      {"caster_friction = inf", [](EnvConfig& c) { c.caster_friction = INFINITY; }},
      {"wheel_radius = -0.01", [](EnvConfig& c) { c.wheel_radius = -0.01; }},
      {"wheel_separation = nan", [](EnvConfig& c) { c.wheel_separation = std::nan(""); }},
  };
  expectRefused(cases);
}

TEST(EnvConfig, MaxEpisodeLengthFollowsIsaacLab) {
  EnvConfig c;
  EXPECT_EQ(c.maxEpisodeLength(), 300);
  c.episode_length_s = 5.01;
  EXPECT_EQ(c.maxEpisodeLength(), 301);  // ceil
}

TEST(EnvConfig, EffortOverrideReplacesTheUrdfLimit) {
  // A tiny torque limit cannot accelerate the robot as fast as the URDF's.
  EnvConfig weak = test::smallConfig(1);
  weak.effort_limit = 0.005;
  BatchedEnv strong_env(test::jetbot(), test::smallConfig(1)), weak_env(test::jetbot(), weak);
  for (int s = 0; s < 10; ++s) {
    strong_env.step(test::uniformActions(strong_env, 20.0f, 20.0f));
    weak_env.step(test::uniformActions(weak_env, 20.0f, 20.0f));
  }
  EXPECT_LT(weak_env.state().observations[0], 0.5f * strong_env.state().observations[0]);
}

}  // namespace
}  // namespace jetbot_rl
