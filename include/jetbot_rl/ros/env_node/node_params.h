#pragma once

#include <ros/node_handle.h>

#include <algorithm>
#include <string>

#include "jetbot_rl/config/config_fields.h"
#include "jetbot_rl/env/env_setup.h"
#include "jetbot_rl/ros/common/env_mode.h"

namespace jetbot_rl {

/// Every private parameter of jetbot_env_node; defaults match config/jetbot_env.yaml (a test
/// checks it).
struct NodeParams {
  EnvSetup setup;  ///< The envs: num_envs, physics, ..., task, reward_variant.
  EnvMode mode = EnvMode::kLockstep;
  double real_time_factor = 1.0;  ///< Realtime mode: simulated seconds per wall second.
  double action_timeout = 0.5;    ///< Realtime mode: targets older than this brake [s, wall].
  bool publish_clock = true;      ///< Publish simulation time on /clock.
  int tf_envs = 4;                ///< Envs that get tf frames (clamped to num_envs).
  double tf_rate = 30.0;          ///< Largest tf (and marker) rate [Hz of simulation time].
  bool markers = true;            ///< Publish ~markers for the envs with tf.
  /// Envs 0..robot_view_envs-1 get the robot view: cmd_vel in, odom and joint_states out, and tf
  /// (clamped to num_envs).
  int robot_view_envs = 1;
  /// false: env 0's robot view topics and tf frames have no "env_0/" prefix (one robot env only).
  bool env_prefix = true;
  double cmd_vel_timeout = 0.5;  ///< Realtime mode: an older cmd_vel no longer drives [s, wall].
  double odom_rate = 50.0;       ///< Largest odom and joint_states rate [Hz of simulation time].
  /// tf of the links below the root link; false leaves them to robot_state_publisher.
  bool publish_link_tf = true;
  /// Before the robot view's topics and frames (e.g. "jetbot_env_1/"): several env nodes' robots
  /// in one graph keep apart.
  std::string robot_prefix;
  double diagnostic_period = 1.0;  ///< Between /diagnostics status messages [s, wall].
};

/// Rows with the robot view: robot_view_envs clamped to the rows (num_envs x robots_per_env).
inline int robotViewEnvs(const NodeParams& p) {
  return std::min(p.robot_view_envs, p.setup.env.numRows());
}
/// Rows with tf frames: the tf_envs and the robot envs, clamped to the rows.
inline int tfEnvs(const NodeParams& p) {
  return std::min(std::max(p.tf_envs, p.robot_view_envs), p.setup.env.numRows());
}

template <typename C, typename V>
IfConfig<C, NodeParams> visitFields(C& c, V&& v) {
  visitFields(c.setup, v);
  v("mode", c.mode, AnyValue{},
    "lockstep: one control step per accepted WheelTargets or ~step call (training); realtime: "
    "steps on a wall-clock timer with the latest targets (driving by hand).");
  v("real_time_factor", c.real_time_factor, positiveUpTo(1000.0),
    "Realtime mode: simulated seconds per wall second.");
  v("action_timeout", c.action_timeout, positive("s, wall"),
    "Realtime mode: targets older than this brake to 0.");
  v("publish_clock", c.publish_clock, AnyValue{},
    "Publish simulation time (step x control step) on /clock.");
  v("tf_envs", c.tf_envs, atLeast(0, "", "0: no tf"),
    "Envs with tf frames world -> env_<i>/odom -> env_<i>/<links> (and the robot envs).");
  v("tf_rate", c.tf_rate, positive("Hz of simulation time"),
    "Largest tf and marker publishing rate.");
  v("markers", c.markers, AnyValue{},
    "Publish ~markers (body box, forward and command arrows) for the tf_envs envs.");
  v("robot_view_envs", c.robot_view_envs, atLeast(0, "", "0: no robot view"),
    "Envs 0..robot_view_envs-1 with the robot view: env_<i>/cmd_vel in, odom, joint_states and tf "
    "out (clamped to num_envs); with robots_per_env K, rows (robots) 0..robot_view_envs-1 under "
    "env_<i / K>/robot_<i % K>/.");
  v("env_prefix", c.env_prefix, AnyValue{},
    "false: env 0's robot view without the env_0/ prefix (cmd_vel, odom, frame odom, ...); "
    "robot_view_envs 1 only.");
  v("cmd_vel_timeout", c.cmd_vel_timeout, positive("s, wall"),
    "Realtime mode: a cmd_vel older than this no longer drives its env.");
  v("odom_rate", c.odom_rate, positive("Hz of simulation time"),
    "Largest odom and joint_states rate.");
  v("publish_link_tf", c.publish_link_tf, AnyValue{},
    "tf of the links below the root link; false leaves them to robot_state_publisher.");
  v("robot_prefix", c.robot_prefix, AnyValue{"", "empty: none"},
    "Before the robot view's topics and tf frames (e.g. jetbot_env_1/ gives "
    "jetbot_env_1/env_0/cmd_vel and frame jetbot_env_1/env_0/odom): several env nodes in one "
    "graph keep their robots apart (env_nodes.launch sets it to each node's name).");
  v("diagnostic_period", c.diagnostic_period, inRange(0.01, 60.0, "s, wall"),
    "Between the node's /diagnostics status messages (its counters), as diagnostic_updater's "
    "~diagnostic_period.");
}

/// The rules between fields (EnvConfig's, and env_prefix against robot_view_envs).
void checkFieldRules(const NodeParams& params);

}  // namespace jetbot_rl
