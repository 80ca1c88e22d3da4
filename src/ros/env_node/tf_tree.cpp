#include "jetbot_rl/ros/env_node/tf_tree.h"

#include <algorithm>
#include <string>

#include "jetbot_rl/ros/common/geometry_conversion.h"
#include "jetbot_rl/sensors/camera_spec.h"

namespace jetbot_rl {

TfTree::TfTree(const BatchedEnv& env, int envs, const RobotNames& names, bool link_tf)
    : envs_(std::clamp(envs, 0, env.numEnvs())), link_tf_(link_tf) {
  // The links in linkPoses() order (bodies in order, each with its fixed links), and their parents.
  std::vector<std::string> links, parents;
  for (const BodyModel& body : env.robot().bodies()) {
    for (const AttachedLink& link : body.links) {
      links.push_back(link.name);
      parents.push_back(link.parent);
    }
  }
  for (const std::string& parent : parents) {
    const auto it = std::find(links.begin(), links.end(), parent);
    parent_.push_back(it == links.end() ? -1 : static_cast<int>(it - links.begin()));
  }
  const bool map = env.world() && env.world()->map();
  for (int e = 0; e < envs_; ++e) {
    // world -> odom at the env's origin; with a map, world -> map there and map -> odom the
    // identity (the simulated odometry does not drift).
    geometry_msgs::TransformStamped origin;
    origin.header.frame_id = kWorldFrame;
    origin.child_frame_id = names.frame(e, map ? kMapFrame : kOdomFrame);
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    pose.translation() = env.view(e).origin();
    toTransform(pose, origin.transform);
    statics_.push_back(origin);
    if (map) {
      geometry_msgs::TransformStamped odom;
      odom.header.frame_id = names.frame(e, kMapFrame);
      odom.child_frame_id = names.frame(e, kOdomFrame);
      toTransform(Eigen::Isometry3d::Identity(), odom.transform);
      statics_.push_back(odom);
    }
    // The cameras' optical frames, where the robot description has no link of that name.
    for (int c = 0; c < env.numCameras(); ++c) {
      const CameraSpec* camera = env.camera(c);
      if (std::find(links.begin(), links.end(), camera->frame) != links.end()) continue;
      geometry_msgs::TransformStamped optical;
      optical.header.frame_id = names.frame(e, camera->link);
      optical.child_frame_id = names.frame(e, camera->frame);
      toTransform(camera->optical_in_link, optical.transform);
      statics_.push_back(optical);
    }
    for (std::size_t k = 0; k < links.size(); ++k) {
      if (parent_[k] >= 0 && !link_tf_) continue;
      geometry_msgs::TransformStamped t;
      t.header.frame_id = names.frame(e, parent_[k] < 0 ? kOdomFrame : links[parent_[k]]);
      t.child_frame_id = names.frame(e, links[k]);
      transforms_.push_back(t);
    }
  }
}

void TfTree::update(const BatchedEnv& env, const ros::Time& stamp) {
  std::size_t k = 0;
  for (int e = 0; e < envs_; ++e) {
    // The root relative to the env's origin is the odometry; the others relative to their parent.
    const std::vector<LinkPose> poses = env.view(e).linkPoses();
    Eigen::Isometry3d origin = Eigen::Isometry3d::Identity();
    origin.translation() = env.view(e).origin();
    for (std::size_t l = 0; l < poses.size(); ++l) {
      const int parent = parent_[l];
      if (parent >= 0 && !link_tf_) continue;
      geometry_msgs::TransformStamped& t = transforms_[k++];
      t.header.stamp = stamp;
      const Eigen::Isometry3d& reference = parent < 0 ? origin : poses[parent].pose;
      toTransform(reference.inverse() * poses[l].pose, t.transform);
    }
  }
}

}  // namespace jetbot_rl
