#pragma once

#include <torch/optim/adam.h>

#include <memory>
#include <vector>

#include "jetbot_rl/ppo/action_scaler.h"
#include "jetbot_rl/ppo/actor_critic.h"
#include "jetbot_rl/ppo/obs_normalizer.h"
#include "jetbot_rl/ppo/ppo_config.h"
#include "jetbot_rl/ppo/rollout_storage.h"
#include "jetbot_rl/step_result.h"

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

/**
 * Proximal Policy Optimisation (the PPO paper, as rsl_rl's algorithms/ppo.py): owns the
 * actor-critic, its observation normaliser, Adam and the rollout, and does all the learning:
 * acting, storing each transition (time-outs bootstrapped with V(final observation)), GAE returns
 * and the clipped update over minibatches and epochs. Knows the env only through StepResult.
 */
class Ppo {
 public:
  /// Builds the model from `config` (validated by the caller) for `spec`'s sizes and bounds.
  Ppo(const BatchSpec& spec, const PpoConfig& config);

  /// Samples actions for `state`'s observations (folded into the normaliser first); returns them
  /// in env units (num_envs x action_dim, e.g. rad/s), remembered for processEnvStep().
  const std::vector<float>& act(const StepResult& state);
  /// Stores the transition of the last act() with the env's answer `result`: a truncated env
  /// bootstraps with V(its final observation), a terminated one with 0. Throws Error when the
  /// rollout is full or `result` is inconsistent (a truncated env without final observation).
  void processEnvStep(const StepResult& result);
  /// GAE(lambda) over the stored rollout, bootstrapped with V(`state`'s observations).
  void computeReturns(const StepResult& state);
  /// Epochs x minibatches of the clipped PPO loss on the stored rollout (after
  /// computeReturns()); the next act() starts a new rollout.
  UpdateStats update();

  /// Transitions stored in the current rollout.
  int storedSteps() const { return step_; }
  const RolloutStorage& storage() const { return storage_; }
  const PpoConfig& config() const { return config_; }
  double learningRate() const { return learning_rate_; }
  /// Sets the Adam learning rate of every parameter group.
  void setLearningRate(double lr);
  /// Mean policy std [normalised action units].
  double actionStd();

  // For checkpoints and tests.
  ActorCritic& model() { return model_; }
  ObsNormalizer& normalizer() { return normalizer_; }
  torch::optim::Adam& optimizer() { return *optimizer_; }

 private:
  /// V of normalised observations [rows, obs_dim] (no gradients).
  torch::Tensor values(const std::vector<float>& observations, int rows);

  PpoConfig config_;
  int num_envs_, obs_dim_;
  ActorCritic model_;
  ObsNormalizer normalizer_;
  std::unique_ptr<torch::optim::Adam> optimizer_;
  RolloutStorage storage_;
  ActionScaler scaler_;
  double learning_rate_;

  int step_ = 0;         // transitions stored in this rollout
  bool acted_ = false;   // act() awaits its processEnvStep()
  ActionSample sample_;  // of the last act()
  torch::Tensor obs_;    // normalised observations of the last act()
  std::vector<float> actions_;
};

}  // namespace ppo
}  // namespace jetbot_rl
