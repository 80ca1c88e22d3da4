#pragma once

#include <geometry_msgs/Pose.h>
#include <geometry_msgs/Transform.h>
#include <nav_msgs/OccupancyGrid.h>
#include <nav_msgs/Odometry.h>

#include <Eigen/Geometry>
#include <string>

#include "jetbot_rl/tasks/task.h"
#include "jetbot_rl/world/occupancy_map.h"

namespace jetbot_rl {

/// The grid of an OccupancyGrid message as the core's OccupancyMap (cells, resolution, origin).
OccupancyMap occupancyMapOf(const nav_msgs::OccupancyGrid& grid);

/// The OccupancyGrid map_server would serve for `map` (info from the YAML, cells as its loader
/// makes them), in frame `frame_id`, stamped `stamp`: occupancyMapOf's inverse.
nav_msgs::OccupancyGrid toOccupancyGrid(const OccupancyMap& map, const std::string& frame_id,
                                        const ros::Time& stamp);

/// The robot's state as the task's observer takes it from an odometry message: the pose in the
/// odometry frame, the twist (given in the child frame) rotated into it, as RootState keeps it.
RootState rootStateOf(const nav_msgs::Odometry& odometry);

/// Writes position `p` [m] and orientation `q` into `pose`.
void setPose(geometry_msgs::Pose& pose, const Eigen::Vector3d& p, const Eigen::Quaterniond& q);

/// The rotation by `yaw` [rad] about z.
Eigen::Quaterniond yawQuaternion(double yaw);

/// Writes `pose` into `t`, its rotation normalised (Bullet's single-precision rotations are
/// orthonormal to 1e-7 only).
void toTransform(const Eigen::Isometry3d& pose, geometry_msgs::Transform& t);
/// A tf transform as an Eigen isometry (its quaternion normalised): toTransform()'s inverse.
Eigen::Isometry3d toIsometry(const geometry_msgs::Transform& t);

}  // namespace jetbot_rl
