#pragma once

#include <string>

namespace jetbot_rl {

/**
 * Names of an env's robot view: its topics live in namespace "env_<i>/" relative to the node's
 * namespace and its tf frames carry the same prefix ("env_<i>/odom", "env_<i>/<link>"); with
 * `prefixed` false, env 0 has neither (standard tools find cmd_vel, odom, joint_states and
 * frames odom, base_footprint unchanged).
 */
class RobotNames {
 public:
  explicit RobotNames(bool prefixed = true) : prefixed_(prefixed) {}
  /// "env_<env>/", or "" for env 0 when not prefixed.
  std::string prefix(int env) const {
    return (!prefixed_ && env == 0) ? std::string() : "env_" + std::to_string(env) + "/";
  }
  /// Topic `name` of env `env`, relative to the node's namespace (e.g. "env_0/cmd_vel").
  std::string topic(int env, const std::string& name) const { return prefix(env) + name; }
  /// tf frame of URDF link `link` (or "odom") of env `env` (e.g. "env_0/base_link").
  std::string frame(int env, const std::string& link) const { return prefix(env) + link; }

 private:
  bool prefixed_;
};

/// The odometry frame of every env, fixed at its origin on the grid: "<prefix>odom".
inline constexpr const char* kOdomFrame = "odom";
/// The frame everything hangs from.
inline constexpr const char* kWorldFrame = "world";

}  // namespace jetbot_rl
