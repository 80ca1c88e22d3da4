#pragma once

#include <ros/node_handle.h>

#include <string>

#include "jetbot_rl/env_config.h"
#include "jetbot_rl/task_factory.h"  // makeTask(): the valid `task` names

namespace jetbot_rl {

/// How the node advances the simulation.
enum class EnvMode {
  kLockstep,  ///< One control step per accepted WheelTargets or ~step call (training).
  kRealtime,  ///< Steps on a wall-clock timer with the latest targets (driving by hand).
};

/// Every private parameter of jetbot_env_node; defaults match config/jetbot_env.yaml.
struct NodeParams {
  EnvConfig env;                  ///< num_envs, env_spacing, physics_dt, ..., solver_iterations.
  std::string task = "velocity";  ///< Task name (`velocity` or `command`).
  std::string reward = "exp";     ///< Command task's reward variant (`exp`, `sum`, `product`).
  EnvMode mode = EnvMode::kLockstep;
  double real_time_factor = 1.0;  ///< Realtime mode: simulated seconds per wall second.
  double action_timeout = 0.5;    ///< Realtime mode: targets older than this brake [s, wall].
  bool publish_clock = true;      ///< Publish simulation time on /clock.
  int tf_envs = 4;                ///< Envs that get tf frames (clamped to num_envs).
  double tf_rate = 30.0;          ///< Largest tf (and marker) rate [Hz of simulation time].
  bool markers = true;            ///< Publish ~markers for the envs with tf.
};

/// Name of a mode as given to the `mode` parameter.
std::string modeName(EnvMode mode);

/// Reads the private parameters from `pnh`, keeping the default of every absent one, and
/// validates them all. Throws ConfigError naming the first invalid parameter and its value.
NodeParams loadNodeParams(const ros::NodeHandle& pnh);

/// Throws ConfigError naming the first invalid parameter and its value.
void validateNodeParams(const NodeParams& params);

/// One line per parameter, "name: value", for the start-up INFO echo.
std::string describeNodeParams(const NodeParams& params);

}  // namespace jetbot_rl
