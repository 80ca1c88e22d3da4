#include "jetbot_rl/ppo/ppo_config.h"

namespace jetbot_rl {
namespace ppo {

void checkFieldRules(const PpoConfig& c) {
  if (c.min_learning_rate > c.max_learning_rate) {
    throwInvalid("min_learning_rate", c.min_learning_rate, "must be <= max_learning_rate");
  }
}

void validate(const PpoConfig& c) { validateConfig(c); }

std::string toYaml(const PpoConfig& config) { return fieldsToYaml(config); }

PpoConfig fromYaml(const std::string& yaml, PpoConfig config) {
  fieldsFromYaml(yaml, config);
  return config;
}

bool sameArchitecture(const PpoConfig& a, const PpoConfig& b) {
  return a.actor_hidden_dims == b.actor_hidden_dims &&
         a.critic_hidden_dims == b.critic_hidden_dims && a.activation == b.activation;
}

}  // namespace ppo
}  // namespace jetbot_rl
