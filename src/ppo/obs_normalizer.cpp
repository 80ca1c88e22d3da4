#include "jetbot_rl/ppo/obs_normalizer.h"

#include "jetbot_rl/ppo/torch_api.h"

namespace jetbot_rl {
namespace ppo {

ObsNormalizerImpl::ObsNormalizerImpl(int obs_dim, bool enabled, double epsilon, double clip)
    : enabled_(enabled), epsilon_(epsilon), clip_(clip) {
  mean_ = register_buffer("mean", torch::zeros({obs_dim}, torch::kDouble));
  var_ = register_buffer("var", torch::ones({obs_dim}, torch::kDouble));
  count_ = register_buffer("count", torch::zeros({}, torch::kDouble));
}

void ObsNormalizerImpl::update(const torch::Tensor& obs) {
  if (!enabled_) return;
  torch::NoGradGuard no_grad;
  const torch::Tensor x = obs.to(torch::kDouble);
  const double n = static_cast<double>(x.size(0));
  if (n == 0) return;
  const double c = count();
  const double total = c + n;
  const torch::Tensor batch_mean = x.mean(0);
  const torch::Tensor batch_var = x.var(0, /*unbiased=*/false);
  const torch::Tensor delta = batch_mean - mean_;
  // In place, so that the registered buffers stay the tensors that are saved and loaded.
  const torch::Tensor m2 = var_ * c + batch_var * n + delta * delta * (c * n / total);
  mean_.add_(delta * (n / total));
  var_.copy_(m2 / total);
  count_.fill_(total);
}

torch::Tensor ObsNormalizerImpl::normalize(const torch::Tensor& obs) const {
  if (!enabled_) return obs;
  torch::NoGradGuard no_grad;
  const torch::Tensor mean = mean_.to(obs.scalar_type());
  const torch::Tensor std = (torch::sqrt(var_) + epsilon_).to(obs.scalar_type());
  return torch::clamp((obs - mean) / std, -clip_, clip_);
}

double ObsNormalizerImpl::count() const { return count_.item<double>(); }

}  // namespace ppo
}  // namespace jetbot_rl
