#pragma once

#include <ros/node_handle.h>

#include <string>

#include "jetbot_rl/ppo/ppo_config.h"

namespace jetbot_rl {
namespace ppo {

/// Private parameters of jetbot_ppo_trainer: the PPO hyper-parameters and the run's settings.
struct TrainerParams {
  PpoConfig ppo;                   ///< Hyper-parameters (config/ppo.yaml).
  int iterations = 100;            ///< The run ends after this many iterations (resume included).
  std::string run_dir;             ///< Run directory; empty: ~/.ros/jetbot_rl/<time>_seed<seed>.
  std::string resume;              ///< Checkpoint (or run directory) to continue; empty: new run.
  std::string env = "jetbot_env";  ///< The jetbot_env node (relative: in the node's namespace).
  int save_interval = 10;          ///< Save checkpoints/latest.pt every this many iterations.
  double step_timeout = 10.0;      ///< Give up when the env does not answer within this [s, wall].
  int torch_threads = 1;           ///< libtorch intra-op threads (1: deterministic, leaves a core).
  double target_reward = 0.54;     ///< Reported: first iteration with mean reward/step >= this
                                   ///< [m/s] (90 % of 20 rad/s x 0.03 m).
  int obs_stats_from_step = -1;    ///< obs_mean_* columns over samples at this episode step or
                                   ///< later [control steps]; -1: max_episode_length / 2.
};

/// Reads the private parameters from `pnh` (defaults for absent ones), resolves run_dir and
/// resume, and validates everything. Throws ConfigError naming the parameter and its value.
TrainerParams loadTrainerParams(const ros::NodeHandle& pnh);

/// One "name: value" line per parameter (the INFO echo and config.yaml); `with_ppo` false leaves
/// out the PPO hyper-parameters.
std::string describeTrainerParams(const TrainerParams& params, bool with_ppo = true);

/// Reads every PpoConfig field present under `pnh` into `config` (ConfigError on a wrong type).
void readPpoParams(const ros::NodeHandle& pnh, PpoConfig& config);

/// `~/.ros/jetbot_rl` ($ROS_HOME/jetbot_rl when ROS_HOME is set).
std::string defaultRunRoot();

}  // namespace ppo
}  // namespace jetbot_rl
