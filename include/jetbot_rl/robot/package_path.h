#pragma once

// Files named by ROS and Gazebo URIs, found through the search paths of the environment
// (ROS_PACKAGE_PATH, GAZEBO_MODEL_PATH) without ROS: the programs and the core read URDFs and
// Gazebo worlds with package:// and model:// URIs.

#include <string>
#include <vector>

namespace jetbot_rl {

/// The folders of a `:`-separated search path in the environment variable `name` (none when
/// unset), empty entries left out.
std::vector<std::string> searchPath(const char* name);

/// package://PKG/rest as <dir>/PKG/rest for the first directory of ROS_PACKAGE_PATH that holds
/// PKG/package.xml (a catkin workspace's src/, an install's share/). "" when not found.
std::string findPackageUri(const std::string& uri);

/**
 * The file path of a `model://NAME/...` URI as Gazebo finds it: NAME under each folder of
 * GAZEBO_MODEL_PATH, then under each ROS_PACKAGE_PATH folder and its packages' `models/`
 * folders. "" when it is not found.
 */
std::string findGazeboModel(const std::string& uri);

}  // namespace jetbot_rl
