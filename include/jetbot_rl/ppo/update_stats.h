#pragma once
// The figures of one PPO update, apart from ppo.h so that the iteration's figures (a CSV row, a
// ROS message) are written without libtorch's headers.

namespace jetbot_rl {
namespace ppo {

/// Means over the minibatch updates of one iteration.
struct UpdateStats {
  double value_loss = 0.0;      ///< Clipped value loss [(return units)^2].
  double surrogate_loss = 0.0;  ///< Clipped surrogate (to minimise).
  double entropy = 0.0;         ///< Policy entropy [nats].
  double approx_kl = 0.0;       ///< KL(old || new) of the Gaussians, mean per minibatch.
  double learning_rate = 0.0;   ///< Learning rate at the end of the update.
};

}  // namespace ppo
}  // namespace jetbot_rl
