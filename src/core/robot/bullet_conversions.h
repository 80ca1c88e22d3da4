#pragma once

// Bullet's vectors and transforms as Eigen's, for the core's Eigen API.

#include <LinearMath/btTransform.h>

#include <Eigen/Geometry>

namespace jetbot_rl {

inline Eigen::Vector3d toEigen(const btVector3& v) { return {v.x(), v.y(), v.z()}; }

inline Eigen::Isometry3d toEigen(const btTransform& t) {
  const btQuaternion q = t.getRotation();
  Eigen::Isometry3d out = Eigen::Isometry3d::Identity();
  out.linear() = Eigen::Quaterniond(q.w(), q.x(), q.y(), q.z()).toRotationMatrix();
  out.translation() << t.getOrigin().x(), t.getOrigin().y(), t.getOrigin().z();
  return out;
}

}  // namespace jetbot_rl
