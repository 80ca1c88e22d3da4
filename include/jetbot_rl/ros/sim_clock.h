#pragma once

#include <ros/node_handle.h>
#include <ros/publisher.h>
#include <ros/time.h>
#include <rosgraph_msgs/Clock.h>

#include <cstdint>

namespace jetbot_rl {

/// Simulation time: step x control_dt, computed from the step count so that it never drifts.
/// Publishes it on /clock when enabled.
class SimClock {
 public:
  /// `control_dt` [s]; advertises /clock on `nh` only when `publish` is true.
  SimClock(ros::NodeHandle& nh, double control_dt, bool publish);
  /// Simulation time after `step` control steps [s].
  ros::Time timeAt(std::uint64_t step) const;
  /// Publishes timeAt(step) on /clock (no-op when disabled).
  void publish(std::uint64_t step);

 private:
  double control_dt_;
  bool enabled_;
  ros::Publisher pub_;
  rosgraph_msgs::Clock msg_;
};

}  // namespace jetbot_rl
