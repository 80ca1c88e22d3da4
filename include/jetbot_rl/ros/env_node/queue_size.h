#pragma once

#include <cstdint>

namespace jetbot_rl {

/// Queue of the env node's topics, published and subscribed [messages]: a few control steps.
inline constexpr std::uint32_t kEnvNodeQueueSize = 16;

}  // namespace jetbot_rl
