#include "jetbot_rl/ppo/ros/ros_vec_env.h"

#include <ros/console.h>
#include <ros/transport_hints.h>

#include <algorithm>
#include <chrono>

#include "jetbot_rl/Reset.h"
#include "jetbot_rl/ros/bounded_service.h"
#include "jetbot_rl/ros/bounded_subscription.h"

namespace jetbot_rl {
namespace ppo {
namespace {

// The lockstep learner has one message in flight; realtime players drop old states only.
constexpr std::uint32_t kQueueSize = 8;
// Lockstep: resend targets that got no answer within this [s, wall] (see step()).
constexpr double kResendAfter = 0.5;

std::string seconds(double s) {
  char buf[32];
  std::snprintf(buf, sizeof(buf), "%.1f s", s);
  return buf;
}

}  // namespace

RosVecEnv::RosVecEnv(const std::string& env_ns, bool lockstep, double timeout,
                     const std::atomic<bool>* stop)
    : env_ns_(env_ns), lockstep_(lockstep), timeout_(timeout), stop_(stop) {
  nh_.setCallbackQueue(&queue_);
  // Anyone can publish on these topics: a message whose lengths exceed its bytes is dropped
  // unread (roscpp would allocate what it claims), counted and logged.
  const auto refused = [this](const std::string& reason) {
    ++refused_;
    ROS_WARN_THROTTLE(5.0, "%s: refused unread: %s (%llu so far)", env_ns_.c_str(), reason.c_str(),
                      static_cast<unsigned long long>(refused_));
  };
  spec_sub_ = subscribeBounded<EnvSpec>(
      nh_, env_ns_ + "/spec", 1, [this](const EnvSpec::ConstPtr& m) { onSpec(m); }, refused);
  step_sub_ = subscribeBounded<EnvStep>(
      nh_, env_ns_ + "/env_step", kQueueSize, [this](const EnvStep::ConstPtr& m) { onEnvStep(m); },
      refused, ros::TransportHints().tcpNoDelay());
  targets_pub_ = nh_.advertise<WheelTargets>(
      env_ns_ + "/wheel_targets", kQueueSize,
      [this](const ros::SingleSubscriberPublisher& p) { onTargetsSubscriber(p); });
  reset_client_ = nh_.serviceClient<Reset>(env_ns_ + "/reset", /*persistent=*/true);

  waitFor([this] { return has_spec_; }, timeout_,
          "latched spec on " + spec_sub_.getTopic() + " (is jetbot_env running?)");
  waitFor([this] { return targets_pub_.getNumSubscribers() > 0; }, timeout_,
          "the env to subscribe to " + targets_pub_.getTopic());
  if (!reset_client_.waitForExistence(ros::Duration(timeout_))) {
    throw Error("service " + reset_client_.getService() + " did not appear within " +
                seconds(timeout_));
  }
}

void RosVecEnv::onSpec(const EnvSpec::ConstPtr& msg) {
  if (has_spec_) return;
  if (msg->num_envs < 1 || msg->obs_dim < 1 || msg->action_dim < 1 ||
      msg->action_low.size() != msg->action_dim || msg->action_high.size() != msg->action_dim) {
    ROS_ERROR("ignoring an inconsistent EnvSpec on %s", spec_sub_.getTopic().c_str());
    return;
  }
  spec_ = *msg;
  info_.num_envs = static_cast<int>(msg->num_envs);
  info_.obs_dim = static_cast<int>(msg->obs_dim);
  info_.action_dim = static_cast<int>(msg->action_dim);
  info_.action_low = msg->action_low;
  info_.action_high = msg->action_high;
  info_.control_dt = msg->control_dt;
  info_.max_episode_length = static_cast<int>(msg->max_episode_length);
  info_.task = msg->task;
  info_.observation_names = msg->observation_names;
  has_spec_ = true;
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

void RosVecEnv::onTargetsSubscriber(const ros::SingleSubscriberPublisher&) {
  // Only wakes waitFor(): the predicate reads getNumSubscribers().
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

const EnvBatch& RosVecEnv::reset(std::int64_t seed) {
  Reset srv;
  srv.request.seed = seed;  // env_ids empty: all envs
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_);
  for (;;) {
    accepting_ = false;
    std::string reason;
    if (!callBounded(reset_client_, srv, reason)) throw Error(reason);
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
  toBatch(srv.response.state);
  step_ = srv.response.state.step;
  observed_ = step_;
  newest_.reset();
  accepting_ = true;
  return batch_;
}

const EnvBatch& RosVecEnv::step(const std::vector<float>& actions) {
  if (!accepting_) throw Error("RosVecEnv::step before reset");
  targets_.header.stamp = ros::Time::now();
  targets_.step = step_;
  targets_.velocities = actions;
  targets_pub_.publish(targets_);
  const std::uint64_t expected = step_ + 1;
  if (lockstep_) {
    // The targets can be lost only while the env's subscription to a new publisher is being
    // connected (our subscriber count may come from another node, e.g. rostopic echo): resend
    // them when no answer came within kResendAfter. A duplicate that arrives after the env
    // stepped is rejected by it as stale, so no step is ever applied twice.
    const std::string what = "EnvStep " + std::to_string(expected) + " on " + step_sub_.getTopic() +
                             " (a rejected WheelTargets? see /diagnostics)";
    const auto deadline =
        std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_);
    for (;;) {
      const double left =
          std::chrono::duration<double>(deadline - std::chrono::steady_clock::now()).count();
      if (waitUntil([this] { return newest_ != nullptr; }, std::min(left, kResendAfter), what)) {
        break;
      }
      if (left <= kResendAfter) throw Error("no " + what + " within " + seconds(timeout_));
      ROS_WARN_THROTTLE(5.0,
                        "no EnvStep %llu after %.1f s: sending the targets for step %llu again",
                        static_cast<unsigned long long>(expected), kResendAfter,
                        static_cast<unsigned long long>(step_));
      targets_pub_.publish(targets_);
    }
    if (newest_->step != expected) {
      throw Error("expected EnvStep " + std::to_string(expected) + ", got " +
                  std::to_string(newest_->step) + ": is another node stepping " + env_ns_ + "?");
    }
  } else {
    waitFor([this] { return newest_ != nullptr; }, timeout_,
            "a newer EnvStep on " + step_sub_.getTopic());
  }
  toBatch(*newest_);
  step_ = newest_->step;
  newest_.reset();
  return batch_;
}

const EnvBatch& RosVecEnv::resetEnvs(const std::vector<std::uint32_t>& ids) {
  if (!accepting_) throw Error("RosVecEnv::resetEnvs before reset");
  Reset srv;
  srv.request.env_ids = ids;
  srv.request.seed = -1;
  std::string reason;
  if (!callBounded(reset_client_, srv, reason)) throw Error(reason);
  if (!srv.response.success) {
    throw Error(reset_client_.getService() + " refused: " + srv.response.message);
  }
  if (srv.response.state.step != step_) {
    throw Error("~reset answered with step " + std::to_string(srv.response.state.step) +
                " instead of " + std::to_string(step_) + ": is another node stepping " + env_ns_ +
                "?");
  }
  // Keep this step's rewards and episode ends; take the new observations.
  batch_.observations = srv.response.state.observations;
  return batch_;
}

void RosVecEnv::toBatch(const EnvStep& msg) {
  const std::size_t n = static_cast<std::size_t>(info_.num_envs);
  const std::size_t obs_dim = static_cast<std::size_t>(info_.obs_dim);
  if (msg.num_envs != n || msg.obs_dim != obs_dim || msg.observations.size() != n * obs_dim ||
      msg.rewards.size() != n || msg.terminated.size() != n || msg.truncated.size() != n ||
      msg.final_observations.size() != msg.reset_env_ids.size() * obs_dim) {
    throw Error("EnvStep " + std::to_string(msg.step) + " does not match the spec (" +
                std::to_string(n) + " envs, obs_dim " + std::to_string(obs_dim) + ")");
  }
  batch_.step = msg.step;
  batch_.observations = msg.observations;
  batch_.rewards = msg.rewards;
  batch_.terminated = msg.terminated;
  batch_.truncated = msg.truncated;
  batch_.reset_env_ids = msg.reset_env_ids;
  batch_.final_observations = msg.final_observations;
}

}  // namespace ppo
}  // namespace jetbot_rl
