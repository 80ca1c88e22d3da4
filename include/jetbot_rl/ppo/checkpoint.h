#pragma once

#include <cstdint>
#include <string>

#include "jetbot_rl/ppo/ppo.h"
#include "jetbot_rl/ppo/ppo_config.h"

namespace jetbot_rl {
namespace ppo {

/// Everything in a checkpoint besides the tensors.
struct CheckpointMeta {
  std::int64_t iteration = 0;   ///< Completed iterations.
  std::int64_t env_steps = 0;   ///< Env steps collected (control steps x envs).
  double elapsed_s = 0.0;       ///< Wall time of training so far [s].
  double best_reward = -1e300;  ///< Best mean reward per step of an iteration so far.
  double learning_rate = 0.0;   ///< Current (adaptive) learning rate.
  int obs_dim = 0;              ///< Observation size (the model's input is its history).
  int action_dim = 0;           ///< Model output size.
  PpoConfig config;             ///< Hyper-parameters the model was trained with.
  /// The env it was trained on (num_envs 0): task, names, action bounds [env units] and control
  /// step [s], which the deploy node runs it with. Empty in checkpoints of format 1.
  BatchSpec spec;
};

/**
 * Writes model, Adam state, observation normaliser and `meta` to `path` (torch::serialize
 * archive), through a temporary file renamed into place so that a reader never sees half a file.
 */
void saveCheckpoint(const std::string& path, Ppo& ppo, const CheckpointMeta& meta);

/// Reads only the metadata (enough to build a matching Ppo). Throws Error naming the file.
CheckpointMeta readCheckpointMeta(const std::string& path);

/// Loads model, Adam state and normaliser into `ppo` (built with the checkpoint's sizes and
/// architecture); returns the metadata. Throws Error naming the file on any mismatch.
CheckpointMeta loadCheckpoint(const std::string& path, Ppo& ppo);

/// Loads only the model and normaliser (for playing; no optimiser needed).
CheckpointMeta loadPolicy(const std::string& path, ActorCritic& model, ObsNormalizer& normalizer);

}  // namespace ppo
}  // namespace jetbot_rl
