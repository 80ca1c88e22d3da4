#include "jetbot_rl/ros/env_node/sim_clock.h"

#include <cmath>

namespace jetbot_rl {

ros::Time simTime(std::uint64_t step, double control_dt) {
  // From the step count, rounded to the nanosecond: no accumulated error however long it runs.
  const long double ns = static_cast<long double>(step) * control_dt * 1e9L;
  ros::Time t;
  t.fromNSec(static_cast<std::uint64_t>(std::llround(ns)));
  return t;
}

ClockOutput::ClockOutput(ros::NodeHandle& nh, CountedSubscriberQueues& queues)
    : pub_(advertiseCounted<rosgraph_msgs::Clock>(nh, "/clock", 10, queues)) {}

void ClockOutput::send() {
  if (due_) pub_.publish(msg_);
  due_ = false;
}

}  // namespace jetbot_rl
