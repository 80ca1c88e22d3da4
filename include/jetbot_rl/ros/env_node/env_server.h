#pragma once

#include <geometry_msgs/Twist.h>

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
#include "jetbot_rl/env/batched_env.h"
#include "jetbot_rl/ros/env_node/cmd_vel_mixer.h"
#include "jetbot_rl/ros/env_node/node_params.h"

namespace jetbot_rl {

/// What the node counts and reports on /diagnostics.
struct EnvCounters {
  std::uint64_t steps = 0;       ///< Control steps applied since start-up.
  std::uint64_t rejections = 0;  ///< Rejected WheelTargets messages and ~step calls.
  std::string last_rejection;    ///< Reason of the last one.
  std::uint64_t diverged = 0;    ///< Envs reset because their physics diverged.
  std::string last_divergence;   ///< The core's reason for the last one.
  std::uint64_t malformed = 0;   ///< Messages and requests refused unread (lying lengths).
  std::string last_malformed;    ///< Reason of the last one.

  std::uint64_t cmd_vel_rejections = 0;  ///< Rejected cmd_vel (lockstep mode, non-finite).
  std::string last_cmd_vel_rejection;    ///< Reason of the last one.

  std::uint64_t obstacles_left_out = 0;  ///< Obstacles that did not fit (BatchedEnv).
  std::uint64_t layouts_unmade = 0;      ///< Generated layouts not made (BatchedEnv).
  std::uint64_t movers_left_out = 0;     ///< Movers that did not fit (BatchedEnv).

  // The node's publication pacing (PublicationPacer), filled by the node.
  std::uint64_t paced_states = 0;     ///< States that waited for roscpp's network thread.
  std::uint64_t pacing_timeouts = 0;  ///< Waits that timed out (older messages may be lost).
  std::uint32_t env_step_queue = 0;   ///< ~env_step's queue per connection [messages].
  /// Messages dropped from subscriber queues (CountedSubscriberQueues), and per topic
  /// ("topic: n, ...", topics with drops only).
  std::uint64_t undelivered = 0;
  std::string undelivered_by_topic;
};

/**
 * The env node's logic on message types, without ROS I/O (no node handle, no master): the
 * lockstep gate (a WheelTargets or ~step call steps only when its step is the current one),
 * realtime ticks with the freshest valid targets (braking when they are older than
 * `action_timeout`), cmd_vel of the robot envs (realtime: a fresh one drives its env over
 * WheelTargets), resets and commands, the rejection and divergence counters. Not thread-safe:
 * the node serialises the calls. After every change, state() is a new message.
 */
class EnvServer {
 public:
  using SteadyTime = std::chrono::steady_clock::time_point;

  /// Serves `env` (which it does not own); publishes nothing.
  EnvServer(BatchedEnv& env, EnvMode mode, double action_timeout);

  /// Lockstep: steps with `msg` when valid (true), else counts the rejection (false). Realtime:
  /// keeps the targets for the next tick, which validates them (false).
  bool onWheelTargets(const WheelTargets& msg, SteadyTime received);
  /// ~step: as onWheelTargets in lockstep mode, answered; refused in realtime mode. Returns true
  /// when it stepped. `res.state` is the state after the call.
  bool onStep(const Step::Request& req, Step::Response& res);
  /// ~reset: true when it reset; otherwise `res` says why and nothing changed.
  bool onReset(const Reset::Request& req, Reset::Response& res);
  /// ~set_command: changes the task's command (no new state).
  void onSetCommand(const SetCommand::Request& req, SetCommand::Response& res);
  /// Counts a message or request refused before it was read (its lengths exceed its bytes); it
  /// is a rejection too.
  void countMalformed(const std::string& reason);
  /// Realtime: one control step with the newest valid targets received at most `action_timeout`
  /// before `now`, else 0 rad/s (brakes); an env with a cmd_vel at most `cmd_vel_timeout` old
  /// follows that instead.
  void onTick(SteadyTime now);

  /// Takes cmd_vel for envs 0..envs-1 (clamped to the batch), converted with `drive`; a command
  /// drives its env for `timeout` [s, wall] after it was received.
  void enableCmdVel(const DiffDrive& drive, int envs, double timeout);
  /// A Twist on env `env`'s cmd_vel. Realtime: kept as that env's wheel targets for the next
  /// ticks (true). Lockstep (training steps with WheelTargets only), no cmd_vel enabled, or a
  /// NaN or infinite component: rejected and counted, the previous command stays (false).
  bool onCmdVel(int env, const geometry_msgs::Twist& msg, SteadyTime received);

  /// The current state as published on ~env_step (a new object after every change).
  const EnvStep::ConstPtr& state() const { return state_; }
  const EnvCounters& counters() const { return counters_; }
  const BatchedEnv& env() const { return env_; }
  EnvMode mode() const { return mode_; }

 private:
  /// Lockstep: applies `targets` when valid; otherwise returns false with the reason.
  bool tryLockstep(const WheelTargets& targets, std::string& reason);
  /// Steps the env with `count` targets [rad/s]; throws InputError and changes nothing if invalid.
  void stepWith(const float* targets, std::size_t count);
  /// stepWith() `targets` with the fresh cmd_vel commands written over their envs' targets.
  void stepMixed(const std::vector<float>& targets, SteadyTime now);
  void rejectCmdVel(const std::string& reason);
  void reject(const std::string& reason);
  void updateState();

  BatchedEnv& env_;
  const BatchSpec spec_;  // what each EnvStep carries (its image kinds)
  EnvMode mode_;
  std::chrono::duration<double> action_timeout_;
  EnvCounters counters_;
  EnvStep::ConstPtr state_;

  // Realtime mode: the latest valid targets, and a newer message not yet validated by a tick.
  std::vector<float> current_targets_, pending_targets_, zero_targets_;
  SteadyTime current_time_, pending_time_;
  bool has_current_ = false, has_pending_ = false;

  std::unique_ptr<CmdVelMixer> cmd_vel_;  // null: no robot envs
  std::vector<float> mixed_targets_;      // WheelTargets with the cmd_vel envs written over
};

}  // namespace jetbot_rl
