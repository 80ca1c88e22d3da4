#pragma once

#include <torch/optim/adam.h>

#include <limits>
#include <memory>
#include <vector>

#include "jetbot_rl/env/step_result.h"
#include "jetbot_rl/ppo/action_scaler.h"
#include "jetbot_rl/ppo/actor_critic.h"
#include "jetbot_rl/ppo/obs_normalizer.h"
#include "jetbot_rl/ppo/policy_memory.h"
#include "jetbot_rl/ppo/ppo_config.h"
#include "jetbot_rl/ppo/rollout_storage.h"
#include "jetbot_rl/ppo/update_stats.h"

namespace jetbot_rl {
namespace ppo {

/**
 * Proximal Policy Optimisation (the PPO paper, as rsl_rl's algorithms/ppo.py): owns the
 * actor-critic, its observation normaliser, Adam and the rollout, and does all the learning:
 * acting, storing each transition (time-outs bootstrapped with V(final observation)), GAE returns
 * and the clipped update over minibatches and epochs. Knows the env only through StepResult.
 * With memory (PpoConfig's history lengths, rnn_type) it keeps each env's history and recurrent
 * state, starts them over for exactly the envs whose episode ended, and learns a recurrent model
 * on whole env sequences of the rollout from their stored start states.
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
  /// Caps the learning rate of the next update()s (lr_cooldown; infinity: none).
  void setLearningRateCeiling(double ceiling) { lr_ceiling_ = ceiling; }
  /// Mean policy std [normalised action units].
  double actionStd();
  /// The network's input width (the observation, or the history stacked; an image's values
  /// follow it).
  int inputDim() const { return input_dim_; }
  /// The recurrent states of every env now [N, S] (undefined tensors without an RNN).
  const MemoryState& memoryState() const { return memory_->state(); }

  // For checkpoints and tests.
  ActorCritic& model() { return model_; }
  ObsNormalizer& normalizer() { return normalizer_; }
  torch::optim::Adam& optimizer() { return *optimizer_; }

 private:
  /// V of envs `rows` [R] if they observed `obs` [R, obs_dim] (raw) and, for an image policy,
  /// `images` [R, pixel values] next, where `fresh` [R] (bool) marks an episode start; nothing
  /// changes (no gradients).
  torch::Tensor peekValues(const torch::Tensor& rows, const torch::Tensor& obs,
                           const torch::Tensor& fresh, const torch::Tensor& images);
  torch::Tensor normalize(const torch::Tensor& obs) const { return normalizer_->normalize(obs); }

  PpoConfig config_;
  int num_envs_, obs_dim_, input_dim_;
  ImageShape image_;  // the camera image the policy observes, or none
  ActorCritic model_;
  ObsNormalizer normalizer_;
  std::unique_ptr<torch::optim::Adam> optimizer_;
  RolloutStorage storage_;
  ActionScaler scaler_;
  double learning_rate_;
  double lr_ceiling_ = std::numeric_limits<double>::infinity();

  int step_ = 0;         // transitions stored in this rollout
  bool acted_ = false;   // act() awaits its processEnvStep()
  ActionSample sample_;  // of the last act()
  torch::Tensor obs_;    // the network input of the last act()
  std::vector<float> actions_;
  std::unique_ptr<PolicyMemory> memory_;  // history, recurrent states, episode starts
};

}  // namespace ppo
}  // namespace jetbot_rl
