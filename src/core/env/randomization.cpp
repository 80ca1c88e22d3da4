#include "jetbot_rl/env/randomization.h"

namespace jetbot_rl {

bool RandomizationConfig::drawsAtReset() const {
  const RandomizationConfig off;
  return mass_scale != off.mass_scale || wheel_friction != off.wheel_friction ||
         drive_gain_scale != off.drive_gain_scale || effort_limit_scale != off.effort_limit_scale ||
         wheel_radius_scale != off.wheel_radius_scale || initial_yaw != off.initial_yaw ||
         initial_speed != off.initial_speed || action_delay_steps != off.action_delay_steps;
}

bool RandomizationConfig::hasNoise() const {
  if (action_noise_std > 0.0) return true;
  for (double s : obs_noise_std) {
    if (s > 0.0) return true;
  }
  return false;
}

}  // namespace jetbot_rl
