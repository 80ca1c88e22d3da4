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
         a.critic_hidden_dims == b.critic_hidden_dims && a.activation == b.activation &&
         a.obs_history_length == b.obs_history_length &&
         a.action_history_length == b.action_history_length && a.rnn_type == b.rnn_type &&
         (a.rnn_type == RnnType::kNone ||
          (a.rnn_hidden_size == b.rnn_hidden_size && a.rnn_num_layers == b.rnn_num_layers));
}

void copyArchitecture(const PpoConfig& from, PpoConfig& to) {
  to.actor_hidden_dims = from.actor_hidden_dims;
  to.critic_hidden_dims = from.critic_hidden_dims;
  to.activation = from.activation;
  to.obs_history_length = from.obs_history_length;
  to.action_history_length = from.action_history_length;
  to.rnn_type = from.rnn_type;
  to.rnn_hidden_size = from.rnn_hidden_size;
  to.rnn_num_layers = from.rnn_num_layers;
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
