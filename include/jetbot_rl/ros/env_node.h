#pragma once

#include <ros/node_handle.h>
#include <ros/publisher.h>
#include <ros/service_server.h>
#include <ros/subscriber.h>
#include <ros/wall_timer.h>

#include <chrono>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "jetbot_rl/EnvStep.h"
#include "jetbot_rl/Reset.h"
#include "jetbot_rl/SetCommand.h"
#include "jetbot_rl/Step.h"
#include "jetbot_rl/WheelTargets.h"
#include "jetbot_rl/batched_env.h"
#include "jetbot_rl/ros/env_diagnostics.h"
#include "jetbot_rl/ros/inline_callback_queue.h"
#include "jetbot_rl/ros/marker_publisher.h"
#include "jetbot_rl/ros/node_params.h"
#include "jetbot_rl/ros/sim_clock.h"
#include "jetbot_rl/ros/tf_publisher.h"

namespace jetbot_rl {

/**
 * The jetbot_env node: a BatchedEnv on topics and services.
 *
 * Topic and service callbacks run at once in roscpp's network thread (InlineCallbackQueue: a
 * lockstep round trip wakes no spinner), timers on the spinner; all hold the queue's mutex, so
 * steps, resets and timers never overlap. In lockstep mode each accepted WheelTargets (or ~step
 * call) whose step equals the current step advances exactly one control step; in realtime mode a
 * wall timer steps with the latest targets.
 */
class EnvNode {
 public:
  /// Builds the environment (ConfigError / ModelError) and advertises everything under `pnh`.
  EnvNode(ros::NodeHandle nh, ros::NodeHandle pnh, const NodeParams& params,
          RobotModelConstPtr robot);

  /// EnvStep.step of the current state.
  std::uint64_t step() const { return step_; }
  const BatchedEnv& env() const { return *env_; }

 private:
  void onWheelTargets(const WheelTargets::ConstPtr& msg);
  bool onStep(Step::Request& req, Step::Response& res);
  bool onReset(Reset::Request& req, Reset::Response& res);
  bool onSetCommand(SetCommand::Request& req, SetCommand::Response& res);
  void onRealtimeTimer(const ros::WallTimerEvent& event);
  void onDiagnosticsTimer(const ros::WallTimerEvent& event);

  /// Lockstep: applies `targets` when valid; otherwise returns false with the reason.
  bool tryLockstep(const WheelTargets& targets, std::string& reason);
  /// Steps the env with `count` targets [rad/s]; throws InputError and changes nothing if invalid.
  void stepWith(const float* targets, std::size_t count);
  /// Publishes the current state (EnvStep, /clock, tf when due or `force_tf`).
  void publishState(bool force_tf);
  void reject(const std::string& reason);

  NodeParams params_;
  std::unique_ptr<BatchedEnv> env_;
  std::uint64_t step_ = 0;
  EnvStep env_step_msg_;

  ros::NodeHandle nh_, pnh_;
  InlineCallbackQueue inline_queue_;  // topics and services; timers hold its mutex
  ros::Publisher env_step_pub_, spec_pub_;
  ros::Subscriber targets_sub_;
  ros::ServiceServer step_srv_, reset_srv_, set_command_srv_;
  ros::WallTimer realtime_timer_, diagnostics_timer_;
  SimClock clock_;
  EnvTfPublisher tf_;
  EnvMarkerPublisher markers_;
  EnvDiagnostics diagnostics_;

  // Realtime mode: the latest valid targets, and a newer message not yet validated by a step.
  using SteadyTime = std::chrono::steady_clock::time_point;
  std::vector<float> current_targets_, pending_targets_, zero_targets_;
  SteadyTime current_time_, pending_time_;
  bool has_current_ = false, has_pending_ = false;
};

/// Runs jetbot_env_node after ros::init(): loads and echoes the parameters and the robot, then
/// spins. Returns the process exit code; a bad parameter or robot is ROS_FATAL and returns 1.
int runEnvNode();

}  // namespace jetbot_rl
