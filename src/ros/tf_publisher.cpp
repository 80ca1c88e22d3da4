#include "jetbot_rl/ros/tf_publisher.h"

#include <algorithm>

namespace jetbot_rl {

EnvTfPublisher::EnvTfPublisher(int tf_envs, double tf_rate)
    : tf_envs_(std::max(0, tf_envs)), gate_(tf_rate) {
  if (tf_envs_ > 0) broadcaster_ = std::make_unique<tf2_ros::TransformBroadcaster>();
}

std::string EnvTfPublisher::frameName(int env, const std::string& link) {
  return "env_" + std::to_string(env) + "/" + link;
}

void EnvTfPublisher::capture(const BatchedEnv& env, const EnvStep::ConstPtr& msg, bool reset) {
  if (!broadcaster_ || !gate_.due(msg->header.stamp, reset)) return;
  const int envs = std::min(tf_envs_, env.numEnvs());
  std::size_t k = 0;
  for (int e = 0; e < envs; ++e) {
    for (const LinkPose& link : env.linkPoses(e)) {
      if (k == transforms_.size()) {  // first batch: frame names are built once
        transforms_.emplace_back();
        transforms_[k].header.frame_id = "world";
        transforms_[k].child_frame_id = frameName(e, link.link);
      }
      geometry_msgs::TransformStamped& t = transforms_[k++];
      t.header.stamp = msg->header.stamp;
      const Eigen::Vector3d p = link.pose.translation();
      const Eigen::Quaterniond q(link.pose.rotation());
      t.transform.translation.x = p.x();
      t.transform.translation.y = p.y();
      t.transform.translation.z = p.z();
      t.transform.rotation.x = q.x();
      t.transform.rotation.y = q.y();
      t.transform.rotation.z = q.z();
      t.transform.rotation.w = q.w();
    }
  }
  transforms_.resize(k);
  due_ = true;
}

void EnvTfPublisher::send() {
  if (due_) broadcaster_->sendTransform(transforms_);
  due_ = false;
}

}  // namespace jetbot_rl
