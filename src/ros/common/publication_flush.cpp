#include "jetbot_rl/ros/common/publication_flush.h"

#include <ros/init.h>
#include <ros/poll_manager.h>

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <memory>
#include <mutex>

namespace jetbot_rl {
namespace {

/// Counts the network thread's passes (shared: the listener may run once more after we return).
struct PassCounter {
  std::mutex mutex;
  std::condition_variable passed;
  std::uint64_t passes = 0;
};

}  // namespace

bool flushPublications(double timeout) {
  if (!ros::ok()) return false;  // shut down already: nothing will be written
  const ros::PollManagerPtr& manager = ros::PollManager::instance();
  ros::PollSet& poll_set = manager->getPollSet();
  auto counter = std::make_shared<PassCounter>();
  // Called at the start of each pass, before the thread polls its sockets and writes. Waking the
  // thread (signal) makes an idle pass return at once instead of after its 100 ms poll time-out.
  const boost::signals2::connection listener = manager->addPollThreadListener([counter, &poll_set] {
    bool more;
    {
      std::lock_guard<std::mutex> lock(counter->mutex);
      more = ++counter->passes < 3;
    }
    counter->passed.notify_all();
    if (more) poll_set.signal();
  });
  poll_set.signal();
  bool flushed;
  {
    std::unique_lock<std::mutex> lock(counter->mutex);
    // The first call ends a pass that may have begun before the call; the third ends two whole
    // passes after it.
    flushed = counter->passed.wait_for(lock, std::chrono::duration<double>(timeout),
                                       [&counter] { return counter->passes >= 3; });
  }
  manager->removePollThreadListener(listener);
  return flushed;
}

}  // namespace jetbot_rl
