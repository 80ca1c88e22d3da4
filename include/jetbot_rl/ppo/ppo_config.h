#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace jetbot_rl {
namespace ppo {

/// Every PPO hyper-parameter; defaults match config/ppo.yaml.
struct PpoConfig {
  // --- run ---
  int seed = 0;  ///< Seeds torch (weights, sampling, minibatches) and the env reset, >= 0.

  // --- rollout ---
  int num_steps_per_env = 16;  ///< Control steps per env per iteration (rollout length T).
  /// Cut env i's first episode after i x (max_episode_length - 1) / num_envs steps (a time-out,
  /// bootstrapped), so that episodes end at staggered steps, as rsl_rl's random initial
  /// episode lengths: every rollout then holds episode starts and ends.
  bool stagger_episodes = true;

  // --- model ---
  std::vector<int> actor_hidden_dims{32, 32};   ///< Hidden layer widths of the policy MLP.
  std::vector<int> critic_hidden_dims{32, 32};  ///< Hidden layer widths of the value MLP.
  std::string activation = "elu";               ///< Hidden activation: elu, tanh or relu.
  double init_noise_std = 1.0;  ///< Initial policy std, in normalised action units ([-1, 1]).
  std::string action_squash = "clip";  ///< Sample -> [-1, 1]: clip or tanh; then scaled to limits.
  bool normalize_observations = true;  ///< Running mean/std observation normaliser.

  // --- PPO update ---
  int num_learning_epochs = 5;         ///< Passes over each rollout.
  int num_mini_batches = 4;            ///< Minibatches per epoch.
  double learning_rate = 1e-3;         ///< Adam learning rate (initial, when adaptive).
  std::string schedule = "adaptive";   ///< adaptive (KL-controlled learning rate) or fixed.
  double desired_kl = 0.01;            ///< Adaptive schedule: target KL divergence per minibatch.
  double min_learning_rate = 1e-5;     ///< Adaptive schedule: lower bound of the learning rate.
  double max_learning_rate = 1e-2;     ///< Adaptive schedule: upper bound of the learning rate.
  double gamma = 0.99;                 ///< Discount per control step.
  double lam = 0.95;                   ///< GAE lambda.
  double clip_param = 0.2;             ///< Clip range of the probability ratio and value change.
  bool use_clipped_value_loss = true;  ///< Clip the value change like the policy ratio.
  double value_loss_coef = 1.0;        ///< Weight of the value loss.
  double entropy_coef = 0.005;         ///< Weight of the entropy bonus.
  double max_grad_norm = 1.0;          ///< Global gradient-norm clip.
};

/// Throws ConfigError naming the first invalid field and its value.
void validate(const PpoConfig& config);

/// The config as YAML ("name: value" lines, lists as [a, b]), the format of config.yaml.
std::string toYaml(const PpoConfig& config);

/// Reads the fields present in `yaml` (toYaml's format) over `config`; unknown keys are ignored.
/// Throws ConfigError for a value of the wrong type.
PpoConfig fromYaml(const std::string& yaml, PpoConfig config = PpoConfig());

/// True when both configs build the same network (hidden dims, activation).
bool sameArchitecture(const PpoConfig& a, const PpoConfig& b);

/// Calls `visitor(name, field)` for every field, in declaration order; the one list of names
/// that the YAML writer/reader and the ROS parameter loader share.
template <typename Config, typename Visitor>
void visitFields(Config& c, Visitor&& visitor) {
  visitor("seed", c.seed);
  visitor("num_steps_per_env", c.num_steps_per_env);
  visitor("stagger_episodes", c.stagger_episodes);
  visitor("actor_hidden_dims", c.actor_hidden_dims);
  visitor("critic_hidden_dims", c.critic_hidden_dims);
  visitor("activation", c.activation);
  visitor("init_noise_std", c.init_noise_std);
  visitor("action_squash", c.action_squash);
  visitor("normalize_observations", c.normalize_observations);
  visitor("num_learning_epochs", c.num_learning_epochs);
  visitor("num_mini_batches", c.num_mini_batches);
  visitor("learning_rate", c.learning_rate);
  visitor("schedule", c.schedule);
  visitor("desired_kl", c.desired_kl);
  visitor("min_learning_rate", c.min_learning_rate);
  visitor("max_learning_rate", c.max_learning_rate);
  visitor("gamma", c.gamma);
  visitor("lam", c.lam);
  visitor("clip_param", c.clip_param);
  visitor("use_clipped_value_loss", c.use_clipped_value_loss);
  visitor("value_loss_coef", c.value_loss_coef);
  visitor("entropy_coef", c.entropy_coef);
  visitor("max_grad_norm", c.max_grad_norm);
}

}  // namespace ppo
}  // namespace jetbot_rl
