#include "jetbot_rl/ros/client/ros_vec_env.h"

#include <ros/console.h>
#include <ros/this_node.h>
#include <ros/transport_hints.h>

#include <algorithm>
#include <boost/make_shared.hpp>
#include <chrono>
#include <thread>

#include "jetbot_rl/Reset.h"
#include "jetbot_rl/ros/common/bounded_service.h"
#include "jetbot_rl/ros/common/bounded_subscription.h"
#include "jetbot_rl/ros/common/msg_conversion.h"

namespace jetbot_rl {
namespace {

// The lockstep learner has one message in flight; realtime players drop old states only.
constexpr std::uint32_t kQueueSize = 8;
// Lockstep: resend targets that got no answer within this [s, wall] (see step()).
const double kResendAfter = WheelTargets::RESEND_AFTER;

/// A callback that does nothing: queued to wake a thread waiting on the queue.
struct WakeUp : ros::CallbackInterface {
  CallResult call() override { return Success; }
};

std::string seconds(double s) {
  char buf[32];
  std::snprintf(buf, sizeof(buf), "%.1f s", s);
  return buf;
}

}  // namespace

RosVecEnv::RosVecEnv(const std::string& env_ns, bool lockstep, double timeout,
                     const std::atomic<bool>* stop, const ros::NodeHandle& parent)
    : env_ns_(parent.resolveName(env_ns)),
      lockstep_(lockstep),
      timeout_(timeout),
      stop_(stop),
      nh_(parent),
      refused_(nh_, ros::this_node::getName() + ": env client " + env_ns_, "malformed messages") {
  nh_.setCallbackQueue(&queue_);
  // Anyone can publish on these topics: a message whose lengths exceed its bytes is dropped
  // unread (roscpp would allocate what it claims), counted, logged and shown on /diagnostics.
  const auto refused = [this](const std::string& reason) {
    refused_.drop("refused unread: " + reason);
  };
  spec_sub_ = subscribeBounded<EnvSpec>(
      nh_, env_ns_ + "/spec", 1, [this](const EnvSpec::ConstPtr& m) { onSpec(m); }, refused);
  step_sub_ = subscribeBounded<EnvStep>(
      nh_, env_ns_ + "/env_step", kQueueSize, [this](const EnvStep::ConstPtr& m) { onEnvStep(m); },
      refused, ros::TransportHints().tcpNoDelay());
  // The connect callback only wakes waitFor() (it runs on queue_), whose predicate reads
  // getNumSubscribers().
  targets_pub_ = nh_.advertise<WheelTargets>(
      env_ns_ + "/wheel_targets", kQueueSize,
      ros::SubscriberStatusCallback([](const ros::SingleSubscriberPublisher&) {}));
  reset_client_ = nh_.serviceClient<Reset>(env_ns_ + "/reset", /*persistent=*/true);

  waitFor([this] { return has_spec_; }, timeout_,
          "latched spec on " + spec_sub_.getTopic() + " (is jetbot_env running?)" +
              (spec_error_.empty() ? "" : "; received an " + spec_error_));
  waitFor([this] { return targets_pub_.getNumSubscribers() > 0; }, timeout_,
          "the env to subscribe to " + targets_pub_.getTopic());
  if (!reset_client_.waitForExistence(ros::Duration(timeout_))) {
    throw Error("service " + reset_client_.getService() + " did not appear within " +
                seconds(timeout_));
  }
}

void RosVecEnv::onSpec(const EnvSpec::ConstPtr& msg) {
  if (has_spec_) return;
  try {
    spec_ = fromMsg(*msg);
    has_spec_ = true;
  } catch (const Error& e) {
    spec_error_ = e.what();
    ROS_ERROR("ignoring an EnvSpec on %s: %s", spec_sub_.getTopic().c_str(), e.what());
  }
}

void RosVecEnv::onEnvStep(const EnvStep::ConstPtr& msg) {
  connected_ = true;
  if (!accepting_ || msg->step <= step_) return;  // older than the current state
  if (msg->step > observed_) {
    observed_ = msg->step;
    if (observer_) observer_(*msg);
  }
  if (!newest_ || msg->step > newest_->step) newest_ = msg;
}

bool RosVecEnv::waitUntil(const std::function<bool()>& done, double timeout,
                          const std::string& what) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout);
  while (!done()) {
    if (stop_ && stop_->load()) throw Interrupted("stopped by a signal while waiting for " + what);
    if (!ros::ok()) throw Interrupted("ROS shut down while waiting for " + what);
    const double left =
        std::chrono::duration<double>(deadline - std::chrono::steady_clock::now()).count();
    if (left <= 0.0) return false;
    // Blocks until a callback is queued (or 0.1 s, to notice `stop`): no polling sleep.
    queue_.callAvailable(ros::WallDuration(std::min(left, 0.1)));
  }
  return true;
}

void RosVecEnv::waitFor(const std::function<bool()>& done, double timeout,
                        const std::string& what) {
  if (!waitUntil(done, timeout, what)) throw Error("no " + what + " within " + seconds(timeout));
}

void RosVecEnv::callReset(Reset& srv) {
  // roscpp's service call has no timeout: it runs in a thread of its own while this one waits as
  // for a step (step_timeout, stop flag); a hung env's connection is then dropped, which ends the
  // call.
  std::string reason;
  bool ok = false;
  std::atomic<bool> finished{false};
  std::thread caller([&] {
    ok = callBounded(reset_client_, srv, reason);
    finished = true;
    queue_.addCallback(boost::make_shared<WakeUp>());  // ends waitUntil's wait at once
  });
  const std::string what = "answer from " + reset_client_.getService();
  bool answered = false;
  try {
    answered = waitUntil([&] { return finished.load(); }, timeout_, what);
  } catch (...) {
    reset_client_.shutdown();
    caller.join();
    throw;
  }
  if (!answered) reset_client_.shutdown();
  caller.join();
  if (!answered) {
    throw Error("no " + what + " within " + seconds(timeout_) + " (env node " + env_ns_ +
                " hung?)");
  }
  if (!ok) throw Error(reason);
}

const StepResult& RosVecEnv::reset(std::int64_t seed,
                                   const std::vector<std::uint32_t>& episode_steps) {
  Reset srv;
  srv.request.seed = seed;  // env_ids empty: all envs
  srv.request.episode_steps = episode_steps;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_);
  for (;;) {
    accepting_ = false;
    callReset(srv);
    if (!srv.response.success) {
      throw Error(reset_client_.getService() + " refused: " + srv.response.message);
    }
    // The reset state is also published on ~env_step: receiving anything there proves that our
    // subscription is connected, so that no later step can be missed.
    const double left =
        std::chrono::duration<double>(deadline - std::chrono::steady_clock::now()).count();
    try {
      waitFor([this] { return connected_; }, std::max(0.0, std::min(1.0, left)),
              "EnvStep on " + step_sub_.getTopic() + " after a reset");
      break;
    } catch (const Interrupted&) {
      throw;
    } catch (const Error&) {
      if (left <= 1.0) throw;  // otherwise reset again: the first publication went unheard
    }
  }
  fromMsg(srv.response.state, spec_, result_);
  step_ = srv.response.state.step;
  observed_ = step_;
  newest_.reset();
  sent_ = false;
  accepting_ = true;
  return result_;
}

void RosVecEnv::stepAsync(const std::vector<float>& actions) {
  if (!accepting_) throw Error("RosVecEnv::stepAsync before reset");
  if (sent_) throw Error("RosVecEnv::stepAsync twice without stepWait");
  targets_ = boost::make_shared<WheelTargets>();
  targets_->header.stamp = ros::Time::now();
  targets_->step = step_;
  targets_->velocities = actions;
  targets_pub_.publish(WheelTargets::ConstPtr(targets_));
  sent_ = true;
}

const StepResult& RosVecEnv::stepWait() {
  if (!sent_) throw Error("RosVecEnv::stepWait without stepAsync");
  sent_ = false;
  const std::uint64_t expected = step_ + 1;
  if (lockstep_) {
    // The targets can be lost only while the env's subscription to a new publisher is being
    // connected (our subscriber count may come from another node, e.g. rostopic echo): resend
    // them when no answer came within kResendAfter. A duplicate that arrives after the env
    // stepped is rejected by it as stale, so no step is ever applied twice.
    const std::string what = "EnvStep " + std::to_string(expected) + " from " + env_ns_;
    const auto deadline =
        std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_);
    for (;;) {
      const double left =
          std::chrono::duration<double>(deadline - std::chrono::steady_clock::now()).count();
      if (waitUntil([this] { return newest_ != nullptr; }, std::min(left, kResendAfter), what)) {
        break;
      }
      if (left <= kResendAfter) {
        // A node that died leaves no publisher behind; a live one rejected the targets.
        throw Error("no " + what + " within " + seconds(timeout_) +
                    (step_sub_.getNumPublishers() == 0
                         ? ": the node no longer publishes " + step_sub_.getTopic() + " (dead?)"
                         : ": dead or unreachable (a killed node stays registered until it "
                           "is restarted), or it rejected the targets (see its /diagnostics)"));
      }
      ROS_WARN_THROTTLE(5.0,
                        "no EnvStep %llu after %.1f s: sending the targets for step %llu again",
                        static_cast<unsigned long long>(expected), kResendAfter,
                        static_cast<unsigned long long>(step_));
      targets_pub_.publish(WheelTargets::ConstPtr(targets_));
    }
    if (newest_->step != expected) {
      throw Error("expected EnvStep " + std::to_string(expected) + ", got " +
                  std::to_string(newest_->step) + ": is another node stepping " + env_ns_ + "?");
    }
  } else {
    waitFor([this] { return newest_ != nullptr; }, timeout_,
            "a newer EnvStep on " + step_sub_.getTopic());
  }
  fromMsg(*newest_, spec_, result_);
  step_ = newest_->step;
  newest_.reset();
  return result_;
}

}  // namespace jetbot_rl
