// Shared by the randomisation tests: a speed probe and a configuration with everything on.
#pragma once

#include "test_util.h"

namespace jetbot_rl {
namespace test {

/// Forward body speed [m/s] of env 0 after `steps` steps at (left, right) targets [rad/s].
inline double speedAfter(BatchedEnv& env, int steps, float left = 20.0f, float right = 20.0f) {
  for (int s = 0; s < steps; ++s) env.step(uniformActions(env, left, right));
  return env.view(0).rootState().comLinearVelocityBody().x();
}

/// Every randomisation on, and the motor model.
inline EnvConfig everythingOn(int num_envs, int threads) {
  EnvConfig c = smallConfig(num_envs, threads);
  RandomizationConfig& r = c.randomization;
  r.mass_scale = {0.8, 1.3};
  r.wheel_friction = {0.6, 1.2};
  r.drive_gain_scale = {0.5, 2.0};
  r.effort_limit_scale = {0.7, 1.2};
  r.wheel_radius_scale = {0.95, 1.05};
  r.initial_yaw = {-3.1, 3.1};
  r.initial_speed = {-0.2, 0.4};
  r.action_delay_steps = {0, 3};
  r.action_noise_std = 1.0;
  r.obs_noise_std = {0.01};
  c.motor.enabled = true;
  c.motor.dead_zone = {0.0, 0.1};
  c.motor.trim = {0.9, 1.1};
  return c;
}

}  // namespace test
}  // namespace jetbot_rl
