#pragma once

#include <urdf_model/pose.h>

#include <Eigen/Geometry>

namespace jetbot_rl {

/// A urdfdom pose as an Eigen transform (its quaternion normalised).
inline Eigen::Isometry3d toIsometry(const urdf::Pose& pose) {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.translation() << pose.position.x, pose.position.y, pose.position.z;
  t.linear() =
      Eigen::Quaterniond(pose.rotation.w, pose.rotation.x, pose.rotation.y, pose.rotation.z)
          .normalized()
          .toRotationMatrix();
  return t;
}

}  // namespace jetbot_rl
