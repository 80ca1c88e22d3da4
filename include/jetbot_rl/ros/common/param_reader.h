#pragma once

#include <ros/console.h>
#include <ros/node_handle.h>

#include <cstdint>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "jetbot_rl/config/config_fields.h"
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

/// A parameter's value as rosparam writes it. (Called by its global name: the generated
/// jetbot_rl messages declare operator<< in namespace jetbot_rl, which hides the global one.)
inline std::string paramText(const XmlRpc::XmlRpcValue& raw) {
  std::ostringstream s;
  ::operator<<(s, raw);
  return s.str();
}

/// Reads private parameter `name` into `value` when it is set, keeping the default otherwise;
/// throws ConfigError naming the parameter and its value when it has the wrong type.
template <typename T, std::enable_if_t<!IsNamedEnum<T>::value, int> = 0>
void readParam(const ros::NodeHandle& pnh, const std::string& name, T& value) {
  if (!pnh.hasParam(name) || pnh.getParam(name, value)) return;
  XmlRpc::XmlRpcValue raw;
  pnh.getParam(name, raw);
  throwInvalid(name, paramText(raw), std::string("must be ") + paramTypeName(value));
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
  std::string text() const { return "must be a non-empty list of distinct, valid ROS names"; }
};

/// One valid ROS graph name (e.g. an env node).
struct GraphName {
  const char* unit = "";
  void check(const std::string& name, const std::string& graph_name) const;
  std::string text() const { return "must be a valid ROS name"; }
};

/// Reads every field of `config` (see config_fields.h) present under `pnh`; does not validate.
template <typename C>
void readFields(const ros::NodeHandle& pnh, C& config) {
  visitFields(config, [&pnh](const char* name, auto& value, const auto&, const char*) {
    readParam(pnh, name, value);
  });
}

/// Throws ConfigError ("invalid OLD = (set): was renamed NEW", or why it is gone) when `pnh` has
/// a parameter of an earlier version (formerNames()) that one of `fields` replaced.
void refuseFormerParams(const ros::NodeHandle& pnh, const std::vector<std::string>& fields);

/// Reads the fields of T present under `pnh` over T's defaults and validates them (every field's
/// rule, then T's rules between fields); a former name of one of them is refused. Throws
/// ConfigError naming the parameter and its value.
template <typename T>
T readParams(const ros::NodeHandle& pnh) {
  T config;
  refuseFormerParams(pnh, fieldNames(config));
  readFields(pnh, config);
  validateConfig(config);
  return config;
}

/// ROS_FATAL "<namespace>: parameter error: <what>".
void logParamError(const ros::NodeHandle& pnh, const std::exception& error);

/// INFO "parameters of <namespace>:" and one line per field (describeFields' text).
void echoParams(const ros::NodeHandle& pnh, const std::string& fields_text);

/// The start-up of every node and nodelet: readParams<T>(pnh), then `resolve(T&)` (which may
/// turn a value into what it stands for, e.g. a run directory into its checkpoint, and throw
/// ConfigError), then the echo at INFO. A bad parameter is logged with ROS_FATAL naming it and
/// returns std::nullopt.
template <typename T, typename Resolve>
std::optional<T> loadParams(const ros::NodeHandle& pnh, Resolve&& resolve) {
  try {
    T config = readParams<T>(pnh);
    resolve(config);
    echoParams(pnh, describeFields(config));
    return config;
  } catch (const ConfigError& e) {
    logParamError(pnh, e);
    return std::nullopt;
  }
}
template <typename T>
std::optional<T> loadParams(const ros::NodeHandle& pnh) {
  return loadParams<T>(pnh, [](T&) {});
}

}  // namespace jetbot_rl
