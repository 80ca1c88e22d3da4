#include "jetbot_rl/ppo/gae.h"

#include "jetbot_rl/ppo/torch_api.h"

namespace jetbot_rl {
namespace ppo {

GaeResult computeGae(const torch::Tensor& rewards, const torch::Tensor& values,
                     const torch::Tensor& last_values, const torch::Tensor& terminated,
                     const torch::Tensor& truncated, const torch::Tensor& truncated_values,
                     double gamma, double lambda) {
  torch::NoGradGuard no_grad;
  const int64_t steps = rewards.size(0);
  GaeResult r;
  r.advantages = torch::zeros_like(rewards);
  torch::Tensor gae = torch::zeros_like(last_values);
  for (int64_t t = steps - 1; t >= 0; --t) {
    torch::Tensor next_values = t == steps - 1 ? last_values : values[t + 1];
    next_values = torch::where(truncated[t] > 0.5, truncated_values[t], next_values);
    next_values = next_values * (1.0 - terminated[t]);
    const torch::Tensor continues = 1.0 - torch::max(terminated[t], truncated[t]);
    const torch::Tensor delta = rewards[t] + gamma * next_values - values[t];
    gae = delta + gamma * lambda * continues * gae;
    r.advantages[t] = gae;
  }
  r.returns = r.advantages + values;
  return r;
}

}  // namespace ppo
}  // namespace jetbot_rl
