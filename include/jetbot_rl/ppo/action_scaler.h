#pragma once

#include <torch/types.h>

#include <string>
#include <vector>

#include "jetbot_rl/ppo/network_config.h"

namespace jetbot_rl {
namespace ppo {

/// Maps policy actions (normalised units) to the env's limits: squash to [-1, 1] (clip or
/// tanh), then affinely onto [low, high] per dimension (rad/s for the Jetbot's wheels).
class ActionScaler {
 public:
  /// `low`/`high` per action dimension from the spec; ConfigError unless low < high, finite.
  ActionScaler(const std::vector<float>& low, const std::vector<float>& high, ActionSquash squash);

  /// [B, A] normalised actions -> [B, A] in [-1, 1] (what the action history holds).
  torch::Tensor squash(const torch::Tensor& actions) const;
  /// [B, A] normalised actions -> [B, A] env actions.
  torch::Tensor toEnv(const torch::Tensor& actions) const;
  /// The same, flattened row-major into `out` (B x A floats, WheelTargets order).
  void toEnv(const torch::Tensor& actions, std::vector<float>& out) const;

  /// Middle and half width of each dimension's [low, high] (float tensors [A]).
  const torch::Tensor& center() const { return center_; }
  const torch::Tensor& halfRange() const { return half_range_; }
  bool tanh() const { return tanh_; }

 private:
  torch::Tensor center_, half_range_;
  bool tanh_;
};

}  // namespace ppo
}  // namespace jetbot_rl
