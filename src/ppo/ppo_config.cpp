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

bool sameArchitecture(const NetworkConfig& a, const NetworkConfig& b) {
  // Without a recurrent layer its sizes shape nothing.
  const auto shaping = [](NetworkConfig c) {
    if (c.rnn_type == RnnType::kNone) {
      c.rnn_hidden_size = NetworkConfig().rnn_hidden_size;
      c.rnn_num_layers = NetworkConfig().rnn_num_layers;
    }
    return networkYaml(c);
  };
  return shaping(a) == shaping(b);
}

void copyArchitecture(const NetworkConfig& from, PpoConfig& to) {
  fieldsFromYaml(networkYaml(from), to);
}

}  // namespace ppo
}  // namespace jetbot_rl
