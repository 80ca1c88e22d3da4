#pragma once

#include <torch/nn/module.h>
#include <torch/nn/modules/container/sequential.h>

#include <string>
#include <vector>

#include "jetbot_rl/ppo/ppo_config.h"

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

/// Gaussian policy with a learned, state-independent log-std and a separate MLP value function.
class ActorCriticImpl : public torch::nn::Module {
 public:
  /// Builds both MLPs with the hidden `activation`; std starts at `init_noise_std`.
  ActorCriticImpl(int obs_dim, int action_dim, const std::vector<int>& actor_hidden_dims,
                  const std::vector<int>& critic_hidden_dims, Activation activation,
                  double init_noise_std);

  /// Samples actions (no gradients); uses torch's default generator.
  ActionSample act(const torch::Tensor& obs);
  /// Log-probabilities, entropy and values of given `actions` at `obs` (with gradients).
  ActionEvaluation evaluate(const torch::Tensor& obs, const torch::Tensor& actions);
  /// [B, A] Gaussian mean: the deterministic action.
  torch::Tensor actionMean(const torch::Tensor& obs);
  /// [B] V(obs).
  torch::Tensor value(const torch::Tensor& obs);
  /// Current policy std per action dimension [normalised action units].
  torch::Tensor actionStd() const;

  /// The policy MLP (Linear and activation layers): obs -> action mean.
  const torch::nn::Sequential& actor() const { return actor_; }
  int obsDim() const { return obs_dim_; }
  int actionDim() const { return action_dim_; }

 private:
  int obs_dim_, action_dim_;
  torch::nn::Sequential actor_{nullptr}, critic_{nullptr};
  torch::Tensor log_std_;
};
TORCH_MODULE(ActorCritic);

}  // namespace ppo
}  // namespace jetbot_rl
