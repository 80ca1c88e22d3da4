#pragma once

#include <torch/types.h>

#include <vector>

#include "jetbot_rl/ppo/actor_critic.h"

namespace jetbot_rl {
namespace ppo {

/// One minibatch of a rollout, flattened over steps and envs; a recurrent one holds whole env
/// sequences: `obs` [T, B, D] and `actions` [T, B, A], the others flattened t-major [T x B].
struct MiniBatch {
  torch::Tensor obs, actions, old_log_probs, old_values, advantages, returns, old_mean, old_std;
  MemoryState state;     ///< Recurrent: the envs' states at the rollout's start [B, S].
  torch::Tensor starts;  ///< Recurrent: [T, B] 1 where an episode starts at step t.
};

/// A rollout of T steps x N envs: normalised observations, actions, their log-probabilities,
/// values, rewards, episode ends and the V(final observation) of truncated steps. An image
/// policy's inputs end in `image_values` pixel values, kept as bytes.
class RolloutStorage {
 public:
  /// `obs_dim`: the network input's width without the image.
  RolloutStorage(int num_steps, int num_envs, int obs_dim, int action_dim, int image_values = 0);

  /// Records step `t` (tensors [N, ...]); `truncated_values` [N] is read where `truncated` is 1.
  void add(int t, const torch::Tensor& obs, const torch::Tensor& actions,
           const torch::Tensor& log_probs, const torch::Tensor& values, const torch::Tensor& mean,
           const torch::Tensor& std, const torch::Tensor& rewards, const torch::Tensor& terminated,
           const torch::Tensor& truncated, const torch::Tensor& truncated_values);
  /// Recurrent policies: the states [N, S] before step 0 and, per step, where episodes start
  /// ([N] float 0/1: the state was zeroed before the step).
  void setInitialState(const MemoryState& state) { initial_state_ = state; }
  void addStarts(int t, const torch::Tensor& starts) { starts_[t].copy_(starts); }
  /// GAE(lambda) with time-out bootstrapping (see computeGae); `last_values` [N] = V(obs after
  /// the last step). Advantages are then normalised to zero mean, unit std over the rollout.
  void computeReturns(const torch::Tensor& last_values, double gamma, double lambda);
  /// `num_mini_batches` shuffled minibatches (torch::randperm with the default generator).
  std::vector<MiniBatch> miniBatches(int num_mini_batches) const;
  /// `num_mini_batches` minibatches of whole env sequences (the envs shuffled with
  /// torch::randperm), for back-propagation through the rollout; <= numEnvs() of them.
  std::vector<MiniBatch> sequenceMiniBatches(int num_mini_batches) const;

  int numSteps() const { return num_steps_; }
  int numEnvs() const { return num_envs_; }
  const torch::Tensor& rewards() const { return rewards_; }
  /// [T, N, pixel values] an image policy's images as bytes (undefined without an image).
  const torch::Tensor& images() const { return images_; }
  const torch::Tensor& returns() const { return returns_; }
  const torch::Tensor& values() const { return values_; }
  /// [T, N] V(final observation) where a step was truncated, else 0.
  const torch::Tensor& truncatedValues() const { return truncated_values_; }
  /// Un-normalised GAE advantages of the last computeReturns().
  const torch::Tensor& rawAdvantages() const { return raw_advantages_; }

 private:
  int num_steps_, num_envs_, obs_dim_;
  torch::Tensor images_;  // [T, N, pixel values] bytes, or undefined
  torch::Tensor obs_, actions_, log_probs_, values_, mean_, std_, rewards_, terminated_, truncated_,
      truncated_values_;
  torch::Tensor advantages_, raw_advantages_, returns_;
  torch::Tensor starts_;  // [T, N]
  MemoryState initial_state_;
};

}  // namespace ppo
}  // namespace jetbot_rl
