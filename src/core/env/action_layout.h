#pragma once

#include <memory>
#include <string>
#include <vector>

#include "jetbot_rl/env/env_config.h"
#include "jetbot_rl/robot/diff_drive.h"
#include "jetbot_rl/robot/robot_model.h"

namespace jetbot_rl {

/// What an env's action is: its bounds and names, and for action_space twist the kinematics that
/// turn a twist into wheel targets.
struct ActionLayout {
  std::vector<float> low, high;      ///< Per action dimension [rad/s; twist: m/s, rad/s].
  std::vector<std::string> names;    ///< The dof names; twist: linear_x, angular_z.
  std::unique_ptr<DiffDrive> drive;  ///< Twist only.
};

/**
 * The layout of `config.action_space` for `robot` with wheel velocity limits `wheel_limits`
 * [rad/s] (in dof order): wheel targets within them, or a twist bounded by the fastest straight v
 * and turn on the spot they allow (v from below by twist_reverse_speed). ConfigError naming
 * action_space for a robot that is no differential drive, twist_reverse_speed beyond the wheels.
 */
ActionLayout makeActionLayout(const RobotModel& robot, const EnvConfig& config,
                              const std::vector<double>& wheel_limits);

/// Checks a batch's actions (num_envs x layout size): InputError naming the env, the action and
/// the value for a wrong count or a value that is not finite.
void checkActions(const ActionLayout& layout, int num_envs, const float* actions,
                  std::size_t count);

/// Clamps `actions` (num_envs x layout size) into the bounds (`clamped`) and gives each env's
/// dof targets [rad/s] (num_envs x `dofs`): a twist through the drive (the curvature kept within
/// the wheels' limits), wheel targets as clamped, or as given when `raw` (action noise is added
/// before clamping). `speed_caps` (twist only; per env [m/s], or none) lower each env's forward v
/// to its cap (speed_limit/...), in `clamped` too.
void actionsToTargets(const ActionLayout& layout, int num_envs, std::size_t dofs,
                      const float* actions, bool raw, float* clamped, float* targets,
                      const float* speed_caps = nullptr);

}  // namespace jetbot_rl
