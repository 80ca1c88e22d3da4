#pragma once

#include <ros/node_handle.h>

#include <optional>
#include <string>

#include "jetbot_rl/config/config_fields.h"
#include "jetbot_rl/ppo/ppo_config.h"
#include "jetbot_rl/ppo/runner_options.h"
#include "jetbot_rl/ros/client/connect_envs.h"
#include "jetbot_rl/ros/common/param_reader.h"

namespace jetbot_rl {
namespace ppo {

/// Private parameters of jetbot_ppo_trainer besides the PPO hyper-parameters.
struct TrainerParams {
  RunnerOptions run;         ///< iterations, run_dir, resume, save_interval, ...
  EnvNodesParams env_nodes;  ///< env_nodes, step_timeout
  /// Build the env in this process (LocalVecEnv) from the parameters under ~env_config (those of
  /// jetbot_env_node) and robot_description, instead of talking to env nodes; with several
  /// env_nodes, one part per name from ~env_config/NAME, stepped as one batch in list order.
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
  v("env_in_process", c.env_in_process, AnyValue{},
    "Build the env in this process from the parameters under ~env_config (those of "
    "jetbot_env_node's EnvSetup) and robot_description, instead of stepping env nodes; with "
    "several env_nodes, one part per name from ~env_config/NAME, one batch in list order.");
  v("torch_threads", c.torch_threads, inRange(1, 256),
    "libtorch intra-op threads; 1 is deterministic and leaves a core to the env.");
  v("end_launch", c.end_launch, AnyValue{},
    "When the run has ended well, end the roslaunch that started this node cleanly (SIGINT).");
}

/// Every private parameter of jetbot_ppo_trainer: its own, then the PPO hyper-parameters.
struct TrainerConfig {
  TrainerParams trainer;
  PpoConfig ppo;
};

template <typename C, typename V>
IfConfig<C, TrainerConfig> visitFields(C& c, V&& v) {
  visitFields(c.trainer, v);
  visitFields(c.ppo, v);
}

/// PpoConfig's rules between fields.
inline void checkFieldRules(const TrainerConfig& c) { checkFieldRules(c.ppo); }

/// Reads, validates and echoes the trainer's private parameters under `pnh` (loadParams), with
/// resume resolved to a checkpoint file and run_dir to a created directory (resume's run, or
/// ~/.ros/jetbot_rl/TIME_seedSEED when empty). std::nullopt after ROS_FATAL naming a bad one.
std::optional<TrainerConfig> loadTrainerConfig(const ros::NodeHandle& pnh);

/// `~/.ros/jetbot_rl` ($ROS_HOME/jetbot_rl when ROS_HOME is set).
std::string defaultRunRoot();

}  // namespace ppo
}  // namespace jetbot_rl
