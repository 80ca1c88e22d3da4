#pragma once

#include <tf2_ros/buffer.h>

#include <Eigen/Geometry>
#include <string>

namespace jetbot_rl {

/// The planar part (x [m], y [m], yaw [rad]) of tf's latest transform from `source` into
/// `target`: the robot drives in the plane. Equal frames, or one not named (""), give the
/// identity. False with `why` when tf has no such transform.
bool lookupPlanar(const tf2_ros::Buffer& tf, const std::string& target, const std::string& source,
                  Eigen::Isometry2d& target_source, std::string& why);

}  // namespace jetbot_rl
