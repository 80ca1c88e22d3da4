#pragma once

#include <string>
#include <utility>
#include <vector>

#include "jetbot_rl/config/config_fields.h"
#include "jetbot_rl/ppo/network_config.h"

namespace jetbot_rl {
namespace ppo {

/// Learning-rate schedule: KL-controlled (rsl_rl) or fixed.
enum class LrSchedule { kAdaptive, kFixed };

/// Every PPO hyper-parameter: the policy's (NetworkConfig: network, memory, squashing,
/// normaliser) and the trainer's; defaults match config/ppo.yaml.
struct PpoConfig : NetworkConfig {
  // --- run ---
  int seed = 0;  ///< Seeds torch (weights, sampling, minibatches) and the env reset, >= 0.

  // --- rollout ---
  int num_steps_per_env = 16;  ///< Control steps per env per iteration (rollout length T).
  /// Start env i's first episode at episode step i x (max_episode_length - 1) / num_envs (as
  /// rsl_rl's random initial episode lengths), so that episodes end at staggered steps and every
  /// rollout holds episode starts and ends.
  bool stagger_episodes = true;

  // --- PPO update ---
  int num_learning_epochs = 5;                  ///< Passes over each rollout.
  int num_mini_batches = 4;                     ///< Minibatches per epoch.
  double learning_rate = 1e-3;                  ///< Adam learning rate (initial, when adaptive).
  LrSchedule schedule = LrSchedule::kAdaptive;  ///< KL-controlled or fixed learning rate.
  double desired_kl = 0.01;         ///< Adaptive schedule: target KL divergence per minibatch.
  double min_learning_rate = 1e-5;  ///< Adaptive schedule: lower bound of the learning rate.
  double max_learning_rate = 1e-2;  ///< Adaptive schedule: upper bound of the learning rate.
  /// Fraction of the iterations, at the end, over which the learning rate's ceiling falls
  /// linearly to min_learning_rate (0: none).
  double lr_cooldown = 0.0;
  double gamma = 0.99;                 ///< Discount per control step.
  double lam = 0.95;                   ///< GAE lambda.
  double clip_param = 0.2;             ///< Clip range of the probability ratio and value change.
  bool use_clipped_value_loss = true;  ///< Clip the value change like the policy ratio.
  double value_loss_coef = 1.0;        ///< Weight of the value loss.
  double entropy_coef = 0.005;         ///< Weight of the entropy bonus.
  double max_grad_norm = 1.0;          ///< Global gradient-norm clip.
};

/// The fields of PpoConfig with their rules: the one list that validation, the echo, YAML
/// (config.yaml, checkpoints) and the ROS parameter loader share.
template <typename C, typename V>
IfConfig<C, PpoConfig> visitFields(C& c, V&& v) {
  v("seed", c.seed, atLeast(0),
    "Seeds torch (weights, sampling, minibatches) and the env's reset.");
  v("num_steps_per_env", c.num_steps_per_env, inRange(1, 100000),
    "Control steps per env per iteration (rollout length).");
  v("stagger_episodes", c.stagger_episodes, AnyValue{},
    "The first reset starts env i at episode step i x (max_episode_length - 1) / num_envs, so "
    "that episodes end at staggered steps (rsl_rl's random initial episode lengths).");
  visitPolicyFields(c, v);  // the policy's fields, in their place
  v("num_learning_epochs", c.num_learning_epochs, inRange(1, 1000), "Passes over each rollout.");
  v("num_mini_batches", c.num_mini_batches, atLeast(1),
    "Minibatches per epoch (<= num_steps_per_env x num_envs; with an RNN <= num_envs: a "
    "minibatch holds whole env sequences).");
  v("learning_rate", c.learning_rate, positive(),
    "Adam learning rate (the start value when schedule is adaptive).");
  v("schedule", c.schedule, AnyValue{},
    "adaptive: learning rate / 1.5 when KL > 2 desired_kl, x 1.5 when KL < desired_kl / 2 "
    "(rsl_rl); fixed: constant.");
  v("desired_kl", c.desired_kl, positive(), "Adaptive schedule's target KL per minibatch.");
  v("min_learning_rate", c.min_learning_rate, positive(),
    "Adaptive schedule's lower bound (<= max_learning_rate), and where lr_cooldown ends.");
  v("max_learning_rate", c.max_learning_rate, positive(), "Adaptive schedule's upper bound.");
  v("lr_cooldown", c.lr_cooldown, inRange(0.0, 1.0),
    "Fraction of the iterations, at the end, over which the learning rate's ceiling falls "
    "linearly from max_learning_rate (fixed schedule: learning_rate) to min_learning_rate, so "
    "that the last policy settles (0: none).");
  v("gamma", c.gamma, inRange(0.0, 1.0), "Discount per control step.");
  v("lam", c.lam, inRange(0.0, 1.0), "GAE lambda.");
  v("clip_param", c.clip_param, positive(),
    "PPO clip of the probability ratio (and of the value change).");
  v("use_clipped_value_loss", c.use_clipped_value_loss, AnyValue{},
    "Clip the value change like the ratio.");
  v("value_loss_coef", c.value_loss_coef, atLeast(0.0), "Weight of the value loss.");
  v("entropy_coef", c.entropy_coef, atLeast(0.0), "Weight of the entropy bonus.");
  v("max_grad_norm", c.max_grad_norm, positive(), "Global gradient-norm clip.");
}

/// The rules between PpoConfig's fields: min_learning_rate <= max_learning_rate.
void checkFieldRules(const PpoConfig& config);

/// Throws ConfigError naming the first invalid field and its value.
void validate(const PpoConfig& config);

/// The config as YAML ("name: value" lines, lists as [a, b]), the format of config.yaml.
std::string toYaml(const PpoConfig& config);

/// Reads the fields present in `yaml` (toYaml's format) over `config`; unknown keys are ignored.
/// Throws ConfigError for a value of the wrong type.
PpoConfig fromYaml(const std::string& yaml, PpoConfig config = PpoConfig());

/// True when both networks are the same (visitNetworkFields; the recurrent layer's sizes only
/// with one).
bool sameArchitecture(const NetworkConfig& a, const NetworkConfig& b);
/// Copies the fields that shape the network (visitNetworkFields) from `from` into `to`.
void copyArchitecture(const NetworkConfig& from, PpoConfig& to);
inline const EnumNameList<LrSchedule>& enumNames(LrSchedule) {
  static const EnumNameList<LrSchedule> names{{LrSchedule::kAdaptive, "adaptive"},
                                              {LrSchedule::kFixed, "fixed"}};
  return names;
}

}  // namespace ppo
}  // namespace jetbot_rl
