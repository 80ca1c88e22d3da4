#include "jetbot_rl/ros/env_node/tf_publisher.h"

namespace jetbot_rl {

EnvTfPublisher::EnvTfPublisher(const BatchedEnv& env, int tf_envs, double tf_rate,
                               const RobotNames& names, bool link_tf)
    : tree_(env, tf_envs, names, link_tf), gate_(tf_rate) {
  if (tree_.envs() == 0) return;
  static_broadcaster_ = std::make_unique<tf2_ros::StaticTransformBroadcaster>();
  static_broadcaster_->sendTransform(tree_.statics());  // latched
  broadcaster_ = std::make_unique<tf2_ros::TransformBroadcaster>();
}

void EnvTfPublisher::capture(const BatchedEnv& env, const EnvStep::ConstPtr& msg, bool reset) {
  if (!broadcaster_ || !gate_.due(msg->header.stamp, reset)) return;
  tree_.update(env, msg->header.stamp);
  due_ = true;
}

void EnvTfPublisher::send() {
  if (due_) broadcaster_->sendTransform(tree_.transforms());
  due_ = false;
}

}  // namespace jetbot_rl
