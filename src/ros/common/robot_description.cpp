#include "jetbot_rl/ros/common/robot_description.h"

#include <string>

#include "jetbot_rl/errors.h"
#include "jetbot_rl/ros/common/package_resolver.h"

namespace jetbot_rl {

RobotModelConstPtr loadRobotDescription(const ros::NodeHandle& nh) {
  std::string urdf;
  if (!nh.getParam("robot_description", urdf)) {
    throw ConfigError("parameter " + nh.resolveName("robot_description") +
                      " is not set or not a string: load the robot's URDF into it");
  }
  return RobotModel::fromUrdfString(urdf, packageResolver());
}

}  // namespace jetbot_rl
