#include "jetbot_rl/ros/common/inline_callback_queue.h"

#include <ros/console.h>

#include <algorithm>
#include <vector>

namespace jetbot_rl {
namespace {

// The queues whose callbacks this thread is inside, innermost last. In one process (nodelets) a
// callback of one queue may publish to a subscriber of another, which publishes back: the chain
// must come back to the first queue as "nested", not wait for its own mutex.
thread_local std::vector<const InlineCallbackQueue*> running_queues;

}  // namespace

bool InlineCallbackQueue::insideCallback() { return !running_queues.empty(); }

void InlineCallbackQueue::addCallback(const ros::CallbackInterfacePtr& callback,
                                      std::uint64_t /*owner_id*/) {
  if (std::find(running_queues.begin(), running_queues.end(), this) != running_queues.end()) {
    nested_.push_back(callback);  // re-entered from one of our callbacks: run it right after
    return;
  }
  std::lock_guard<std::mutex> lock(mutex_);
  // Popped however the loop ends: a callback's exception must not leave this thread "inside".
  struct Running {
    explicit Running(const InlineCallbackQueue* queue) { running_queues.push_back(queue); }
    ~Running() { running_queues.pop_back(); }
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
