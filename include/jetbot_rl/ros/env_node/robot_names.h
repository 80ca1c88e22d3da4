#pragma once

#include <string>
#include <utility>

namespace jetbot_rl {

/**
 * Names of an env's robot view: its topics live in namespace "env_<i>/" relative to the node's
 * namespace and its tf frames carry the same prefix ("env_<i>/odom", "env_<i>/<link>"); with
 * `prefixed` false, env 0 has neither (standard tools find cmd_vel, odom, joint_states and
 * frames odom, base_footprint unchanged). A node prefix (the `robot_prefix` parameter, e.g.
 * "jetbot_env_1/") comes before both, so that several env nodes' robots do not clash.
 */
class RobotNames {
 public:
  explicit RobotNames(bool prefixed = true, std::string node_prefix = "")
      : prefixed_(prefixed), node_prefix_(std::move(node_prefix)) {
    if (!node_prefix_.empty() && node_prefix_.back() != '/') node_prefix_ += '/';
  }
  /// "<node prefix>env_<env>/", or the node prefix alone for env 0 when not prefixed.
  std::string prefix(int env) const {
    return node_prefix_ +
           ((!prefixed_ && env == 0) ? std::string() : "env_" + std::to_string(env) + "/");
  }
  /// The node prefix alone ("" or e.g. "jetbot_env_1/"): of the node's topics that belong to no
  /// env (the map).
  const std::string& nodePrefix() const { return node_prefix_; }
  /// Topic `name` of env `env`, relative to the node's namespace (e.g. "env_0/cmd_vel").
  std::string topic(int env, const std::string& name) const { return prefix(env) + name; }
  /// tf frame of URDF link `link` (or "odom") of env `env` (e.g. "env_0/base_link").
  std::string frame(int env, const std::string& link) const { return prefix(env) + link; }

 private:
  bool prefixed_;
  std::string node_prefix_;
};

/// The odometry frame of every env, fixed at its origin on the grid: "<prefix>odom".
inline constexpr const char* kOdomFrame = "odom";
/// With a map: every env's map frame, at its origin, parent of its odom frame: "<prefix>map".
inline constexpr const char* kMapFrame = "map";
/// The frame everything hangs from.
inline constexpr const char* kWorldFrame = "world";

}  // namespace jetbot_rl
