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

std::string networkYaml(const PpoConfig& config) {
  return fieldsToYaml(config, [](const PpoConfig& c, auto&& v) { visitNetworkFields(c, v); });
}

bool sameArchitecture(const PpoConfig& a, const PpoConfig& b) {
  // Without a recurrent layer its sizes shape nothing.
  const auto shaping = [](PpoConfig c) {
    if (c.rnn_type == RnnType::kNone) {
      c.rnn_hidden_size = PpoConfig().rnn_hidden_size;
      c.rnn_num_layers = PpoConfig().rnn_num_layers;
    }
    return networkYaml(c);
  };
  return shaping(a) == shaping(b);
}

void copyArchitecture(const PpoConfig& from, PpoConfig& to) {
  fieldsFromYaml(networkYaml(from), to);
}

int policyInputDim(const PpoConfig& c, int obs_dim, int action_dim) {
  return c.obs_history_length * obs_dim + c.action_history_length * action_dim;
}

bool hasHistory(const PpoConfig& c) {
  return c.obs_history_length > 1 || c.action_history_length > 0;
}

bool hasMemory(const PpoConfig& c) { return hasHistory(c) || c.rnn_type != RnnType::kNone; }

}  // namespace ppo
}  // namespace jetbot_rl
