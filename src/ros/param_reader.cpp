#include "jetbot_rl/ros/param_reader.h"

namespace jetbot_rl {

void readParam(const ros::NodeHandle& pnh, const std::string& name,
               std::vector<std::string>& value) {
  std::string single;
  if (pnh.getParam(name, single)) {
    value = {single};
    return;
  }
  readParam<std::vector<std::string>>(pnh, name, value);
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
