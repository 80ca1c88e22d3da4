#pragma once

#include <torch/types.h>

#include <vector>

namespace jetbot_rl {
namespace ppo {

/// One minibatch of a rollout, flattened over steps and envs.
struct MiniBatch {
  torch::Tensor obs, actions, old_log_probs, old_values, advantages, returns, old_mean, old_std;
};

/// A rollout of T steps x N envs: normalised observations, actions, their log-probabilities,
/// values, rewards, episode ends and the V(final observation) of truncated steps.
class RolloutStorage {
 public:
  RolloutStorage(int num_steps, int num_envs, int obs_dim, int action_dim);

  /// Records step `t` (tensors [N, ...]); `truncated_values` [N] is read where `truncated` is 1.
  void add(int t, const torch::Tensor& obs, const torch::Tensor& actions,
           const torch::Tensor& log_probs, const torch::Tensor& values, const torch::Tensor& mean,
           const torch::Tensor& std, const torch::Tensor& rewards, const torch::Tensor& terminated,
           const torch::Tensor& truncated, const torch::Tensor& truncated_values);
  /// GAE(lambda) with time-out bootstrapping (see computeGae); `last_values` [N] = V(obs after
  /// the last step). Advantages are then normalised to zero mean, unit std over the rollout.
  void computeReturns(const torch::Tensor& last_values, double gamma, double lambda);
  /// `num_mini_batches` shuffled minibatches (torch::randperm with the default generator).
  std::vector<MiniBatch> miniBatches(int num_mini_batches) const;

  int numSteps() const { return num_steps_; }
  int numEnvs() const { return num_envs_; }
  const torch::Tensor& rewards() const { return rewards_; }
  const torch::Tensor& returns() const { return returns_; }
  const torch::Tensor& values() const { return values_; }
  /// Un-normalised GAE advantages of the last computeReturns().
  const torch::Tensor& rawAdvantages() const { return raw_advantages_; }

 private:
  int num_steps_, num_envs_;
  torch::Tensor obs_, actions_, log_probs_, values_, mean_, std_, rewards_, terminated_, truncated_,
      truncated_values_;
  torch::Tensor advantages_, raw_advantages_, returns_;
};

}  // namespace ppo
}  // namespace jetbot_rl
