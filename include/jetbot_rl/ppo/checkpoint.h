#pragma once

#include <torch/serialize/archive.h>

#include <cstdint>
#include <string>

#include "jetbot_rl/env/step_result.h"
#include "jetbot_rl/ppo/actor_critic.h"
#include "jetbot_rl/ppo/network_config.h"
#include "jetbot_rl/ppo/obs_normalizer.h"

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

/// Loads only the model and normaliser (for playing; no optimiser needed).
CheckpointMeta loadPolicy(const std::string& path, ActorCritic& model, ObsNormalizer& normalizer);

// ---- the archive's layout, shared with the trainer's checkpoint (ppo_checkpoint.h) ----

/// Opens the checkpoint `path`; Error naming it when it is no file or no archive.
torch::serialize::InputArchive openCheckpoint(const std::string& path);
/// Writes `meta` into `archive`, with `config_yaml` (every hyper-parameter as YAML) as "config".
void writeCheckpointMeta(torch::serialize::OutputArchive& archive, const CheckpointMeta& meta,
                         const std::string& config_yaml);
/// Reads the metadata of `archive`; the "config" entry as stored into `config_yaml` when given.
/// Error for an unsupported format; c10::Error for a missing entry.
CheckpointMeta readCheckpointMeta(torch::serialize::InputArchive& archive,
                                  std::string* config_yaml = nullptr);
/// Error naming `path` when `meta`'s sizes are not a model of `input_dim` and `action_dim`.
void checkCheckpointSizes(const std::string& path, const CheckpointMeta& meta, int input_dim,
                          int action_dim);

}  // namespace ppo
}  // namespace jetbot_rl
