#pragma once

#include <diagnostic_msgs/DiagnosticArray.h>
#include <ros/node_handle.h>
#include <ros/publisher.h>

#include <cstdint>
#include <string>

namespace jetbot_rl {

/// Counts inputs a learner drops (messages refused unread, non-finite odometry) and publishes the
/// count and the last reason on /diagnostics at each drop (WARN), so that nothing is dropped
/// without a trace; a drop costs one small message, as the input it drops did.
class DropCounter {
 public:
  /// `name`: the DiagnosticStatus name (e.g. "/jetbot_ppo_trainer: env client /jetbot_env");
  /// `what`: the counted inputs as the values name them (e.g. "malformed messages").
  DropCounter(ros::NodeHandle& nh, std::string name, std::string what);
  /// Counts one drop, logs it (throttled) and publishes the new count with `reason`.
  void drop(const std::string& reason);
  /// Drops so far.
  std::uint64_t count() const { return count_; }

 private:
  ros::Publisher pub_;
  std::string name_, what_;
  std::uint64_t count_ = 0;
};

}  // namespace jetbot_rl
