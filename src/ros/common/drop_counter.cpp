#include "jetbot_rl/ros/common/drop_counter.h"

#include <ros/console.h>

#include <utility>

namespace jetbot_rl {

DropCounter::DropCounter(ros::NodeHandle& nh, std::string name, std::string what)
    : pub_(nh.advertise<diagnostic_msgs::DiagnosticArray>("/diagnostics", 10)),
      name_(std::move(name)),
      what_(std::move(what)) {}

void DropCounter::drop(const std::string& reason) {
  ++count_;
  ROS_WARN_THROTTLE(5.0, "%s: %s (%llu %s so far)", name_.c_str(), reason.c_str(),
                    static_cast<unsigned long long>(count_), what_.c_str());
  diagnostic_msgs::DiagnosticStatus status;
  status.level = diagnostic_msgs::DiagnosticStatus::WARN;
  status.name = name_;
  status.message = reason;
  diagnostic_msgs::KeyValue value;
  value.key = what_;
  value.value = std::to_string(count_);
  status.values.push_back(value);
  value.key = "last reason";
  value.value = reason;
  status.values.push_back(value);
  diagnostic_msgs::DiagnosticArray msg;
  msg.header.stamp = ros::Time::now();
  msg.status.push_back(std::move(status));
  pub_.publish(msg);
}

}  // namespace jetbot_rl
