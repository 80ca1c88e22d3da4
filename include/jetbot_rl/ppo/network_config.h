#pragma once

#include <type_traits>
#include <vector>

#include "jetbot_rl/config/config_fields.h"

namespace jetbot_rl {
namespace ppo {

/// Hidden-layer activation of both MLPs.
enum class Activation { kElu, kTanh, kRelu };
/// How a Gaussian sample is squashed into [-1, 1] before it is scaled to the action limits.
enum class ActionSquash { kClip, kTanh };
/// Recurrent layer before both MLPs (rsl_rl's ActorCriticRecurrent), or none.
enum class RnnType { kNone, kGru, kLstm };

/// The hyper-parameters a trained policy is built and run with (its network, memory, squashing
/// and normaliser): the policy library's part of PpoConfig, which extends it with the trainer's.
/// Defaults match config/ppo.yaml.
struct NetworkConfig {
  std::vector<int> actor_hidden_dims{32, 32};   ///< Hidden layer widths of the policy MLP.
  std::vector<int> critic_hidden_dims{32, 32};  ///< Hidden layer widths of the value MLP.
  Activation activation = Activation::kElu;     ///< Hidden activation.
  double init_noise_std = 1.0;  ///< Initial policy std, in normalised action units ([-1, 1]).
  ActionSquash action_squash = ActionSquash::kClip;  ///< Sample -> [-1, 1], then to the limits.
  bool normalize_observations = true;                ///< Running mean/std observation normaliser.
  int obs_history_length = 1;     ///< Observations the policy sees: the current one and k-1 before.
  int action_history_length = 0;  ///< Its own previous actions the policy sees.
  RnnType rnn_type = RnnType::kNone;  ///< Recurrent layer before the actor's and critic's MLPs.
  int rnn_hidden_size = 64;           ///< Its state width per layer.
  int rnn_num_layers = 1;             ///< Its stacked layers.
  // The image encoder of a policy that observes a camera image (ObserverSpec::camera_image).
  std::vector<int> conv_channels{16, 32};  ///< Output channels of each convolution.
  std::vector<int> conv_kernels{5, 3};     ///< Their square kernels [px].
  std::vector<int> conv_strides{2, 2};     ///< Their strides [px].
  int image_features = 64;                 ///< The encoder's output width.
  bool image_grayscale = false;            ///< The image is turned grey before the encoder.
  int image_frames = 1;  ///< Camera images the encoder sees: the current one and k-1 before.
};

/// Enables the visitors below for NetworkConfig and the configs that extend it (PpoConfig).
template <typename C>
using IfNetworkConfig = std::enable_if_t<std::is_base_of_v<NetworkConfig, std::remove_const_t<C>>>;

/// The fields that shape the network (its layers and memory): the one list that resuming
/// (sameArchitecture, copyArchitecture) and the export's meta.yaml share.
template <typename C, typename V, typename = IfNetworkConfig<C>>
void visitNetworkFields(C& c, V&& v) {
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
  v("conv_channels", c.conv_channels, IntList{1, 1024},
    "An image policy (the env's observation contract names a camera_image): the output channels "
    "of each convolution of its image encoder (each followed by a ReLU); the encoder's features "
    "join the vector observation before both MLPs.");
  v("conv_kernels", c.conv_kernels, IntList{1, 64, "px"},
    "Their square kernels, one per convolution.");
  v("conv_strides", c.conv_strides, IntList{1, 64, "px"},
    "Their strides, one per convolution (no padding).");
  v("image_features", c.image_features, inRange(1, 4096),
    "The image encoder's output width: a Linear and a ReLU after the convolutions.");
  v("image_grayscale", c.image_grayscale, AnyValue{},
    "The image is turned grey (ITU-R BT.601 luma) before the encoder: one channel, not three.");
  v("image_frames", c.image_frames, inRange(1, 16, "control steps"),
    "A frame stack: the encoder sees the last this many camera images (the current one first), "
    "as channels of one input; an episode starts with all of them its first image. Each is kept "
    "in the rollout (its memory times this many).");
}

/// Every field of NetworkConfig in PpoConfig's order (the network's, then the initial noise, the
/// squashing and the normaliser), which PpoConfig's own list takes in as it is.
template <typename C, typename V, typename = IfNetworkConfig<C>>
void visitPolicyFields(C& c, V&& v) {
  visitNetworkFields(c, v);
  v("init_noise_std", c.init_noise_std, positive(),
    "Initial policy std in normalised action units (1 = the limit).");
  v("action_squash", c.action_squash, AnyValue{},
    "Gaussian sample -> [-1, 1] (clip or tanh), then scaled to the env's action bounds.");
  v("normalize_observations", c.normalize_observations, AnyValue{},
    "Running mean/std observation normaliser (saved in checkpoints).");
}

/// NetworkConfig's field list (visitPolicyFields): reads it from a checkpoint's hyper-parameters,
/// the trainer's among them ignored.
template <typename C, typename V>
IfConfig<C, NetworkConfig> visitFields(C& c, V&& v) {
  visitPolicyFields(c, v);
}

/// The fields that shape the network (visitNetworkFields) as YAML lines.
std::string networkYaml(const NetworkConfig& config);
/// True when the policy has memory: a history longer than the current observation, or an RNN.
bool hasMemory(const NetworkConfig& config);
/// True when the policy's input is a history: more than the current observation, or actions.
bool hasHistory(const NetworkConfig& config);
/// The network's input width: obs_history_length x obs_dim + action_history_length x action_dim.
int policyInputDim(const NetworkConfig& config, int obs_dim, int action_dim);

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

}  // namespace ppo
}  // namespace jetbot_rl
