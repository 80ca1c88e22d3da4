#pragma once

#include <ros/callback_queue_interface.h>

#include <cstdint>
#include <deque>
#include <mutex>

namespace jetbot_rl {

/**
 * A roscpp callback queue that runs each callback at once, in the thread that delivers it
 * (roscpp's network thread for topics and services), one at a time under mutex().
 *
 * A lockstep round trip through the global queue wakes six threads (network thread, spinner and
 * the network thread again to write, on each side); run inline, a reply is written by the thread
 * that read the request, and only the two network threads wake. Hold mutex() to share state with
 * callbacks that run elsewhere (timers on the spinner).
 */
class InlineCallbackQueue : public ros::CallbackQueueInterface {
 public:
  /// Runs `callback` now; a callback added from inside a callback of this queue (also through
  /// other inline queues in between, as in-process publishers do) runs after it returns.
  void addCallback(const ros::CallbackInterfacePtr& callback, std::uint64_t owner_id = 0) override;
  /// Nothing is ever queued for long, so there is nothing to remove.
  void removeByID(std::uint64_t /*owner_id*/) override {}
  /// Held while a callback of this queue runs.
  std::mutex& mutex() { return mutex_; }
  /// True in a thread that runs a callback of some InlineCallbackQueue: roscpp's network thread,
  /// or (nodelets) an in-process publisher's, which holds roscpp's topic lock meanwhile.
  static bool insideCallback();

 private:
  std::mutex mutex_;
  std::deque<ros::CallbackInterfacePtr> nested_;  // added from inside a callback, guarded
};

}  // namespace jetbot_rl
