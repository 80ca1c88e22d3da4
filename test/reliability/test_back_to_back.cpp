// Back-to-back ~step calls and a reset storm on a loaded machine (a busy loop beside the node):
// every state the node answers with is also delivered on ~env_step, in order, to a subscriber
// that keeps up (issue 49: up to 87 % were lost under load, the same for every subscriber,
// because roscpp's network thread hands a burst of publications to each connection's queue of
// 16 at once); the node's /diagnostics says how many states it paced.
#include <diagnostic_msgs/DiagnosticArray.h>
#include <gtest/gtest.h>
#include <ros/ros.h>

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <mutex>
#include <string>
#include <vector>

#include "jetbot_rl/EnvStep.h"
#include "jetbot_rl/Reset.h"
#include "jetbot_rl/Step.h"

namespace {

constexpr int kSteps = 2000;  // back-to-back ~step calls
constexpr int kResets = 500;  // then back-to-back ~reset calls
constexpr int kMixed = 500;   // then a ~reset after every ~step

/// What a subscriber to ~env_step received, in order: each state's step and header.seq (roscpp
/// numbers a publisher's messages: a gap is a lost one).
struct Received {
  std::mutex mutex;
  std::condition_variable arrived;
  std::vector<std::uint64_t> states;
  std::vector<std::uint32_t> seqs;
  std::string paced;  // the last /diagnostics value "states paced"
};

TEST(BackToBack, EveryAnsweredStateIsPublished) {
  ros::NodeHandle nh;
  Received got;
  ros::Subscriber sub = nh.subscribe<jetbot_rl::EnvStep>(
      "/jetbot_env/env_step", 100000,  // never the reader's queue that drops
      [&got](const jetbot_rl::EnvStep::ConstPtr& msg) {
        std::lock_guard<std::mutex> lock(got.mutex);
        got.states.push_back(msg->step);
        got.seqs.push_back(msg->header.seq);
        got.arrived.notify_all();
      });
  ros::Subscriber diagnostics = nh.subscribe<diagnostic_msgs::DiagnosticArray>(
      "/diagnostics", 100, [&got](const diagnostic_msgs::DiagnosticArray::ConstPtr& msg) {
        for (const auto& status : msg->status) {
          for (const auto& kv : status.values) {
            if (kv.key != "states paced") continue;
            std::lock_guard<std::mutex> lock(got.mutex);
            got.paced = kv.value;
          }
        }
      });
  ros::AsyncSpinner spinner(1);
  spinner.start();
  // Persistent connections, made once the services are there (a failed first call would end one).
  ASSERT_TRUE(ros::service::waitForService("/jetbot_env/step", ros::Duration(60.0)));
  ASSERT_TRUE(ros::service::waitForService("/jetbot_env/reset", ros::Duration(60.0)));
  ros::ServiceClient step = nh.serviceClient<jetbot_rl::Step>("/jetbot_env/step", true);
  ros::ServiceClient reset = nh.serviceClient<jetbot_rl::Reset>("/jetbot_env/reset", true);
  jetbot_rl::Reset r;
  ASSERT_TRUE(reset.call(r) && r.response.success) << r.response.message;
  std::vector<std::uint64_t> answered;  // each answer's step
  const std::size_t num_envs = r.response.state.num_envs;
  std::uint64_t current = r.response.state.step;
  const auto call_step = [&] {
    jetbot_rl::Step s;
    s.request.actions.step = current;
    s.request.actions.velocities.assign(num_envs * 2, 5.0f);
    ASSERT_TRUE(step.call(s) && s.response.success) << s.response.message;
    current = s.response.state.step;
    answered.push_back(s.response.state.step);
  };
  const auto call_reset = [&] {
    jetbot_rl::Reset q;
    q.request.seed = -1;
    ASSERT_TRUE(reset.call(q) && q.response.success) << q.response.message;
    answered.push_back(q.response.state.step);
  };
  // Steps until one's state arrives: the subscription is connected from then on (each step's
  // state is new: one that arrives late is older than the one waited for).
  bool connected = false;
  for (int attempt = 0; attempt < 60 && !connected; ++attempt) {
    ASSERT_NO_FATAL_FAILURE(call_step());
    std::unique_lock<std::mutex> lock(got.mutex);
    connected = got.arrived.wait_for(lock, std::chrono::milliseconds(500), [&] {
      return !got.states.empty() && got.states.back() == current;
    });
    got.states.clear();
    got.seqs.clear();
  }
  ASSERT_TRUE(connected) << "no ~env_step received";
  answered.clear();
  const auto start = std::chrono::steady_clock::now();
  for (int i = 0; i < kSteps; ++i) ASSERT_NO_FATAL_FAILURE(call_step());
  for (int i = 0; i < kResets; ++i) ASSERT_NO_FATAL_FAILURE(call_reset());
  for (int i = 0; i < kMixed; ++i) {
    ASSERT_NO_FATAL_FAILURE(call_step());
    ASSERT_NO_FATAL_FAILURE(call_reset());
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  std::unique_lock<std::mutex> lock(got.mutex);
  // Waits for the last answered state, or 10 s without a new one (the rest were lost).
  for (;;) {
    const std::size_t before = got.states.size();
    if (before >= answered.size()) break;
    if (!got.arrived.wait_for(lock, std::chrono::seconds(10),
                              [&] { return got.states.size() > before; })) {
      break;
    }
  }
  std::printf(
      "FIGURE: %zu states answered in %.2f s (%.0f a second), %zu received on ~env_step, "
      "%zu lost; states paced by the node: %s\n",
      answered.size(), seconds, answered.size() / seconds, got.states.size(),
      answered.size() - std::min(answered.size(), got.states.size()),
      got.paced.empty() ? "(no report yet)" : got.paced.c_str());
  ASSERT_EQ(got.states, answered) << "states lost on ~env_step";
  for (std::size_t i = 1; i < got.seqs.size(); ++i) ASSERT_EQ(got.seqs[i], got.seqs[i - 1] + 1);
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_back_to_back");
  ros::NodeHandle nh;  // keeps the node alive for the test
  return RUN_ALL_TESTS();
}
