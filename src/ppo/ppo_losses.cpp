#include "jetbot_rl/ppo/ppo_losses.h"

#include <algorithm>
#include <limits>

#include "jetbot_rl/ppo/torch_api.h"

namespace jetbot_rl {
namespace ppo {

torch::Tensor clippedSurrogate(const torch::Tensor& ratio, const torch::Tensor& advantages,
                               double clip) {
  return torch::max(-advantages * ratio, -advantages * torch::clamp(ratio, 1.0 - clip, 1.0 + clip))
      .mean();
}

torch::Tensor valueLoss(const torch::Tensor& values, const torch::Tensor& old_values,
                        const torch::Tensor& returns, double clip, bool clipped) {
  if (!clipped) return (values - returns).square().mean();
  const torch::Tensor moved = old_values + torch::clamp(values - old_values, -clip, clip);
  return torch::max((values - returns).square(), (moved - returns).square()).mean();
}

double gaussianKl(const torch::Tensor& old_mean, const torch::Tensor& old_std,
                  const torch::Tensor& mean, const torch::Tensor& std) {
  torch::NoGradGuard no_grad;
  return (torch::log(std / old_std) +
          (old_std.square() + (old_mean - mean).square()) / (2.0 * std.square()) - 0.5)
      .sum(-1)
      .mean()
      .item<double>();
}

double adaptedLearningRate(double lr, double kl, const PpoConfig& c) {
  if (c.schedule != LrSchedule::kAdaptive) return lr;
  if (kl > 2.0 * c.desired_kl) return std::max(c.min_learning_rate, lr / 1.5);
  if (kl < 0.5 * c.desired_kl && kl > 0.0) return std::min(c.max_learning_rate, lr * 1.5);
  return lr;
}

double learningRateCeiling(const PpoConfig& c, std::int64_t iteration, std::int64_t iterations) {
  const double window = c.lr_cooldown * static_cast<double>(iterations);
  const double left = static_cast<double>(iterations - 1 - iteration);  // iterations after this
  if (window <= 0.0 || left >= window) return std::numeric_limits<double>::infinity();
  const double top = c.schedule == LrSchedule::kAdaptive ? c.max_learning_rate : c.learning_rate;
  const double low = std::min(c.min_learning_rate, top);
  return low + (top - low) * std::max(0.0, left) / window;
}

}  // namespace ppo
}  // namespace jetbot_rl
