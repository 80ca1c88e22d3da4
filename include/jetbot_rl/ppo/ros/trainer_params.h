#pragma once

#include <ros/node_handle.h>

#include <string>

#include "jetbot_rl/config_fields.h"
#include "jetbot_rl/ppo/ppo_config.h"
#include "jetbot_rl/ppo/runner.h"

namespace jetbot_rl {
namespace ppo {

/// Private parameters of jetbot_ppo_trainer besides the PPO hyper-parameters.
struct TrainerParams {
  RunnerOptions run;               ///< iterations, run_dir, resume, save_interval, ...
  std::string env = "jetbot_env";  ///< The jetbot_env node (relative: in the node's namespace).
  /// Build the env in this process (LocalVecEnv) from the parameters under ~env_config (those of
  /// jetbot_env_node) and robot_description, instead of talking to an env node.
  bool env_in_process = false;
  double step_timeout = 10.0;  ///< Give up when the env does not answer within this [s, wall].
  int torch_threads = 1;       ///< libtorch intra-op threads (1: deterministic, leaves a core).
};

template <typename C, typename V>
IfConfig<C, TrainerParams> visitFields(C& c, V&& v) {
  visitFields(c.run, v);
  v("env", c.env, AnyValue{});
  v("env_in_process", c.env_in_process, AnyValue{});
  v("step_timeout", c.step_timeout, positive("s, wall"));
  v("torch_threads", c.torch_threads, inRange(1, 256));
}

/// Reads the private parameters from `pnh` (defaults for absent ones) into `ppo` and the
/// returned TrainerParams, resolves run_dir and resume, and validates everything. Throws
/// ConfigError naming the parameter and its value.
TrainerParams loadTrainerParams(const ros::NodeHandle& pnh, PpoConfig& ppo);

/// `~/.ros/jetbot_rl` ($ROS_HOME/jetbot_rl when ROS_HOME is set).
std::string defaultRunRoot();

}  // namespace ppo
}  // namespace jetbot_rl
