#include "jetbot_rl/ros/deploy/planar_transform.h"

#include <tf2/utils.h>

namespace jetbot_rl {

bool lookupPlanar(const tf2_ros::Buffer& tf, const std::string& target, const std::string& source,
                  Eigen::Isometry2d& target_source, std::string& why) {
  if (target == source || target.empty() || source.empty()) {
    target_source = Eigen::Isometry2d::Identity();
    return true;
  }
  try {
    const geometry_msgs::Transform t = tf.lookupTransform(target, source, ros::Time(0)).transform;
    target_source = Eigen::Translation2d(t.translation.x, t.translation.y) *
                    Eigen::Rotation2Dd(tf2::getYaw(t.rotation));
    return true;
  } catch (const tf2::TransformException& e) {
    why = "no transform from '" + source + "' into '" + target + "': " + e.what();
    return false;
  }
}

}  // namespace jetbot_rl
