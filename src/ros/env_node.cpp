#include "jetbot_rl/ros/env_node.h"

#include <ros/console.h>
#include <ros/transport_hints.h>

#include <algorithm>
#include <optional>

#include "jetbot_rl/command_task.h"
#include "jetbot_rl/errors.h"
#include "jetbot_rl/ros/bounded_service.h"
#include "jetbot_rl/ros/bounded_subscription.h"
#include "jetbot_rl/ros/msg_conversion.h"
#include "jetbot_rl/task_factory.h"

namespace jetbot_rl {
namespace {

// Small bounded queues: a lockstep learner has one message in flight, and a slow subscriber
// only loses old messages.
constexpr std::uint32_t kQueueSize = 16;

std::unique_ptr<BatchedEnv> makeEnv(const NodeParams& params, RobotModelConstPtr robot) {
  return std::make_unique<BatchedEnv>(std::move(robot), params.env,
                                      makeTask(params.task, params.reward));
}

}  // namespace

EnvNode::EnvNode(ros::NodeHandle nh, ros::NodeHandle pnh, const NodeParams& params,
                 RobotModelConstPtr robot)
    : params_(params),
      env_(makeEnv(params, std::move(robot))),
      nh_(nh),
      pnh_(pnh),
      clock_(nh_, env_->controlDt(), params.publish_clock),
      tf_(params.tf_envs, params.tf_rate),
      markers_(pnh_, *env_, params.tf_envs, params.markers),
      diagnostics_(nh_, pnh_.getNamespace().substr(1) + ": environment", modeName(params.mode),
                   env_->numEnvs()) {
  const std::size_t action_count = static_cast<std::size_t>(env_->numEnvs()) * env_->actionDim();
  zero_targets_.assign(action_count, 0.0f);
  current_targets_.reserve(action_count);
  pending_targets_.reserve(action_count);

  spec_pub_ = pnh_.advertise<EnvSpec>("spec", 1, /*latch=*/true);
  env_step_pub_ = pnh_.advertise<EnvStep>("env_step", kQueueSize);
  spec_pub_.publish(makeEnvSpec(*env_));
  publishState(/*force_tf=*/true);  // initial /clock, EnvStep and tf batch

  // Callbacks may arrive from here on; they wait until the node is complete.
  std::lock_guard<std::mutex> lock(inline_queue_.mutex());
  ros::NodeHandle inline_pnh(pnh_);
  inline_pnh.setCallbackQueue(&inline_queue_);
  // Anyone can send bytes: a message or request whose array or string lengths exceed its bytes
  // is refused before roscpp allocates for it, and counted.
  const auto refused = [this](const std::string& what) -> RefusalHandler {
    return [this, what](const std::string& reason) {
      diagnostics_.countMalformed(what + " refused unread: " + reason);
      ROS_WARN_THROTTLE(1.0, "%s refused unread: %s (%llu malformed so far)", what.c_str(),
                        reason.c_str(), static_cast<unsigned long long>(diagnostics_.malformed()));
    };
  };
  targets_sub_ = subscribeBounded<WheelTargets>(
      inline_pnh, "wheel_targets", kQueueSize,
      [this](const WheelTargets::ConstPtr& msg) { onWheelTargets(msg); }, refused("wheel_targets"),
      ros::TransportHints().tcpNoDelay());
  step_srv_ = advertiseServiceBounded<Step>(
      inline_pnh, "step", [this](Step::Request& q, Step::Response& r) { return onStep(q, r); },
      refused("step"));
  reset_srv_ = advertiseServiceBounded<Reset>(
      inline_pnh, "reset", [this](Reset::Request& q, Reset::Response& r) { return onReset(q, r); },
      refused("reset"));
  set_command_srv_ = advertiseServiceBounded<SetCommand>(
      inline_pnh, "set_command",
      [this](SetCommand::Request& q, SetCommand::Response& r) { return onSetCommand(q, r); },
      refused("set_command"));
  if (params_.mode == EnvMode::kRealtime) {
    const double period = env_->controlDt() / params_.real_time_factor;
    realtime_timer_ =
        nh_.createWallTimer(ros::WallDuration(period), &EnvNode::onRealtimeTimer, this);
  }
  diagnostics_.publish();
  diagnostics_timer_ =
      nh_.createWallTimer(ros::WallDuration(1.0), &EnvNode::onDiagnosticsTimer, this);
  ROS_INFO(
      "jetbot_env ready: %d envs, obs_dim %d, action_dim %d, control step %.6f s, %d threads, "
      "%s mode",
      env_->numEnvs(), env_->obsDim(), env_->actionDim(), env_->controlDt(), env_->numThreads(),
      modeName(params_.mode).c_str());
}

void EnvNode::onWheelTargets(const WheelTargets::ConstPtr& msg) {
  if (params_.mode == EnvMode::kRealtime) {
    // Validated by the core when the next tick steps with it (see onRealtimeTimer).
    pending_targets_.assign(msg->velocities.begin(), msg->velocities.end());
    pending_time_ = std::chrono::steady_clock::now();
    has_pending_ = true;
    return;
  }
  std::string reason;
  if (!tryLockstep(*msg, reason)) reject("wheel_targets rejected: " + reason);
}

bool EnvNode::onStep(Step::Request& req, Step::Response& res) {
  if (params_.mode == EnvMode::kRealtime) {
    res.success = false;
    res.message = "~step is only served in lockstep mode; publish on ~wheel_targets instead";
  } else {
    std::string reason;
    res.success = tryLockstep(req.actions, reason);
    if (!res.success) {
      reject("step rejected: " + reason);
      res.message = reason;
    }
  }
  res.state = env_step_msg_;
  return true;
}

bool EnvNode::onReset(Reset::Request& req, Reset::Response& res) {
  std::optional<std::uint64_t> seed;
  if (req.seed >= 0) seed = static_cast<std::uint64_t>(req.seed);
  try {
    env_->reset(req.env_ids, seed);
  } catch (const InputError& e) {
    ROS_WARN_THROTTLE(1.0, "reset rejected: %s", e.what());
    res.success = false;
    res.message = e.what();
    res.state = env_step_msg_;
    return true;
  }
  publishState(/*force_tf=*/true);
  res.success = true;
  res.message = "reset " +
                (req.env_ids.empty() ? std::string("all") : std::to_string(req.env_ids.size())) +
                " envs" + (seed ? " with seed " + std::to_string(*seed) : std::string());
  res.state = env_step_msg_;
  return true;
}

bool EnvNode::onSetCommand(SetCommand::Request& req, SetCommand::Response& res) {
  auto* task = dynamic_cast<CommandTask*>(&env_->task());
  if (!task) {
    res.success = false;
    res.message = "task '" + env_->task().name() + "' has no command: launch with task:=command";
    return true;
  }
  try {
    task->setCommand(static_cast<int>(req.env_id), Eigen::Vector2d(req.x, req.y), req.hold);
  } catch (const InputError& e) {
    res.success = false;
    res.message = e.what();
    return true;
  }
  res.success = true;
  res.message = "command of env " + std::to_string(req.env_id) + " set" +
                (req.hold ? ", held across resets" : "") + "; observed from the next step";
  return true;
}

void EnvNode::onRealtimeTimer(const ros::WallTimerEvent&) {
  std::lock_guard<std::mutex> lock(inline_queue_.mutex());
  const auto now = std::chrono::steady_clock::now();
  const auto timeout = std::chrono::duration<double>(params_.action_timeout);
  if (has_pending_) {
    has_pending_ = false;
    // A message older than the time-out would only brake: it is dropped unapplied.
    if (now - pending_time_ <= timeout) {
      try {
        stepWith(pending_targets_.data(), pending_targets_.size());
        current_targets_.swap(pending_targets_);
        current_time_ = pending_time_;
        has_current_ = true;
        return;
      } catch (const InputError& e) {
        reject(std::string("wheel_targets rejected: ") + e.what());
      }
    }
  }
  if (has_current_ && now - current_time_ <= timeout) {
    stepWith(current_targets_.data(), current_targets_.size());
  } else {
    stepWith(zero_targets_.data(), zero_targets_.size());  // no fresh targets: brake
  }
}

void EnvNode::onDiagnosticsTimer(const ros::WallTimerEvent&) {
  std::lock_guard<std::mutex> lock(inline_queue_.mutex());
  diagnostics_.publish();
}

bool EnvNode::tryLockstep(const WheelTargets& targets, std::string& reason) {
  if (targets.step != step_) {
    reason = std::string(targets.step < step_ ? "stale" : "future") + " step " +
             std::to_string(targets.step) + ": the current step is " + std::to_string(step_);
    return false;
  }
  try {
    stepWith(targets.velocities.data(), targets.velocities.size());
  } catch (const InputError& e) {
    reason = e.what();
    return false;
  }
  return true;
}

void EnvNode::stepWith(const float* targets, std::size_t count) {
  const StepResult& result = env_->step(targets, count);  // throws before changing anything
  ++step_;
  diagnostics_.countStep(step_);
  if (!result.divergences.empty()) {
    diagnostics_.noteDivergences(result.divergences, env_->divergedCount());
    ROS_WARN_THROTTLE(1.0, "step %llu: %zu env(s) diverged and were reset; last: %s",
                      static_cast<unsigned long long>(step_), result.divergences.size(),
                      result.divergences.back().reason.c_str());
  }
  publishState(/*force_tf=*/false);
}

void EnvNode::publishState(bool force_tf) {
  const ros::Time stamp = clock_.timeAt(step_);
  clock_.publish(step_);
  fillEnvStep(env_->state(), env_->numEnvs(), env_->obsDim(), step_, stamp, env_step_msg_);
  env_step_pub_.publish(env_step_msg_);
  if (tf_.update(*env_, stamp, force_tf)) markers_.publish(*env_, stamp);
}

void EnvNode::reject(const std::string& reason) {
  diagnostics_.countRejection(reason);
  ROS_WARN_THROTTLE(1.0, "%s (%llu rejected so far)", reason.c_str(),
                    static_cast<unsigned long long>(diagnostics_.rejections()));
}

int runEnvNode() {
  ros::NodeHandle nh;
  ros::NodeHandle pnh("~");
  NodeParams params;
  try {
    params = loadNodeParams(pnh);
  } catch (const Error& e) {
    ROS_FATAL("%s: parameter error: %s", pnh.getNamespace().c_str(), e.what());
    return 1;
  }
  ROS_INFO_STREAM("parameters of " << pnh.getNamespace() << ":\n" << describeNodeParams(params));

  const std::string description_param = nh.resolveName("robot_description");
  std::string urdf;
  if (!nh.getParam("robot_description", urdf)) {
    ROS_FATAL("%s: parameter %s is not set or not a string: load the robot's URDF into it",
              pnh.getNamespace().c_str(), description_param.c_str());
    return 1;
  }
  RobotModelConstPtr robot;
  try {
    robot = RobotModel::fromUrdfString(urdf);
  } catch (const Error& e) {
    ROS_FATAL("%s: cannot use %s: %s", pnh.getNamespace().c_str(), description_param.c_str(),
              e.what());
    return 1;
  }

  std::unique_ptr<EnvNode> node;
  try {
    node = std::make_unique<EnvNode>(nh, pnh, params, robot);
  } catch (const ModelError& e) {
    ROS_FATAL("%s: %s does not fit the parameters: %s", pnh.getNamespace().c_str(),
              description_param.c_str(), e.what());
    return 1;
  } catch (const Error& e) {
    ROS_FATAL("%s: %s", pnh.getNamespace().c_str(), e.what());
    return 1;
  }
  ros::spin();  // timers; topics and services run in roscpp's network thread (inline_queue_)
  return 0;
}

}  // namespace jetbot_rl
