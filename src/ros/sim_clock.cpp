#include "jetbot_rl/ros/sim_clock.h"

#include <cmath>

namespace jetbot_rl {

SimClock::SimClock(ros::NodeHandle& nh, double control_dt, bool publish)
    : control_dt_(control_dt), enabled_(publish) {
  if (enabled_) pub_ = nh.advertise<rosgraph_msgs::Clock>("/clock", 10);
}

ros::Time SimClock::timeAt(std::uint64_t step) const {
  // From the step count, rounded to the nanosecond: no accumulated error however long it runs.
  const long double ns = static_cast<long double>(step) * control_dt_ * 1e9L;
  ros::Time t;
  t.fromNSec(static_cast<std::uint64_t>(std::llround(ns)));
  return t;
}

void SimClock::publish(std::uint64_t step) {
  if (!enabled_) return;
  msg_.clock = timeAt(step);
  pub_.publish(msg_);
}

}  // namespace jetbot_rl
