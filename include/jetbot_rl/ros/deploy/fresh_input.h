#pragma once

#include <ros/node_handle.h>
#include <ros/subscriber.h>
#include <ros/transport_hints.h>

#include <chrono>
#include <functional>
#include <limits>
#include <memory>
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
  using Callback = std::function<void(const typename M::ConstPtr&)>;
  /// A subscription made by its owner (roscpp's, image_transport's): kept while the input lives.
  struct Subscription {
    std::shared_ptr<void> handle;
    std::function<std::string()> topic;
  };
  /// Subscribes `callback` to the input's topic.
  using Subscribe = std::function<Subscription(Callback callback)>;

  /// Subscribed through roscpp, TCP_NODELAY.
  FreshInput(ros::NodeHandle& nh, const std::string& topic, const std::string& what, double timeout,
             Check check, DropCounter& drops)
      : FreshInput(
            [&nh, &topic](Callback callback) {
              auto sub = std::make_shared<ros::Subscriber>(nh.subscribe<M>(
                  topic, 10, callback, ros::VoidConstPtr(), ros::TransportHints().tcpNoDelay()));
              return Subscription{sub, [sub] { return sub->getTopic(); }};
            },
            what, timeout, std::move(check), drops) {}
  /// Subscribed through `subscribe` (a transport other than roscpp's).
  FreshInput(const Subscribe& subscribe, const std::string& what, double timeout, Check check,
             DropCounter& drops)
      : what_(what), timeout_(timeout), check_(std::move(check)), drops_(drops) {
    sub_ = subscribe([this](const typename M::ConstPtr& msg) { onMessage(msg); });
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
  std::string topic() const { return sub_.topic(); }

 private:
  void onMessage(const typename M::ConstPtr& msg) {
    const std::string why = check_(*msg);
    if (!why.empty()) {
      drops_.drop(what_ + " on " + topic() + " " + why + ": dropped");
      return;
    }
    latest_ = msg;
    time_ = std::chrono::steady_clock::now();
  }

  std::string what_;
  double timeout_;
  Check check_;
  DropCounter& drops_;
  Subscription sub_;
  typename M::ConstPtr latest_;
  std::chrono::steady_clock::time_point time_;
};

}  // namespace jetbot_rl
