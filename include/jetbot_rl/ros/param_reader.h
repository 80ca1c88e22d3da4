#pragma once

#include <ros/node_handle.h>

#include <string>
#include <vector>

#include "jetbot_rl/errors.h"

namespace jetbot_rl {

/// What a parameter of type T must be, for error messages.
inline const char* paramTypeName(bool) { return "a bool"; }
inline const char* paramTypeName(int) { return "an integer"; }
inline const char* paramTypeName(double) { return "a number"; }
inline const char* paramTypeName(const std::string&) { return "a string"; }
inline const char* paramTypeName(const std::vector<int>&) { return "a list of integers"; }
inline const char* paramTypeName(const std::vector<std::string>&) { return "a list of strings"; }

/// Reads private parameter `name` into `value` when it is set, keeping the default otherwise;
/// throws ConfigError naming the parameter and its value when it has the wrong type.
template <typename T>
void readParam(const ros::NodeHandle& pnh, const std::string& name, T& value) {
  if (!pnh.hasParam(name) || pnh.getParam(name, value)) return;
  XmlRpc::XmlRpcValue raw;
  pnh.getParam(name, raw);
  throwInvalid(name, raw, std::string("must be ") + paramTypeName(value));
}

}  // namespace jetbot_rl
