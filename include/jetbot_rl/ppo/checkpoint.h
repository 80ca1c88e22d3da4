#pragma once

#include <torch/serialize/archive.h>

#include <cstdint>
#include <string>

#include "jetbot_rl/env/step_result.h"
#include "jetbot_rl/ppo/actor_critic.h"
#include "jetbot_rl/ppo/checkpoint_meta.h"
#include "jetbot_rl/ppo/network_config.h"
#include "jetbot_rl/ppo/obs_normalizer.h"

namespace jetbot_rl {
namespace ppo {

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
