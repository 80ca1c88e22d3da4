// InlineCallbackQueue without a master: callbacks run at once, one at a time, nested ones after;
// PublicationPacer never waits inside them.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <boost/make_shared.hpp>
#include <functional>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "jetbot_rl/ros/common/inline_callback_queue.h"
#include "jetbot_rl/ros/common/publication_pacer.h"

namespace jetbot_rl {
namespace {

class FunctionCallback : public ros::CallbackInterface {
 public:
  explicit FunctionCallback(std::function<void()> f) : f_(std::move(f)) {}
  CallResult call() override {
    f_();
    return Success;
  }

 private:
  std::function<void()> f_;
};

ros::CallbackInterfacePtr callback(std::function<void()> f) {
  return boost::make_shared<FunctionCallback>(std::move(f));
}

TEST(InlineCallbackQueue, RunsACallbackAtOnceInTheCallingThreadUnderItsMutex) {
  InlineCallbackQueue queue;
  std::thread::id ran_in;
  bool locked_while_running = false;
  queue.addCallback(callback([&] {
    ran_in = std::this_thread::get_id();
    std::thread other([&] {
      std::unique_lock<std::mutex> attempt(queue.mutex(), std::try_to_lock);
      locked_while_running = !attempt.owns_lock();
    });
    other.join();
  }));
  EXPECT_EQ(ran_in, std::this_thread::get_id());
  EXPECT_TRUE(locked_while_running);
  std::unique_lock<std::mutex> after(queue.mutex(), std::try_to_lock);
  EXPECT_TRUE(after.owns_lock());  // released on return
}

TEST(InlineCallbackQueue, ACallbackAddedByACallbackRunsAfterItReturns) {
  InlineCallbackQueue queue;
  std::vector<std::string> order;
  queue.addCallback(callback([&] {
    order.push_back("outer begins");
    queue.addCallback(callback([&] { order.push_back("inner"); }));
    order.push_back("outer ends");
  }));
  EXPECT_EQ(order, (std::vector<std::string>{"outer begins", "outer ends", "inner"}));
}

TEST(InlineCallbackQueue, APingPongBetweenTwoQueuesInOneThreadRunsAsNestedCallbacks) {
  // In-process publishers (nodelets): a callback of queue a adds to queue b, whose callback adds
  // back to a. That must queue behind a's running callback, not wait for a's mutex (deadlock).
  InlineCallbackQueue a, b;
  std::vector<std::string> order;
  int rounds = 0;
  std::function<void()> on_a, on_b;
  on_a = [&] {
    order.push_back("a" + std::to_string(rounds));
    if (++rounds < 3) b.addCallback(callback(on_b));
  };
  on_b = [&] {
    order.push_back("b" + std::to_string(rounds));
    a.addCallback(callback(on_a));
  };
  a.addCallback(callback(on_a));
  EXPECT_EQ(order, (std::vector<std::string>{"a0", "b1", "a1", "b2", "a2"}));
}

TEST(InlineCallbackQueue, AThrowingCallbackLeavesTheQueueUsable) {
  InlineCallbackQueue queue;
  EXPECT_THROW(queue.addCallback(callback([] { throw std::runtime_error("boom"); })),
               std::runtime_error);
  bool ran = false;
  queue.addCallback(callback([&] { ran = true; }));
  EXPECT_TRUE(ran);
}

TEST(InlineCallbackQueue, CallbacksFromSeveralThreadsNeverOverlap) {
  InlineCallbackQueue queue;
  std::atomic<int> running{0}, most{0}, calls{0};
  auto work = [&] {
    const int now = ++running;
    int seen = most.load();
    while (now > seen && !most.compare_exchange_weak(seen, now)) {
    }
    std::this_thread::yield();  // give another thread the chance to overlap
    ++calls;
    --running;
  };
  std::vector<std::thread> threads;
  for (int t = 0; t < 4; ++t) {
    threads.emplace_back([&] {
      for (int i = 0; i < 2000; ++i) queue.addCallback(callback(work));
    });
  }
  for (auto& t : threads) t.join();
  EXPECT_EQ(calls.load(), 8000);
  EXPECT_EQ(most.load(), 1);
}

TEST(PublicationPacer, NeverWaitsInsideAnInlineCallback) {
  // No network thread runs here (no ros::start()): outside a callback, the state after `limit`
  // waits for a pass that never comes and times out; inside one (a nodelet's in-process
  // publisher, whose topic lock the network thread waits for), it goes out at once.
  PublicationPacer pacer(1, 0.05);
  EXPECT_TRUE(pacer.wait());
  EXPECT_FALSE(pacer.wait());
  EXPECT_EQ(pacer.timeouts(), 1u);
  InlineCallbackQueue queue;
  bool inside = false;
  queue.addCallback(callback([&] {
    inside = InlineCallbackQueue::insideCallback();
    for (int k = 0; k < 5; ++k) EXPECT_TRUE(pacer.wait());
  }));
  EXPECT_TRUE(inside);
  EXPECT_FALSE(InlineCallbackQueue::insideCallback());
  EXPECT_EQ(pacer.timeouts(), 1u);  // none inside
  EXPECT_EQ(pacer.waits(), 1u);
}

}  // namespace
}  // namespace jetbot_rl
