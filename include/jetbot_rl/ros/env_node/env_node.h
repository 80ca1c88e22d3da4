#pragma once

#include <geometry_msgs/Twist.h>
#include <ros/node_handle.h>
#include <ros/publisher.h>
#include <ros/service_server.h>
#include <ros/subscriber.h>
#include <ros/wall_timer.h>

#include <memory>
#include <mutex>
#include <optional>
#include <vector>

#include "jetbot_rl/env/batched_env.h"
#include "jetbot_rl/robot/diff_drive.h"
#include "jetbot_rl/ros/common/counted_subscriber_queues.h"
#include "jetbot_rl/ros/common/inline_callback_queue.h"
#include "jetbot_rl/ros/common/publication_pacer.h"
#include "jetbot_rl/ros/env_node/env_diagnostics.h"
#include "jetbot_rl/ros/env_node/env_server.h"
#include "jetbot_rl/ros/env_node/map_publisher.h"
#include "jetbot_rl/ros/env_node/node_params.h"
#include "jetbot_rl/ros/env_node/state_output.h"
#include "jetbot_rl/ros/env_node/world_geometry_publisher.h"

namespace jetbot_rl {

/**
 * The jetbot_env node: an EnvServer (the lockstep/realtime logic) on topics and services, and
 * the robot view of the first robot_view_envs envs (cmd_vel, odom, joint_states, tf).
 *
 * Topic and service callbacks run at once in roscpp's network thread (InlineCallbackQueue: a
 * lockstep round trip wakes no spinner), timers on the spinner. A call changes the state under
 * the state lock; the outputs (StateOutput: EnvStep, /clock, tf, markers) capture the new state
 * under it and publish after it is released, in order (the publish lock is taken before the
 * state lock is released).
 */
class EnvNode {
 public:
  /// Serves `env` (built by the caller from the same params) under `pnh`; `drive`: the robot's
  /// cmd_vel kinematics, needed when params.robot_view_envs > 0 (else ConfigError).
  EnvNode(ros::NodeHandle nh, ros::NodeHandle pnh, const NodeParams& params,
          std::unique_ptr<BatchedEnv> env, std::optional<DiffDrive> drive = std::nullopt);

  /// EnvStep.step of the current state.
  std::uint64_t step() const;
  /// Ends serving: stops the timers, topics and services, publishes what the outputs send at the
  /// end (DELETEALL markers) and waits up to `flush_timeout` [s, wall] until it is written to the
  /// subscribers. Call before ros::shutdown(); the node publishes nothing afterwards.
  void shutdown(double flush_timeout);
  const BatchedEnv& env() const { return *env_; }

 private:
  void onWheelTargets(const WheelTargets::ConstPtr& msg);
  void onCmdVel(int env, const geometry_msgs::Twist::ConstPtr& msg);
  bool onStep(Step::Request& req, Step::Response& res);
  bool onReset(Reset::Request& req, Reset::Response& res);
  bool onSetCommand(SetCommand::Request& req, SetCommand::Response& res);
  void onRealtimeTimer(const ros::WallTimerEvent& event);
  void onDiagnosticsTimer(const ros::WallTimerEvent& event);
  /// Captures the new state in every output, releases `state_lock`, then publishes.
  void publish(std::unique_lock<std::mutex>& state_lock, bool reset);
  /// The server's counters with the publication pacer's and the undelivered messages; under the
  /// state lock.
  EnvCounters counters() const;

  NodeParams params_;
  std::unique_ptr<BatchedEnv> env_;
  EnvServer server_;
  mutable std::mutex state_mutex_;  // env_, server_ and finished_
  bool finished_ = false;           // shutdown(): nothing more is published
  std::mutex publish_mutex_;        // outputs_: keeps states in order

  ros::NodeHandle nh_, pnh_;
  InlineCallbackQueue inline_queue_;  // topics and services, in the network thread
  ros::Publisher spec_pub_;
  CountedSubscriberQueues queues_;  // the outputs' subscriber queues, under publish_mutex_
  std::vector<std::unique_ptr<StateOutput>> outputs_;
  ros::Subscriber targets_sub_;
  std::vector<ros::Subscriber> cmd_vel_subs_;  // per robot env
  ros::ServiceServer step_srv_, reset_srv_, set_command_srv_;
  ros::ServiceServer get_randomization_srv_;  // domain randomisation (randomization_service.h)
  ros::WallTimer realtime_timer_, diagnostics_timer_;
  std::unique_ptr<MapPublisher> map_publisher_;                 // /map, when the world has a map
  std::unique_ptr<WorldGeometryPublisher> geometry_publisher_;  // a Gazebo world's shapes
  EnvDiagnostics diagnostics_;
  PublicationPacer pacer_;            // before outputs_' send(), under publish_mutex_
  std::uint32_t env_step_queue_ = 0;  // ~env_step's queue per connection [messages]
};

/// Loads and echoes the parameters under `pnh` and the robot (robot_description, resolved in
/// `nh`'s namespace), builds the env and serves it (the node's and the nodelet's start-up).
/// Returns nullptr after a ROS_FATAL naming the bad parameter or robot.
std::unique_ptr<EnvNode> makeEnvNode(ros::NodeHandle nh, ros::NodeHandle pnh);

/// Runs jetbot_env_node after ros::init() (with ros::init_options::NoSigintHandler): loads and
/// echoes the parameters and the robot, builds the env, then spins until SIGINT or SIGTERM (or
/// ROS shuts down), sends the last markers and shuts ROS down. Returns the process exit code: 0,
/// or 1 after ROS_FATAL for a bad parameter or robot.
int runEnvNode();

}  // namespace jetbot_rl
