#pragma once

#include <torch/types.h>

namespace jetbot_rl {
namespace ppo {

/// Advantages and value targets of one rollout, both [T, N].
struct GaeResult {
  torch::Tensor advantages;
  torch::Tensor returns;  ///< advantages + values: the value function's targets.
};

/**
 * GAE(lambda) over a rollout of T steps of N envs (all tensors float, [T, N] unless noted).
 *
 * Step t of env n bootstraps with: 0 when `terminated` (a true terminal state);
 * `truncated_values[t][n]` = V(final observation) when `truncated` (a time-out is never terminal);
 * otherwise V of the next observation: `values[t + 1]`, or `last_values` [N] after the last step.
 * An ended episode (terminated or truncated) does not pass advantages back across its end.
 */
GaeResult computeGae(const torch::Tensor& rewards, const torch::Tensor& values,
                     const torch::Tensor& last_values, const torch::Tensor& terminated,
                     const torch::Tensor& truncated, const torch::Tensor& truncated_values,
                     double gamma, double lambda);

}  // namespace ppo
}  // namespace jetbot_rl
