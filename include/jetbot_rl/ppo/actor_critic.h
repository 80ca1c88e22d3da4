#pragma once

#include <torch/nn/module.h>
#include <torch/nn/modules/container/sequential.h>

#include <string>
#include <vector>

#include "jetbot_rl/ppo/image_encoder.h"
#include "jetbot_rl/ppo/network_config.h"
#include "jetbot_rl/ppo/recurrent_memory.h"

namespace jetbot_rl {
namespace ppo {

/// What the policy produced for a batch of (normalised) observations.
struct ActionSample {
  torch::Tensor actions;    ///< [B, A] Gaussian samples, normalised action units (before squash).
  torch::Tensor log_probs;  ///< [B] log-density of `actions`.
  torch::Tensor values;     ///< [B] V(obs).
  torch::Tensor mean;       ///< [B, A] Gaussian mean.
  torch::Tensor std;        ///< [B, A] Gaussian std.
};

/// The policy's view of stored actions, with gradients.
struct ActionEvaluation {
  torch::Tensor log_probs;  ///< [B]
  torch::Tensor entropy;    ///< [B]
  torch::Tensor values;     ///< [B]
  torch::Tensor mean;       ///< [B, A]
  torch::Tensor std;        ///< [B, A]
};

/// The recurrent states of a batch, [B, stateSize()] each; undefined without an RNN.
struct MemoryState {
  torch::Tensor actor, critic;
};

/**
 * Gaussian policy with a learned, state-independent log-std and a separate MLP value function;
 * with `rnn_type` gru or lstm, a recurrent layer before each MLP (rsl_rl's ActorCriticRecurrent).
 * Its input is the observation, or the history InputHistory stacks; an image policy's input is
 * that followed by the camera image's bytes (as floats, ImageShape::values() of them), which its
 * ImageEncoder turns into features beside it for both MLPs (or both RNNs).
 */
class ActorCriticImpl : public torch::nn::Module {
 public:
  /// Builds both MLPs with the hidden `activation`; std starts at `init_noise_std`.
  ActorCriticImpl(int input_dim, int action_dim, const std::vector<int>& actor_hidden_dims,
                  const std::vector<int>& critic_hidden_dims, Activation activation,
                  double init_noise_std);
  /// The same with config's widths, activation, noise and recurrent layer; with `image`, an
  /// image encoder of config's layers (ConfigError naming the field when the image does not fit
  /// them). `input_dim` excludes the image.
  ActorCriticImpl(int input_dim, int action_dim, const NetworkConfig& config,
                  ImageShape image = {});

  /// Samples actions (no gradients); uses torch's default generator. With an RNN, `state` is
  /// advanced by the step (its rows zeroed first where an episode starts).
  ActionSample act(const torch::Tensor& input, MemoryState* state = nullptr);
  /// Log-probabilities, entropy and values of given `actions` at `input` [B, D] (with gradients;
  /// no RNN).
  ActionEvaluation evaluate(const torch::Tensor& input, const torch::Tensor& actions);
  /// The same over whole sequences (with an RNN): `input` [T, B, D], `actions` [T, B, A], from
  /// `state` with the states zeroed where `starts` [T, B] is 1; results flattened to [T x B].
  ActionEvaluation evaluateSequence(const torch::Tensor& input, const torch::Tensor& actions,
                                    const MemoryState& state, const torch::Tensor& starts);
  /// [B, A] Gaussian mean: the deterministic action; `actor_state` advanced with an RNN.
  torch::Tensor actionMean(const torch::Tensor& input, torch::Tensor* actor_state = nullptr);
  /// [B] V(input), from `critic_state` with an RNN (not changed).
  torch::Tensor value(const torch::Tensor& input, const torch::Tensor* critic_state = nullptr);
  /// Current policy std per action dimension [normalised action units].
  torch::Tensor actionStd() const;

  /// Zero states for `batch` envs (undefined tensors without an RNN).
  MemoryState initialState(int64_t batch) const;
  bool recurrent() const { return !actor_rnn_.is_empty(); }

  /// The policy MLP (Linear and activation layers): input (or RNN output) -> action mean.
  const torch::nn::Sequential& actor() const { return actor_; }
  /// The actor's recurrent layer (empty without one).
  const RecurrentMemory& actorMemory() const { return actor_rnn_; }
  /// The image encoder (empty without an image).
  const ImageEncoder& imageEncoder() const { return encoder_; }
  /// The input's width without the image.
  int inputDim() const { return input_dim_; }
  /// The image's values that follow it in the input (0 without one).
  int imageValues() const { return encoder_.is_empty() ? 0 : encoder_->shape().values(); }
  int actionDim() const { return action_dim_; }

 private:
  /// What both MLPs (or RNNs) take: the input, with an image its features after the rest.
  torch::Tensor features(const torch::Tensor& input);
  /// actionMean() of features `x`.
  torch::Tensor meanOf(const torch::Tensor& x, torch::Tensor* actor_state);

  int input_dim_, action_dim_;
  ImageEncoder encoder_{nullptr};
  RecurrentMemory actor_rnn_{nullptr}, critic_rnn_{nullptr};
  torch::nn::Sequential actor_{nullptr}, critic_{nullptr};
  torch::Tensor log_std_;
};
TORCH_MODULE(ActorCritic);

}  // namespace ppo
}  // namespace jetbot_rl
