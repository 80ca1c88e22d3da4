#pragma once

#include <geometry_msgs/TransformStamped.h>
#include <ros/time.h>

#include <vector>

#include "jetbot_rl/env/batched_env.h"
#include "jetbot_rl/ros/env_node/robot_names.h"

namespace jetbot_rl {

/**
 * The tf tree of envs 0..envs-1, one tree per env hanging from `world`:
 *
 *     world -> env_<i>/odom               static: the env's origin on the grid (with a map:
 *                                         world -> env_<i>/map there, map -> odom identity)
 *           -> env_<i>/<root link>        the root link's pose in the env (the odometry)
 *           -> env_<i>/<link> ...         every other link relative to its URDF parent link
 *    env_<i>/<camera link> -> <its frame>  static: the camera's optical frame, when no URDF link
 *                                          has the name the camera's block gives it
 *
 * (frame names as RobotNames gives them). With `link_tf` false only odom -> root is dynamic;
 * the links are left to robot_state_publisher. Messages are built once and updated in place.
 */
class TfTree {
 public:
  /// `envs` clamped to the batch.
  TfTree(const BatchedEnv& env, int envs, const RobotNames& names, bool link_tf);
  /// world -> odom (or map, and map -> odom) and the camera's optical frame of every env (stamp
  /// 0: static transforms hold at any time).
  const std::vector<geometry_msgs::TransformStamped>& statics() const { return statics_; }
  /// Sets the dynamic transforms to `env`'s current state, stamped `stamp`.
  void update(const BatchedEnv& env, const ros::Time& stamp);
  /// The dynamic transforms: per env, odom -> root, then (with link_tf) each other link.
  const std::vector<geometry_msgs::TransformStamped>& transforms() const { return transforms_; }
  int envs() const { return envs_; }

 private:
  int envs_;
  bool link_tf_;
  std::vector<int> parent_;  // per link of linkPoses(): index of its URDF parent, -1 for the root
  std::vector<geometry_msgs::TransformStamped> statics_, transforms_;
};

/// Sets `t` to `pose` (translation [m], unit quaternion).
void toTransform(const Eigen::Isometry3d& pose, geometry_msgs::Transform& t);

}  // namespace jetbot_rl
