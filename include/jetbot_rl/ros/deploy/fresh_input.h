#pragma once

#include <ros/node_handle.h>
#include <ros/subscriber.h>
#include <ros/transport_hints.h>

#include <chrono>
#include <functional>
#include <limits>
#include <string>

#include "jetbot_rl/ros/common/drop_counter.h"

namespace jetbot_rl {

/**
 * The newest valid message of one of the robot's inputs (odometry, scan) and when it came (wall
 * clock): an input older than its timeout is stale, and a driver stops the robot on it. A message
 * `check` refuses (non-finite values) is dropped and counted on /diagnostics, never used.
 * Callbacks and readers run in the same spinner thread.
 */
template <class M>
class FreshInput {
 public:
  /// Returns "" for a message it takes, else why it is dropped.
  using Check = std::function<std::string(const M&)>;

  FreshInput(ros::NodeHandle& nh, const std::string& topic, const std::string& what, double timeout,
             Check check, DropCounter& drops)
      : what_(what), timeout_(timeout), check_(std::move(check)), drops_(drops) {
    sub_ =
        nh.subscribe(topic, 10, &FreshInput::onMessage, this, ros::TransportHints().tcpNoDelay());
  }
  FreshInput(const FreshInput&) = delete;
  FreshInput& operator=(const FreshInput&) = delete;

  /// The newest message taken, or null before one came.
  const typename M::ConstPtr& latest() const { return latest_; }
  /// True when a message came within the timeout.
  bool fresh() const {
    return latest_ &&
           std::chrono::steady_clock::now() - time_ <= std::chrono::duration<double>(timeout_);
  }
  /// Seconds since the newest message (infinity before one came) [s, wall].
  double age() const {
    if (!latest_) return std::numeric_limits<double>::infinity();
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - time_).count();
  }
  const std::string& what() const { return what_; }
  std::string topic() const { return sub_.getTopic(); }

 private:
  void onMessage(const typename M::ConstPtr& msg) {
    const std::string why = check_(*msg);
    if (!why.empty()) {
      drops_.drop(what_ + " on " + sub_.getTopic() + " " + why + ": dropped");
      return;
    }
    latest_ = msg;
    time_ = std::chrono::steady_clock::now();
  }

  std::string what_;
  double timeout_;
  Check check_;
  DropCounter& drops_;
  ros::Subscriber sub_;
  typename M::ConstPtr latest_;
  std::chrono::steady_clock::time_point time_;
};

}  // namespace jetbot_rl
