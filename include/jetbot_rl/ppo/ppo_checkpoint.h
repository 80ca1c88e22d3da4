#pragma once

#include <string>

#include "jetbot_rl/ppo/checkpoint.h"
#include "jetbot_rl/ppo/ppo.h"
#include "jetbot_rl/ppo/ppo_config.h"

namespace jetbot_rl {
namespace ppo {

/**
 * Writes model, Adam state, observation normaliser, `meta` and every hyper-parameter of `ppo`
 * (its PpoConfig, as "config"; `meta.config` is its part of them) to `path` (torch::serialize
 * archive), through a temporary file renamed into place so that a reader never sees half a file.
 */
void saveCheckpoint(const std::string& path, Ppo& ppo, const CheckpointMeta& meta);

/// Loads model, Adam state and normaliser into `ppo` (built with the checkpoint's sizes and
/// architecture); returns the metadata. Throws Error naming the file on any mismatch.
CheckpointMeta loadCheckpoint(const std::string& path, Ppo& ppo);

/// Every hyper-parameter `path` was trained with (one missing at its default). Throws Error
/// naming the file.
PpoConfig readCheckpointConfig(const std::string& path);

}  // namespace ppo
}  // namespace jetbot_rl
