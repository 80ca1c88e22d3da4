#include "jetbot_rl/ppo/network_config.h"

namespace jetbot_rl {
namespace ppo {

std::string networkYaml(const NetworkConfig& config) {
  return fieldsToYaml(config, [](const NetworkConfig& c, auto&& v) { visitNetworkFields(c, v); });
}

int policyInputDim(const NetworkConfig& c, int obs_dim, int action_dim) {
  return c.obs_history_length * obs_dim + c.action_history_length * action_dim;
}

bool hasHistory(const NetworkConfig& c) {
  return c.obs_history_length > 1 || c.action_history_length > 0;
}

bool hasMemory(const NetworkConfig& c) {
  return hasHistory(c) || c.rnn_type != RnnType::kNone || c.image_frames > 1;
}

}  // namespace ppo
}  // namespace jetbot_rl
