#pragma once

#include <torch/nn/module.h>

namespace jetbot_rl {
namespace ppo {

/// Running mean and variance of observations (Chan et al.'s parallel update, as rsl_rl's
/// EmpiricalNormalization); its buffers are saved with the checkpoint.
class ObsNormalizerImpl : public torch::nn::Module {
 public:
  /// `enabled` false: normalize() returns its input and update() does nothing.
  ObsNormalizerImpl(int obs_dim, bool enabled, double epsilon = 1e-2, double clip = 10.0);

  /// Folds a batch [B, obs_dim] into the statistics.
  void update(const torch::Tensor& obs);
  /// (obs - mean) / (std + epsilon), clipped to +-clip. As rsl_rl, epsilon (0.01, in obs units)
  /// bounds the gain of near-constant components (e.g. vertical velocity), whose noise would
  /// otherwise be amplified into large inputs.
  torch::Tensor normalize(const torch::Tensor& obs) const;

  torch::Tensor mean() const { return mean_; }
  torch::Tensor var() const { return var_; }
  /// Observations folded in so far.
  double count() const;
  bool enabled() const { return enabled_; }
  double epsilon() const { return epsilon_; }
  double clip() const { return clip_; }

 private:
  bool enabled_;
  double epsilon_, clip_;
  torch::Tensor mean_, var_, count_;  // float64 buffers
};
TORCH_MODULE(ObsNormalizer);

}  // namespace ppo
}  // namespace jetbot_rl
