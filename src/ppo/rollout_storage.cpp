#include "jetbot_rl/ppo/rollout_storage.h"

#include <torch/torch.h>

#include "jetbot_rl/ppo/gae.h"

namespace jetbot_rl {
namespace ppo {

RolloutStorage::RolloutStorage(int num_steps, int num_envs, int obs_dim, int action_dim)
    : num_steps_(num_steps), num_envs_(num_envs) {
  obs_ = torch::zeros({num_steps, num_envs, obs_dim});
  actions_ = torch::zeros({num_steps, num_envs, action_dim});
  mean_ = torch::zeros({num_steps, num_envs, action_dim});
  std_ = torch::zeros({num_steps, num_envs, action_dim});
  log_probs_ = torch::zeros({num_steps, num_envs});
  values_ = torch::zeros({num_steps, num_envs});
  rewards_ = torch::zeros({num_steps, num_envs});
  terminated_ = torch::zeros({num_steps, num_envs});
  truncated_ = torch::zeros({num_steps, num_envs});
  truncated_values_ = torch::zeros({num_steps, num_envs});
}

void RolloutStorage::add(int t, const torch::Tensor& obs, const torch::Tensor& actions,
                         const torch::Tensor& log_probs, const torch::Tensor& values,
                         const torch::Tensor& mean, const torch::Tensor& std,
                         const torch::Tensor& rewards, const torch::Tensor& terminated,
                         const torch::Tensor& truncated, const torch::Tensor& truncated_values) {
  obs_[t].copy_(obs);
  actions_[t].copy_(actions);
  log_probs_[t].copy_(log_probs);
  values_[t].copy_(values);
  mean_[t].copy_(mean);
  std_[t].copy_(std);
  rewards_[t].copy_(rewards);
  terminated_[t].copy_(terminated);
  truncated_[t].copy_(truncated);
  truncated_values_[t].copy_(truncated_values);
}

void RolloutStorage::computeReturns(const torch::Tensor& last_values, double gamma, double lambda) {
  const GaeResult r = computeGae(rewards_, values_, last_values, terminated_, truncated_,
                                 truncated_values_, gamma, lambda);
  raw_advantages_ = r.advantages;
  returns_ = r.returns;
  advantages_ = (r.advantages - r.advantages.mean()) / (r.advantages.std() + 1e-8);
}

std::vector<MiniBatch> RolloutStorage::miniBatches(int num_mini_batches) const {
  const int64_t total = static_cast<int64_t>(num_steps_) * num_envs_;
  const int64_t size = total / num_mini_batches;
  const torch::Tensor perm = torch::randperm(total, torch::kLong);
  auto flat = [](const torch::Tensor& x) { return x.flatten(0, 1); };
  const torch::Tensor obs = flat(obs_), actions = flat(actions_), log_probs = flat(log_probs_),
                      values = flat(values_), advantages = flat(advantages_),
                      returns = flat(returns_), mean = flat(mean_), std = flat(std_);
  std::vector<MiniBatch> batches;
  for (int i = 0; i < num_mini_batches; ++i) {
    const torch::Tensor idx = perm.slice(0, i * size, (i + 1) * size);
    batches.push_back({obs.index_select(0, idx), actions.index_select(0, idx),
                       log_probs.index_select(0, idx), values.index_select(0, idx),
                       advantages.index_select(0, idx), returns.index_select(0, idx),
                       mean.index_select(0, idx), std.index_select(0, idx)});
  }
  return batches;
}

}  // namespace ppo
}  // namespace jetbot_rl
