#pragma once

#include <string>

#include "jetbot_rl/world/gazebo/mesh_loader.h"

namespace jetbot_rl {

/// Path of a `package://<package>/<path>` URI: <package>'s directory (ros::package::getPath, the
/// ROS package path) joined with <path>. Throws Error naming the package when it is not found,
/// or the scheme when it is not package://.
std::string resolvePackageUri(const std::string& uri);

/// The MeshResolver the ROS adapter gives the core: resolvePackageUri.
MeshResolver packageResolver();

}  // namespace jetbot_rl
