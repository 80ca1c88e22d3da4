#pragma once

#include <torch/optim/adam.h>

#include <memory>

#include "jetbot_rl/ppo/actor_critic.h"
#include "jetbot_rl/ppo/obs_normalizer.h"
#include "jetbot_rl/ppo/ppo_config.h"
#include "jetbot_rl/ppo/rollout_storage.h"

namespace jetbot_rl {
namespace ppo {

/// Means over the minibatch updates of one iteration.
struct UpdateStats {
  double value_loss = 0.0;      ///< Clipped value loss [(return units)^2].
  double surrogate_loss = 0.0;  ///< Clipped surrogate (to minimise).
  double entropy = 0.0;         ///< Policy entropy [nats].
  double approx_kl = 0.0;       ///< KL(old || new) of the Gaussians, mean per minibatch.
  double learning_rate = 0.0;   ///< Learning rate at the end of the update.
};

/// Proximal Policy Optimisation (the PPO paper, as rsl_rl): the actor-critic, its observation
/// normaliser, Adam, and the clipped update over minibatches and epochs.
class Ppo {
 public:
  /// Builds the model from `config` (validated by the caller) for the given sizes.
  Ppo(int obs_dim, int action_dim, const PpoConfig& config);

  /// Epochs x minibatches of the clipped PPO loss on a rollout whose returns are computed.
  UpdateStats update(const RolloutStorage& storage);

  ActorCritic& model() { return model_; }
  ObsNormalizer& normalizer() { return normalizer_; }
  torch::optim::Adam& optimizer() { return *optimizer_; }
  const PpoConfig& config() const { return config_; }
  double learningRate() const { return learning_rate_; }
  /// Sets the Adam learning rate of every parameter group.
  void setLearningRate(double lr);

 private:
  PpoConfig config_;
  ActorCritic model_;
  ObsNormalizer normalizer_;
  std::unique_ptr<torch::optim::Adam> optimizer_;
  double learning_rate_;
};

}  // namespace ppo
}  // namespace jetbot_rl
