#include "jetbot_rl/ros/env_node/tf_publisher.h"

namespace jetbot_rl {

namespace {

constexpr std::size_t kTfQueue = 100;  // tf2_ros::TransformBroadcaster's

}  // namespace

EnvTfPublisher::EnvTfPublisher(ros::NodeHandle& nh, const BatchedEnv& env, int tf_envs,
                               double tf_rate, const RobotNames& names, bool link_tf,
                               CountedSubscriberQueues& queues)
    : tree_(env, tf_envs, names, link_tf), gate_(tf_rate) {
  if (tree_.envs() == 0) return;
  static_broadcaster_ = std::make_unique<tf2_ros::StaticTransformBroadcaster>();
  static_broadcaster_->sendTransform(tree_.statics());  // latched
  pub_ = advertiseCounted<tf2_msgs::TFMessage>(nh, "/tf", kTfQueue, queues);
}

void EnvTfPublisher::capture(const BatchedEnv& env, const EnvStep::ConstPtr& msg, bool reset) {
  if (!pub_ || !gate_.due(msg->header.stamp, reset)) return;
  tree_.update(env, msg->header.stamp);
  due_ = true;
}

void EnvTfPublisher::send() {
  if (due_) {
    msg_.transforms = tree_.transforms();
    pub_.publish(msg_);
  }
  due_ = false;
}

}  // namespace jetbot_rl
