#include "jetbot_rl/ros/param_reader.h"

#include <ros/names.h>

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
