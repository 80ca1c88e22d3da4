#include "jetbot_rl/ros/inline_callback_queue.h"

#include <ros/console.h>

namespace jetbot_rl {
namespace {

thread_local const InlineCallbackQueue* running_queue = nullptr;  // the queue this thread is in

}  // namespace

void InlineCallbackQueue::addCallback(const ros::CallbackInterfacePtr& callback,
                                      std::uint64_t /*owner_id*/) {
  if (running_queue == this) {  // re-entered from one of our callbacks: run it right after
    nested_.push_back(callback);
    return;
  }
  std::lock_guard<std::mutex> lock(mutex_);
  // Cleared however the loop ends: a callback's exception must not leave this thread "inside".
  struct Running {
    explicit Running(const InlineCallbackQueue* queue) { running_queue = queue; }
    ~Running() { running_queue = nullptr; }
  } running(this);
  nested_.push_back(callback);
  while (!nested_.empty()) {
    const ros::CallbackInterfacePtr next = nested_.front();
    nested_.pop_front();
    // TryAgain only comes from a callback already running elsewhere, which the mutex rules out.
    if (next->call() == ros::CallbackInterface::TryAgain) {
      ROS_ERROR("inline callback queue: a callback asked to be called again; it was dropped");
    }
  }
}

}  // namespace jetbot_rl
