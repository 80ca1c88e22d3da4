#include "jetbot_rl/ros/tf_publisher.h"

#include <algorithm>

namespace jetbot_rl {

EnvTfPublisher::EnvTfPublisher(int tf_envs, double tf_rate)
    : tf_envs_(std::max(0, tf_envs)), period_(1.0 / tf_rate) {
  if (tf_envs_ > 0) broadcaster_ = std::make_unique<tf2_ros::TransformBroadcaster>();
}

std::string EnvTfPublisher::frameName(int env, const std::string& link) {
  return "env_" + std::to_string(env) + "/" + link;
}

bool EnvTfPublisher::update(const BatchedEnv& env, const ros::Time& stamp, bool force) {
  if (!broadcaster_) return false;
  if (published_ && stamp == last_) {
    // tf2 listeners drop a second batch with the same stamp (TF_REPEATED_DATA): a forced batch
    // at an unchanged time (a reset) goes out with the next step instead.
    pending_ = pending_ || force;
    return false;
  }
  if (!force && !pending_ && published_ && stamp - last_ < period_) return false;
  pending_ = false;
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
      t.header.stamp = stamp;
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
  broadcaster_->sendTransform(transforms_);
  last_ = stamp;
  published_ = true;
  return true;
}

}  // namespace jetbot_rl
