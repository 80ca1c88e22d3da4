#include "jetbot_rl/ppo/ros/policy_params.h"

#include <filesystem>

#include "jetbot_rl/ros/common/param_reader.h"

namespace jetbot_rl {
namespace ppo {

void checkFieldRules(const PolicyParams& p) {
  if (p.checkpoint.empty()) {
    throwInvalid("checkpoint", "''", "name a checkpoint file or a run directory");
  }
}

std::optional<PolicyParams> loadPolicyParams(const ros::NodeHandle& pnh) {
  return loadParams<PolicyParams>(pnh, [](PolicyParams& p) {
    if (std::filesystem::is_directory(p.checkpoint)) {
      p.checkpoint = (std::filesystem::path(p.checkpoint) / "checkpoints/best.pt").string();
    }
  });
}

}  // namespace ppo
}  // namespace jetbot_rl
