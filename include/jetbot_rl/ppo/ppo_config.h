#pragma once

#include <string>
#include <utility>
#include <vector>

#include "jetbot_rl/config/config_fields.h"

namespace jetbot_rl {
namespace ppo {

/// Hidden-layer activation of both MLPs.
enum class Activation { kElu, kTanh, kRelu };
/// How a Gaussian sample is squashed into [-1, 1] before it is scaled to the action limits.
enum class ActionSquash { kClip, kTanh };
/// Learning-rate schedule: KL-controlled (rsl_rl) or fixed.
enum class LrSchedule { kAdaptive, kFixed };
/// Recurrent layer before both MLPs (rsl_rl's ActorCriticRecurrent), or none.
enum class RnnType { kNone, kGru, kLstm };

/// Every PPO hyper-parameter; defaults match config/ppo.yaml.
struct PpoConfig {
  // --- run ---
  int seed = 0;  ///< Seeds torch (weights, sampling, minibatches) and the env reset, >= 0.

  // --- rollout ---
  int num_steps_per_env = 16;  ///< Control steps per env per iteration (rollout length T).
  /// Start env i's first episode at episode step i x (max_episode_length - 1) / num_envs (as
  /// rsl_rl's random initial episode lengths), so that episodes end at staggered steps and every
  /// rollout holds episode starts and ends.
  bool stagger_episodes = true;

  // --- model ---
  std::vector<int> actor_hidden_dims{32, 32};   ///< Hidden layer widths of the policy MLP.
  std::vector<int> critic_hidden_dims{32, 32};  ///< Hidden layer widths of the value MLP.
  Activation activation = Activation::kElu;     ///< Hidden activation.
  double init_noise_std = 1.0;  ///< Initial policy std, in normalised action units ([-1, 1]).
  ActionSquash action_squash = ActionSquash::kClip;  ///< Sample -> [-1, 1], then to the limits.
  bool normalize_observations = true;                ///< Running mean/std observation normaliser.

  // --- memory ---
  int obs_history_length = 1;     ///< Observations the policy sees: the current one and k-1 before.
  int action_history_length = 0;  ///< Its own previous actions the policy sees.
  RnnType rnn_type = RnnType::kNone;  ///< Recurrent layer before the actor's and critic's MLPs.
  int rnn_hidden_size = 64;           ///< Its state width per layer.
  int rnn_num_layers = 1;             ///< Its stacked layers.

  // --- PPO update ---
  int num_learning_epochs = 5;                  ///< Passes over each rollout.
  int num_mini_batches = 4;                     ///< Minibatches per epoch.
  double learning_rate = 1e-3;                  ///< Adam learning rate (initial, when adaptive).
  LrSchedule schedule = LrSchedule::kAdaptive;  ///< KL-controlled or fixed learning rate.
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

/// The fields of PpoConfig that shape the network (its layers and memory): the one list that
/// resuming (sameArchitecture, copyArchitecture) and the export's meta.yaml share.
template <typename C, typename V>
IfConfig<C, PpoConfig> visitNetworkFields(C& c, V&& v) {
  v("actor_hidden_dims", c.actor_hidden_dims, IntList{1, 4096}, "Policy MLP hidden widths.");
  v("critic_hidden_dims", c.critic_hidden_dims, IntList{1, 4096}, "Value MLP hidden widths.");
  v("activation", c.activation, AnyValue{}, "Hidden activation of both MLPs.");
  v("obs_history_length", c.obs_history_length, inRange(1, 1000, "control steps"),
    "The policy sees the last this many observations (the current one first); an episode starts "
    "with all of them its first observation.");
  v("action_history_length", c.action_history_length, inRange(0, 1000, "control steps"),
    "The policy sees its last this many actions (normalised, in [-1, 1]; zero at an episode "
    "start).");
  v("rnn_type", c.rnn_type, AnyValue{},
    "none, or gru or lstm: a recurrent layer before the actor's MLP and one before the critic's, "
    "its state carried from step to step and zeroed at an episode start.");
  v("rnn_hidden_size", c.rnn_hidden_size, inRange(1, 4096),
    "The recurrent state's width per layer.");
  v("rnn_num_layers", c.rnn_num_layers, inRange(1, 16), "Stacked recurrent layers.");
}

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
  visitNetworkFields(c, v);
  v("init_noise_std", c.init_noise_std, positive(),
    "Initial policy std in normalised action units (1 = the limit).");
  v("action_squash", c.action_squash, AnyValue{},
    "Gaussian sample -> [-1, 1] (clip or tanh), then scaled to the env's action bounds.");
  v("normalize_observations", c.normalize_observations, AnyValue{},
    "Running mean/std observation normaliser (saved in checkpoints).");
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
    "Adaptive schedule's lower bound (<= max_learning_rate).");
  v("max_learning_rate", c.max_learning_rate, positive(), "Adaptive schedule's upper bound.");
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

/// True when both configs build the same network (visitNetworkFields; the recurrent layer's
/// sizes only with one).
bool sameArchitecture(const PpoConfig& a, const PpoConfig& b);
/// The fields that shape the network (visitNetworkFields) as YAML lines.
std::string networkYaml(const PpoConfig& config);
/// Copies the fields that shape the network (visitNetworkFields) from `from` into `to`.
void copyArchitecture(const PpoConfig& from, PpoConfig& to);
/// True when the policy has memory: a history longer than the current observation, or an RNN.
bool hasMemory(const PpoConfig& config);

/// True when the policy's input is a history: more than the current observation, or actions.
bool hasHistory(const PpoConfig& config);
/// The network's input width: obs_history_length x obs_dim + action_history_length x action_dim.
int policyInputDim(const PpoConfig& config, int obs_dim, int action_dim);

inline const EnumNameList<Activation>& enumNames(Activation) {
  static const EnumNameList<Activation> names{
      {Activation::kElu, "elu"}, {Activation::kTanh, "tanh"}, {Activation::kRelu, "relu"}};
  return names;
}
inline const EnumNameList<ActionSquash>& enumNames(ActionSquash) {
  static const EnumNameList<ActionSquash> names{{ActionSquash::kClip, "clip"},
                                                {ActionSquash::kTanh, "tanh"}};
  return names;
}
inline const EnumNameList<RnnType>& enumNames(RnnType) {
  static const EnumNameList<RnnType> names{
      {RnnType::kNone, "none"}, {RnnType::kGru, "gru"}, {RnnType::kLstm, "lstm"}};
  return names;
}
inline const EnumNameList<LrSchedule>& enumNames(LrSchedule) {
  static const EnumNameList<LrSchedule> names{{LrSchedule::kAdaptive, "adaptive"},
                                              {LrSchedule::kFixed, "fixed"}};
  return names;
}

}  // namespace ppo
}  // namespace jetbot_rl
