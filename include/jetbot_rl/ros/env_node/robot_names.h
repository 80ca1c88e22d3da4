#pragma once

#include <string>
#include <utility>

namespace jetbot_rl {

/**
 * Names of an env's robot view: its topics live in namespace "env_<i>/" relative to the node's
 * namespace and its tf frames carry the same prefix ("env_<i>/odom", "env_<i>/<link>"); with
 * `prefixed` false, env 0 has neither (standard tools find cmd_vel, odom, joint_states and
 * frames odom, base_footprint unchanged). A node prefix (the `robot_prefix` parameter, e.g.
 * "jetbot_env_1/") comes before both, so that several env nodes' robots do not clash. With
 * robots_per_env K > 1, row i is robot i % K of env i / K: "env_<i / K>/robot_<i % K>/".
 */
class RobotNames {
 public:
  explicit RobotNames(bool prefixed = true, std::string node_prefix = "", int robots_per_env = 1)
      : prefixed_(prefixed), node_prefix_(std::move(node_prefix)), k_(robots_per_env) {
    if (!node_prefix_.empty() && node_prefix_.back() != '/') node_prefix_ += '/';
  }
  /// "<node prefix>env_<env>/" (of row `env`; with K robots per env "env_<env / K>/robot_<env %
  /// K>/"), or the node prefix alone for env 0 when not prefixed.
  std::string prefix(int env) const {
    if (!prefixed_ && env == 0) return node_prefix_;
    if (k_ == 1) return node_prefix_ + "env_" + std::to_string(env) + "/";
    return node_prefix_ + "env_" + std::to_string(env / k_) + "/robot_" + std::to_string(env % k_) +
           "/";
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
  int k_;
};

/// The odometry frame of every env, fixed at its origin on the grid: "<prefix>odom".
inline constexpr const char* kOdomFrame = "odom";
/// With a map: every env's map frame, at its origin, parent of its odom frame: "<prefix>map".
inline constexpr const char* kMapFrame = "map";
/// The frame everything hangs from.
inline constexpr const char* kWorldFrame = "world";

}  // namespace jetbot_rl
