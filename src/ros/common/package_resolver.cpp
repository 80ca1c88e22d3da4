#include "jetbot_rl/ros/common/package_resolver.h"

#include <ros/package.h>

#include "jetbot_rl/errors.h"

namespace jetbot_rl {

std::string resolvePackageUri(const std::string& uri) {
  static const std::string kPackage = "package://";
  if (uri.compare(0, kPackage.size(), kPackage) != 0) {
    throw Error("only package:// URIs (besides file paths and file://) are resolved");
  }
  const std::string rest = uri.substr(kPackage.size());
  const auto slash = rest.find('/');
  const std::string package = rest.substr(0, slash);
  if (package.empty()) throw Error("no package name after package://");
  const std::string directory = ros::package::getPath(package);
  if (directory.empty()) {
    throw Error("package '" + package + "' is not on the ROS package path (ROS_PACKAGE_PATH)");
  }
  return slash == std::string::npos ? directory : directory + rest.substr(slash);
}

MeshResolver packageResolver() { return &resolvePackageUri; }

}  // namespace jetbot_rl
