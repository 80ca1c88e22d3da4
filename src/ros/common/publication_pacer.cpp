#include "jetbot_rl/ros/common/publication_pacer.h"

#include <ros/poll_manager.h>

#include <chrono>
#include <condition_variable>
#include <mutex>

#include "jetbot_rl/errors.h"
#include "jetbot_rl/ros/common/inline_callback_queue.h"

namespace jetbot_rl {

struct PublicationPacer::Shared {
  std::mutex mutex;
  std::condition_variable passed;
  std::uint64_t passes = 0;
  int since_pass = 0;  // states published since the last pass began
  std::uint64_t waits = 0, timeouts = 0;
};

PublicationPacer::PublicationPacer(int limit, double timeout)
    : shared_(std::make_shared<Shared>()), limit_(limit), timeout_(timeout) {
  if (limit < 1) throwInvalid("PublicationPacer limit", limit, "must be >= 1");
  // Listeners run at the start of each pass, after roscpp's own (TopicManager's, connected at
  // ros::start(), which hands the queued messages to the subscriber connections).
  std::shared_ptr<Shared> shared = shared_;
  listener_ = ros::PollManager::instance()->addPollThreadListener([shared] {
    {
      std::lock_guard<std::mutex> lock(shared->mutex);
      ++shared->passes;
      shared->since_pass = 0;
    }
    shared->passed.notify_all();
  });
}

PublicationPacer::~PublicationPacer() {
  ros::PollManager::instance()->removePollThreadListener(listener_);
}

bool PublicationPacer::wait() {
  std::unique_lock<std::mutex> lock(shared_->mutex);
  bool on_time = true;
  // Inside an inline callback no pass can come while this thread waits: it is the network
  // thread itself, or (nodelets) an in-process publisher's that holds the topic lock the network
  // thread's pass needs (each wait ran into the time-out: 1 s every `limit` states).
  if (shared_->since_pass >= limit_ && !InlineCallbackQueue::insideCallback()) {
    ++shared_->waits;
    const std::uint64_t pass = shared_->passes;
    ros::PollManager::instance()->getPollSet().signal();  // an idle thread sleeps up to 100 ms
    on_time = shared_->passed.wait_for(lock, std::chrono::duration<double>(timeout_),
                                       [&] { return shared_->passes != pass; });
    if (!on_time) {
      ++shared_->timeouts;
      shared_->since_pass = 0;  // one time-out per `limit` states while the thread stays away
    }
  }
  ++shared_->since_pass;
  return on_time;
}

std::uint64_t PublicationPacer::waits() const {
  std::lock_guard<std::mutex> lock(shared_->mutex);
  return shared_->waits;
}

std::uint64_t PublicationPacer::timeouts() const {
  std::lock_guard<std::mutex> lock(shared_->mutex);
  return shared_->timeouts;
}

}  // namespace jetbot_rl
