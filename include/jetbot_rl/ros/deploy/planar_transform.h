#pragma once

#include <geometry_msgs/Transform.h>
#include <tf2/utils.h>

#include <Eigen/Geometry>

namespace jetbot_rl {

/// The planar part (x [m], y [m], yaw [rad]) of a tf transform: the robot drives in the plane.
inline Eigen::Isometry2d planarTransform(const geometry_msgs::Transform& t) {
  return Eigen::Translation2d(t.translation.x, t.translation.y) *
         Eigen::Rotation2Dd(tf2::getYaw(t.rotation));
}

}  // namespace jetbot_rl
