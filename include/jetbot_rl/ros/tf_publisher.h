#pragma once

#include <geometry_msgs/TransformStamped.h>
#include <tf2_ros/transform_broadcaster.h>

#include <memory>
#include <string>
#include <vector>

#include "jetbot_rl/ros/state_output.h"

namespace jetbot_rl {

/// Broadcasts world -> env_<i>/<link> for every URDF link of the first `tf_envs` envs, at most
/// `tf_rate` Hz of simulation time and after every reset (see SimRateGate).
class EnvTfPublisher : public StateOutput {
 public:
  /// `tf_envs`: envs that get frames (clamped to the batch; 0 disables); `tf_rate` [Hz].
  EnvTfPublisher(int tf_envs, double tf_rate);
  void capture(const BatchedEnv& env, const EnvStep::ConstPtr& msg, bool reset) override;
  void send() override;
  /// Frame name of `link` of env `env`: "env_<env>/<link>".
  static std::string frameName(int env, const std::string& link);

 private:
  int tf_envs_;
  SimRateGate gate_;
  bool due_ = false;
  std::vector<geometry_msgs::TransformStamped> transforms_;
  std::unique_ptr<tf2_ros::TransformBroadcaster> broadcaster_;
};

}  // namespace jetbot_rl
