#pragma once

#include <memory>

#include "jetbot_rl/ppo/action_scaler.h"
#include "jetbot_rl/ppo/actor_critic.h"
#include "jetbot_rl/ppo/obs_normalizer.h"
#include "jetbot_rl/ppo/policy.h"
#include "jetbot_rl/ppo/policy_memory.h"

namespace jetbot_rl {
namespace ppo {

/// Policy's libtorch parts, for its own source files (policy.cpp, policy_export.cpp).
struct Policy::Model {
  ActorCritic net{nullptr};
  ObsNormalizer normalizer{nullptr};
  std::unique_ptr<ActionScaler> scaler;  // set by setActionLimits()
  std::unique_ptr<PolicyMemory> memory;  // sized by the last act()
};

}  // namespace ppo
}  // namespace jetbot_rl
