#pragma once

#include <tf2_msgs/TFMessage.h>
#include <tf2_ros/static_transform_broadcaster.h>

#include <memory>

#include "jetbot_rl/ros/env_node/state_output.h"
#include "jetbot_rl/ros/env_node/tf_tree.h"

namespace jetbot_rl {

/// Broadcasts the TfTree of the first `tf_envs` envs: world -> odom once on /tf_static at
/// start-up, the rest on /tf at most `tf_rate` Hz of simulation time and after every reset (see
/// SimRateGate). /tf is published as tf2_ros::TransformBroadcaster does, with its queue of 100
/// per connection kept in a CountedSubscriberQueues.
class EnvTfPublisher : public StateOutput {
 public:
  /// `tf_envs`: envs that get frames (clamped to the batch; 0 disables); `tf_rate` [Hz];
  /// `link_tf` false: only odom -> root link (robot_state_publisher does the links).
  EnvTfPublisher(ros::NodeHandle& nh, const BatchedEnv& env, int tf_envs, double tf_rate,
                 const RobotNames& names, bool link_tf, CountedSubscriberQueues& queues);
  void capture(const BatchedEnv& env, const EnvStep::ConstPtr& msg, bool reset) override;
  void send() override;

 private:
  TfTree tree_;
  SimRateGate gate_;
  bool due_ = false;
  ros::Publisher pub_;  // /tf
  tf2_msgs::TFMessage msg_;
  std::unique_ptr<tf2_ros::StaticTransformBroadcaster> static_broadcaster_;
};

}  // namespace jetbot_rl
