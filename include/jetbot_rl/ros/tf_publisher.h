#pragma once

#include <geometry_msgs/TransformStamped.h>
#include <ros/time.h>
#include <tf2_ros/transform_broadcaster.h>

#include <string>
#include <vector>

#include "jetbot_rl/batched_env.h"

namespace jetbot_rl {

/// Broadcasts world -> env_<i>/<link> for every URDF link of the first `tf_envs` envs, at most
/// `tf_rate` Hz of simulation time.
class EnvTfPublisher {
 public:
  /// `tf_envs`: envs that get frames (0 disables); `tf_rate` [Hz of simulation time].
  EnvTfPublisher(int tf_envs, double tf_rate);
  /// Publishes when at least 1/tf_rate of simulation time passed since the last batch, or when
  /// `force` (start-up, resets). `stamp` is the simulation time of the current state [s]; a
  /// forced batch at the stamp of the previous batch is sent with the next step instead, since
  /// tf2 listeners ignore repeated stamps.
  /// Returns true when it published a batch.
  bool update(const BatchedEnv& env, const ros::Time& stamp, bool force);
  /// Frame name of `link` of env `env`: "env_<env>/<link>".
  static std::string frameName(int env, const std::string& link);

 private:
  int tf_envs_;
  ros::Duration period_;
  ros::Time last_{0, 0};
  bool published_ = false;
  bool pending_ = false;  // a forced batch waits for a new stamp
  std::vector<geometry_msgs::TransformStamped> transforms_;
  std::unique_ptr<tf2_ros::TransformBroadcaster> broadcaster_;
};

}  // namespace jetbot_rl
