#pragma once

#include <ros/node_handle.h>

#include <string>

namespace jetbot_rl {

/// A topic parameter's value as a name NodeHandle methods take: "~name" (which they refuse) as
/// the private name under `pnh`, any other name as given.
inline std::string resolvePrivateTopic(const ros::NodeHandle& pnh, const std::string& topic) {
  return topic.rfind('~', 0) == 0 ? pnh.resolveName(topic.substr(1)) : topic;
}

}  // namespace jetbot_rl
