#pragma once

#include <ros/node_handle.h>

#include "jetbot_rl/robot/robot_model.h"

namespace jetbot_rl {

/// The robot in the URDF text of `nh`'s `robot_description`, its `package://` meshes resolved on
/// the ROS package path. Throws ConfigError naming the resolved parameter when it is not set or
/// not a string, and the parser's ModelError (naming the link or joint) for a refused URDF.
RobotModelConstPtr loadRobotDescription(const ros::NodeHandle& nh);

}  // namespace jetbot_rl
