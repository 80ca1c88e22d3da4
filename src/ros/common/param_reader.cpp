#include "jetbot_rl/ros/common/param_reader.h"

#include <ros/names.h>

#include <algorithm>

#include "jetbot_rl/config/former_names.h"

namespace jetbot_rl {

void GraphNames::check(const std::string& name, const std::vector<std::string>& names) const {
  NameList{}.check(name, names);
  for (const std::string& graph_name : names) GraphName{}.check(name, graph_name);
}

void GraphName::check(const std::string& name, const std::string& graph_name) const {
  std::string why;
  if (graph_name.empty() || !ros::names::validate(graph_name, why)) {
    throwInvalid(name, "'" + graph_name + "'",
                 "is not a valid ROS name" + (why.empty() ? std::string() : ": " + why));
  }
}

void refuseFormerParams(const ros::NodeHandle& pnh, const std::vector<std::string>& fields) {
  for (const FormerName& former : formerNames()) {
    const bool ours = std::find(fields.begin(), fields.end(), former.replaced_by) != fields.end();
    if (ours && pnh.hasParam(former.name)) throwInvalid(former.name, "(set)", former.refusal());
  }
}

void logParamError(const ros::NodeHandle& pnh, const std::exception& error) {
  ROS_FATAL("%s: parameter error: %s", pnh.getNamespace().c_str(), error.what());
}

void echoParams(const ros::NodeHandle& pnh, const std::string& fields_text) {
  ROS_INFO_STREAM("parameters of " << pnh.getNamespace() << ":\n" << fields_text);
}

void readParam(const ros::NodeHandle& pnh, const std::string& name,
               std::vector<std::string>& value) {
  std::string single;
  if (pnh.getParam(name, single)) {
    value = {single};
    return;
  }
  readParam<std::vector<std::string>>(pnh, name, value);
}

void readParam(const ros::NodeHandle& pnh, const std::string& name, std::vector<double>& value) {
  double single = 0.0;
  if (pnh.getParam(name, single)) {
    value = {single};
    return;
  }
  readParam<std::vector<double>>(pnh, name, value);
}

void readParam(const ros::NodeHandle& pnh, const std::string& name, std::int64_t& value) {
  int v = static_cast<int>(value);
  readParam(pnh, name, v);
  value = v;
}

void readParam(const ros::NodeHandle& pnh, const std::string& name, std::uint64_t& value) {
  int v = static_cast<int>(value);
  readParam(pnh, name, v);
  if (v < 0) throwInvalid(name, v, "must be >= 0");
  value = static_cast<std::uint64_t>(v);
}

}  // namespace jetbot_rl
