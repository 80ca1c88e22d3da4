#pragma once

#include <cstdint>

namespace jetbot_rl {

/// Queue of the env node's topics, published and subscribed [messages]: a few control steps.
inline constexpr std::uint32_t kEnvNodeQueueSize = 16;

/// ~env_step's queue per subscriber connection [bytes]: as many EnvSteps as fit, at least
/// kEnvNodeQueueSize and at most kEnvStepQueueMax, so that a subscriber that stalls for a moment
/// (a loaded machine) loses none, while one that reads nothing costs at most this.
inline constexpr std::uint32_t kEnvStepQueueBytes = 1u << 20;
inline constexpr std::uint32_t kEnvStepQueueMax = 1024;

/// ~env_step's queue [messages] for EnvSteps of `bytes` each.
inline std::uint32_t envStepQueueSize(std::uint32_t bytes) {
  const std::uint32_t fit = kEnvStepQueueBytes / (bytes > 0 ? bytes : 1);
  return fit < kEnvNodeQueueSize  ? kEnvNodeQueueSize
         : fit > kEnvStepQueueMax ? kEnvStepQueueMax
                                  : fit;
}

}  // namespace jetbot_rl
