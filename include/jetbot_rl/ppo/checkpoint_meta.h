#pragma once

#include <cstdint>
#include <string>

#include "jetbot_rl/env/step_result.h"
#include "jetbot_rl/ppo/network_config.h"

// What a checkpoint says besides its tensors, without libtorch's headers (checkpoint.h has the
// archive's side): a program that only plays a policy (policy.h) includes this one.

namespace jetbot_rl {
namespace ppo {

/// Everything in a checkpoint besides the tensors.
struct CheckpointMeta {
  std::int64_t format_version = 0;  ///< The file's format (checkpoint.cpp); 0: not read from one.
  std::int64_t iteration = 0;       ///< Completed iterations.
  std::int64_t env_steps = 0;       ///< Env steps collected (control steps x envs).
  double elapsed_s = 0.0;           ///< Wall time of training so far [s].
  double best_reward = -1e300;      ///< Best mean reward per step of an iteration so far.
  double learning_rate = 0.0;       ///< Current (adaptive) learning rate.
  int obs_dim = 0;                  ///< Observation size (the model's input is its history).
  int action_dim = 0;               ///< Model output size.
  /// The policy's hyper-parameters the model was trained with (read from the checkpoint's
  /// "config", which holds every one of the trainer's: ppo_checkpoint.h reads them all).
  NetworkConfig config;
  /// The env it was trained on (num_envs 0): task, names, action bounds [env units] and control
  /// step [s], which the deploy node runs it with, and from format 3 its observation contract
  /// (spec.observer). Empty in checkpoints of format 1.
  BatchSpec spec;
};

/// The checkpoint format from which `spec.observer` is written (the observation contract).
constexpr std::int64_t kObservationContractFormat = 3;

/// Error naming `path` when `meta` was read from a checkpoint written before checkpoints held
/// the observation contract (a robot elsewhere builds its observer from it): the message says
/// how to save it again.
void requireObservationContract(const CheckpointMeta& meta, const std::string& path);

/// Reads only the metadata (enough to build a matching model). Throws Error naming the file.
CheckpointMeta readCheckpointMeta(const std::string& path);

}  // namespace ppo
}  // namespace jetbot_rl
