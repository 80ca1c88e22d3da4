#pragma once

#include <ros/node_handle.h>

#include <cstdint>
#include <string>
#include <vector>

#include "jetbot_rl/config_fields.h"
#include "jetbot_rl/errors.h"

namespace jetbot_rl {

/// What a parameter of type T must be, for error messages.
inline const char* paramTypeName(bool) { return "a bool"; }
inline const char* paramTypeName(int) { return "an integer"; }
inline const char* paramTypeName(double) { return "a number"; }
inline const char* paramTypeName(const std::string&) { return "a string"; }
inline const char* paramTypeName(const std::vector<int>&) { return "a list of integers"; }
inline const char* paramTypeName(const std::vector<double>&) { return "a list of numbers"; }
inline const char* paramTypeName(const std::vector<std::string>&) { return "a list of strings"; }

/// Reads private parameter `name` into `value` when it is set, keeping the default otherwise;
/// throws ConfigError naming the parameter and its value when it has the wrong type.
template <typename T, std::enable_if_t<!IsNamedEnum<T>::value, int> = 0>
void readParam(const ros::NodeHandle& pnh, const std::string& name, T& value) {
  if (!pnh.hasParam(name) || pnh.getParam(name, value)) return;
  XmlRpc::XmlRpcValue raw;
  pnh.getParam(name, raw);
  throwInvalid(name, raw, std::string("must be ") + paramTypeName(value));
}

/// A list of names; a single name stands for a list of one.
void readParam(const ros::NodeHandle& pnh, const std::string& name,
               std::vector<std::string>& value);
/// A list of numbers; a single number stands for a list of one.
void readParam(const ros::NodeHandle& pnh, const std::string& name, std::vector<double>& value);
/// 64-bit integers are 32-bit integers on the parameter server; negative for unsigned: invalid.
void readParam(const ros::NodeHandle& pnh, const std::string& name, std::int64_t& value);
void readParam(const ros::NodeHandle& pnh, const std::string& name, std::uint64_t& value);

/// An enum parameter is its name as a string (enumNames(E)); ConfigError naming the choices.
template <typename E, std::enable_if_t<IsNamedEnum<E>::value, int> = 0>
void readParam(const ros::NodeHandle& pnh, const std::string& name, E& value) {
  std::string text = enumName(value);
  readParam(pnh, name, text);
  value = parseEnum<E>(name, text);
}

/// A non-empty list of distinct, valid ROS graph names (e.g. env nodes).
struct GraphNames {
  const char* unit = "";
  void check(const std::string& name, const std::vector<std::string>& names) const;
};

/// One valid ROS graph name (e.g. an env node).
struct GraphName {
  const char* unit = "";
  void check(const std::string& name, const std::string& graph_name) const;
};

/// Reads every field of `config` (see config_fields.h) present under `pnh`; does not validate.
template <typename C>
void readFields(const ros::NodeHandle& pnh, C& config) {
  visitFields(config,
              [&pnh](const char* name, auto& value, const auto&) { readParam(pnh, name, value); });
}

}  // namespace jetbot_rl
