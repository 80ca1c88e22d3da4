#pragma once

#include <ros/node_handle.h>

#include <string>

#include "jetbot_rl/config_fields.h"
#include "jetbot_rl/ppo/ppo_config.h"
#include "jetbot_rl/ppo/runner.h"
#include "jetbot_rl/ros/connect_envs.h"
#include "jetbot_rl/ros/param_reader.h"

namespace jetbot_rl {
namespace ppo {

/// Private parameters of jetbot_ppo_trainer besides the PPO hyper-parameters.
struct TrainerParams {
  RunnerOptions run;         ///< iterations, run_dir, resume, save_interval, ...
  EnvNodesParams env_nodes;  ///< envs, step_timeout
  /// Build the env in this process (LocalVecEnv) from the parameters under ~env_config (those of
  /// jetbot_env_node) and robot_description, instead of talking to env nodes.
  bool env_in_process = false;
  int torch_threads = 1;  ///< libtorch intra-op threads (1: deterministic, leaves a core).
  /// When the run has ended well (completed or interrupted), end the roslaunch that started
  /// this node cleanly (SIGINT to it) instead of leaving it to notice a required node's exit.
  bool end_launch = false;
};

template <typename C, typename V>
IfConfig<C, TrainerParams> visitFields(C& c, V&& v) {
  visitFields(c.run, v);
  visitFields(c.env_nodes, v);
  v("env_in_process", c.env_in_process, AnyValue{});
  v("torch_threads", c.torch_threads, inRange(1, 256));
  v("end_launch", c.end_launch, AnyValue{});
}

/// Reads the private parameters from `pnh` (defaults for absent ones) into `ppo` and the
/// returned TrainerParams, resolves run_dir and resume, and validates everything. Throws
/// ConfigError naming the parameter and its value.
TrainerParams loadTrainerParams(const ros::NodeHandle& pnh, PpoConfig& ppo);

/// `~/.ros/jetbot_rl` ($ROS_HOME/jetbot_rl when ROS_HOME is set).
std::string defaultRunRoot();

}  // namespace ppo
}  // namespace jetbot_rl
