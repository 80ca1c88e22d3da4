#pragma once

#include <ros/node_handle.h>
#include <ros/publisher.h>
#include <ros/time.h>
#include <rosgraph_msgs/Clock.h>

#include <cstdint>

#include "jetbot_rl/ros/env_node/state_output.h"

namespace jetbot_rl {

/// Simulation time after `step` control steps of `control_dt` [s], computed from the step count
/// (rounded to the nanosecond) so that it never drifts.
ros::Time simTime(std::uint64_t step, double control_dt);

/// /clock: the simulation time of every state.
class ClockOutput : public StateOutput {
 public:
  ClockOutput(ros::NodeHandle& nh, CountedSubscriberQueues& queues);
  void capture(const BatchedEnv&, const EnvStep::ConstPtr& msg, bool) override {
    msg_.clock = msg->header.stamp;
    due_ = true;
  }
  void send() override;

 private:
  ros::Publisher pub_;
  rosgraph_msgs::Clock msg_;
  bool due_ = false;
};

}  // namespace jetbot_rl
