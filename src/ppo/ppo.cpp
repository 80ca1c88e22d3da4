#include "jetbot_rl/ppo/ppo.h"

#include <torch/nn/utils/clip_grad.h>
#include <torch/torch.h>

#include <algorithm>

namespace jetbot_rl {
namespace ppo {

Ppo::Ppo(int obs_dim, int action_dim, const PpoConfig& config)
    : config_(config),
      model_(obs_dim, action_dim, config.actor_hidden_dims, config.critic_hidden_dims,
             config.activation, config.init_noise_std),
      normalizer_(obs_dim, config.normalize_observations),
      learning_rate_(config.learning_rate) {
  optimizer_ = std::make_unique<torch::optim::Adam>(model_->parameters(),
                                                    torch::optim::AdamOptions(learning_rate_));
}

void Ppo::setLearningRate(double lr) {
  learning_rate_ = lr;
  for (auto& group : optimizer_->param_groups()) {
    static_cast<torch::optim::AdamOptions&>(group.options()).lr(lr);
  }
}

UpdateStats Ppo::update(const RolloutStorage& storage) {
  const PpoConfig& c = config_;
  UpdateStats stats;
  int updates = 0;
  const auto params = model_->parameters();
  for (int epoch = 0; epoch < c.num_learning_epochs; ++epoch) {
    for (const MiniBatch& b : storage.miniBatches(c.num_mini_batches)) {
      const ActionEvaluation e = model_->evaluate(b.obs, b.actions);

      // KL(old || new) of diagonal Gaussians; drives the adaptive learning rate (rsl_rl).
      double kl = 0.0;
      {
        torch::NoGradGuard no_grad;
        const torch::Tensor kl_t =
            (torch::log(e.std / b.old_std) +
             (b.old_std.square() + (b.old_mean - e.mean).square()) / (2.0 * e.std.square()) - 0.5)
                .sum(-1)
                .mean();
        kl = kl_t.item<double>();
      }
      if (c.schedule == "adaptive") {
        if (kl > 2.0 * c.desired_kl) {
          setLearningRate(std::max(c.min_learning_rate, learning_rate_ / 1.5));
        } else if (kl < 0.5 * c.desired_kl && kl > 0.0) {
          setLearningRate(std::min(c.max_learning_rate, learning_rate_ * 1.5));
        }
      }

      const torch::Tensor ratio = torch::exp(e.log_probs - b.old_log_probs);
      const torch::Tensor surrogate =
          torch::max(-b.advantages * ratio,
                     -b.advantages * torch::clamp(ratio, 1.0 - c.clip_param, 1.0 + c.clip_param))
              .mean();
      torch::Tensor value_loss;
      if (c.use_clipped_value_loss) {
        const torch::Tensor clipped =
            b.old_values + torch::clamp(e.values - b.old_values, -c.clip_param, c.clip_param);
        value_loss =
            torch::max((e.values - b.returns).square(), (clipped - b.returns).square()).mean();
      } else {
        value_loss = (e.values - b.returns).square().mean();
      }
      const torch::Tensor entropy = e.entropy.mean();
      const torch::Tensor loss =
          surrogate + c.value_loss_coef * value_loss - c.entropy_coef * entropy;

      optimizer_->zero_grad();
      loss.backward();
      torch::nn::utils::clip_grad_norm_(params, c.max_grad_norm);
      optimizer_->step();

      stats.value_loss += value_loss.item<double>();
      stats.surrogate_loss += surrogate.item<double>();
      stats.entropy += entropy.item<double>();
      stats.approx_kl += kl;
      ++updates;
    }
  }
  stats.value_loss /= updates;
  stats.surrogate_loss /= updates;
  stats.entropy /= updates;
  stats.approx_kl /= updates;
  stats.learning_rate = learning_rate_;
  return stats;
}

}  // namespace ppo
}  // namespace jetbot_rl
