#pragma once

#include <torch/types.h>

#include <cstdint>

#include "jetbot_rl/ppo/ppo_config.h"

namespace jetbot_rl {
namespace ppo {

/// PPO's clipped surrogate (to minimise): mean of max(-A r, -A clamp(r, 1 - clip, 1 + clip)).
torch::Tensor clippedSurrogate(const torch::Tensor& ratio, const torch::Tensor& advantages,
                               double clip);

/// Value loss: mean squared error to `returns`; when `clipped`, the larger of it and the error
/// of the value moved at most `clip` from `old_values` (rsl_rl).
torch::Tensor valueLoss(const torch::Tensor& values, const torch::Tensor& old_values,
                        const torch::Tensor& returns, double clip, bool clipped);

/// KL(old || new) of diagonal Gaussians, summed over action dimensions, mean over samples.
double gaussianKl(const torch::Tensor& old_mean, const torch::Tensor& old_std,
                  const torch::Tensor& mean, const torch::Tensor& std);

/// rsl_rl's adaptive schedule: `lr` / 1.5 when `kl` > 2 desired_kl, x 1.5 when 0 < kl <
/// desired_kl / 2, within [min_learning_rate, max_learning_rate]; unchanged when fixed.
double adaptedLearningRate(double lr, double kl, const PpoConfig& config);

/// The learning rate's ceiling for the update of iteration `iteration` (0-based) of
/// `iterations` under lr_cooldown: infinity before its window, then falling linearly from
/// max_learning_rate (fixed: learning_rate) to min_learning_rate at the last iteration.
double learningRateCeiling(const PpoConfig& config, std::int64_t iteration,
                           std::int64_t iterations);

}  // namespace ppo
}  // namespace jetbot_rl
