#include "jetbot_rl/ppo/rollout_storage.h"

#include "jetbot_rl/ppo/gae.h"
#include "jetbot_rl/ppo/torch_api.h"

namespace jetbot_rl {
namespace ppo {

RolloutStorage::RolloutStorage(int num_steps, int num_envs, int obs_dim, int action_dim,
                               int image_values)
    : num_steps_(num_steps), num_envs_(num_envs), obs_dim_(obs_dim) {
  obs_ = torch::zeros({num_steps, num_envs, obs_dim});
  // Pixels as bytes: a quarter of their floats' memory (64 x 64 rgb: 12 KB a step and env).
  if (image_values > 0) images_ = torch::zeros({num_steps, num_envs, image_values}, torch::kUInt8);
  actions_ = torch::zeros({num_steps, num_envs, action_dim});
  mean_ = torch::zeros({num_steps, num_envs, action_dim});
  std_ = torch::zeros({num_steps, num_envs, action_dim});
  log_probs_ = torch::zeros({num_steps, num_envs});
  values_ = torch::zeros({num_steps, num_envs});
  rewards_ = torch::zeros({num_steps, num_envs});
  terminated_ = torch::zeros({num_steps, num_envs});
  truncated_ = torch::zeros({num_steps, num_envs});
  truncated_values_ = torch::zeros({num_steps, num_envs});
  starts_ = torch::zeros({num_steps, num_envs});
}

void RolloutStorage::add(int t, const torch::Tensor& obs, const torch::Tensor& actions,
                         const torch::Tensor& log_probs, const torch::Tensor& values,
                         const torch::Tensor& mean, const torch::Tensor& std,
                         const torch::Tensor& rewards, const torch::Tensor& terminated,
                         const torch::Tensor& truncated, const torch::Tensor& truncated_values) {
  if (images_.defined()) {
    obs_[t].copy_(obs.narrow(-1, 0, obs_dim_));
    images_[t].copy_(obs.narrow(-1, obs_dim_, images_.size(2)));  // whole values: exact
  } else {
    obs_[t].copy_(obs);
  }
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
  const torch::Tensor images = images_.defined() ? flat(images_) : torch::Tensor();
  const torch::Tensor obs = flat(obs_), actions = flat(actions_), log_probs = flat(log_probs_),
                      values = flat(values_), advantages = flat(advantages_),
                      returns = flat(returns_), mean = flat(mean_), std = flat(std_);
  std::vector<MiniBatch> batches;
  for (int i = 0; i < num_mini_batches; ++i) {
    const torch::Tensor idx = perm.slice(0, i * size, (i + 1) * size);
    MiniBatch b;
    b.obs = obs.index_select(0, idx);
    if (images.defined()) {
      b.obs = torch::cat({b.obs, images.index_select(0, idx).to(torch::kFloat)}, -1);
    }
    b.actions = actions.index_select(0, idx);
    b.old_log_probs = log_probs.index_select(0, idx);
    b.old_values = values.index_select(0, idx);
    b.advantages = advantages.index_select(0, idx);
    b.returns = returns.index_select(0, idx);
    b.old_mean = mean.index_select(0, idx);
    b.old_std = std.index_select(0, idx);
    batches.push_back(b);
  }
  return batches;
}

std::vector<MiniBatch> RolloutStorage::sequenceMiniBatches(int num_mini_batches) const {
  const int64_t size = num_envs_ / num_mini_batches;
  const torch::Tensor perm = torch::randperm(num_envs_, torch::kLong);
  // Envs along dim 1; the flat fields t-major, as evaluateSequence flattens its outputs.
  auto envs = [](const torch::Tensor& x, const torch::Tensor& idx) {
    return x.index_select(1, idx);
  };
  auto flat = [&envs](const torch::Tensor& x, const torch::Tensor& idx) {
    return envs(x, idx).flatten(0, 1);
  };
  std::vector<MiniBatch> batches;
  for (int i = 0; i < num_mini_batches; ++i) {
    const torch::Tensor idx = perm.slice(0, i * size, (i + 1) * size);
    MiniBatch b;
    b.obs = envs(obs_, idx);
    if (images_.defined()) b.obs = torch::cat({b.obs, envs(images_, idx).to(torch::kFloat)}, -1);
    b.actions = envs(actions_, idx);
    b.old_log_probs = flat(log_probs_, idx);
    b.old_values = flat(values_, idx);
    b.advantages = flat(advantages_, idx);
    b.returns = flat(returns_, idx);
    b.old_mean = flat(mean_, idx);
    b.old_std = flat(std_, idx);
    b.state.actor = initial_state_.actor.index_select(0, idx);
    b.state.critic = initial_state_.critic.index_select(0, idx);
    b.starts = envs(starts_, idx);
    batches.push_back(b);
  }
  return batches;
}

}  // namespace ppo
}  // namespace jetbot_rl
