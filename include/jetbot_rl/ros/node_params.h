#pragma once

#include <ros/node_handle.h>

#include <string>

#include "jetbot_rl/config_fields.h"
#include "jetbot_rl/env_config.h"
#include "jetbot_rl/task_factory.h"

namespace jetbot_rl {

/// How the node advances the simulation.
enum class EnvMode {
  kLockstep,  ///< One control step per accepted WheelTargets or ~step call (training).
  kRealtime,  ///< Steps on a wall-clock timer with the latest targets (driving by hand).
};

inline const EnumNameList<EnvMode>& enumNames(EnvMode) {
  static const EnumNameList<EnvMode> names{{EnvMode::kLockstep, "lockstep"},
                                           {EnvMode::kRealtime, "realtime"}};
  return names;
}

/// Every private parameter of jetbot_env_node; defaults match config/jetbot_env.yaml.
struct NodeParams {
  EnvConfig env;    ///< num_envs, env_spacing, physics_dt, ..., solver_iterations.
  TaskConfig task;  ///< task, reward.
  EnvMode mode = EnvMode::kLockstep;
  double real_time_factor = 1.0;  ///< Realtime mode: simulated seconds per wall second.
  double action_timeout = 0.5;    ///< Realtime mode: targets older than this brake [s, wall].
  bool publish_clock = true;      ///< Publish simulation time on /clock.
  int tf_envs = 4;                ///< Envs that get tf frames (clamped to num_envs).
  double tf_rate = 30.0;          ///< Largest tf (and marker) rate [Hz of simulation time].
  bool markers = true;            ///< Publish ~markers for the envs with tf.
};

template <typename C, typename V>
IfConfig<C, NodeParams> visitFields(C& c, V&& v) {
  visitFields(c.env, v);
  visitFields(c.task, v);
  v("mode", c.mode, AnyValue{});
  v("real_time_factor", c.real_time_factor, positiveUpTo(1000.0));
  v("action_timeout", c.action_timeout, positive("s, wall"));
  v("publish_clock", c.publish_clock, AnyValue{});
  v("tf_envs", c.tf_envs, atLeast(0, "", "0: no tf"));
  v("tf_rate", c.tf_rate, positive("Hz of simulation time"));
  v("markers", c.markers, AnyValue{});
}

/// Reads the private parameters from `pnh`, keeping the default of every absent one, and
/// validates them all. Throws ConfigError naming the first invalid parameter and its value.
NodeParams loadNodeParams(const ros::NodeHandle& pnh);

}  // namespace jetbot_rl
