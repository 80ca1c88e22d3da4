#pragma once

#include <torch/types.h>

#include <functional>
#include <memory>

#include "jetbot_rl/ppo/network_config.h"

namespace jetbot_rl {
namespace ppo {

/// Maps raw observations [R, obs_dim] to the network's units (the observation normaliser).
using Normalize = std::function<torch::Tensor(const torch::Tensor&)>;

/**
 * A policy's observation and action history per env (Isaac Lab's history_length; legged_gym's
 * previous actions): the network input is the last `obs_length` observations, newest first, each
 * normalised, then the last `action_length` actions, newest first, in normalised units ([-1, 1]).
 * An env that starts over (an episode start) holds its first observation in every slot and zero
 * actions. Observations are kept raw, so that all of them go through the normaliser of the step.
 */
class InputHistory {
 public:
  InputHistory(int num_envs, int obs_dim, int action_dim, int obs_length, int action_length);
  /// The history `config` asks for (its obs_ and action_history_length), or null without one.
  static std::unique_ptr<InputHistory> forConfig(const NetworkConfig& config, int num_envs,
                                                 int obs_dim, int action_dim);

  /// Input width: obs_length x obs_dim + action_length x action_dim.
  int inputDim() const { return obs_length_ * obs_dim_ + action_length_ * action_dim_; }
  int numEnvs() const { return num_envs_; }

  /// Pushes the observations [N, obs_dim] of every env; rows where `fresh` [N] (bool) is true
  /// start over. Returns the new input [N, inputDim()].
  torch::Tensor push(const torch::Tensor& obs, const torch::Tensor& fresh,
                     const Normalize& normalize);
  /// Pushes the actions [N, action_dim] just taken (normalised units).
  void pushActions(const torch::Tensor& actions);
  /// The input [R, inputDim()] that envs `rows` [R] (long) would get from push() with `obs`
  /// [R, obs_dim] and `fresh` [R] (bool); nothing changes. For values of states not acted on
  /// (a time-out's final observation, the observation after a rollout).
  torch::Tensor peek(const torch::Tensor& rows, const torch::Tensor& obs,
                     const torch::Tensor& fresh, const Normalize& normalize) const;

 private:
  /// The observation slots [R, obs_length, obs_dim] after pushing `obs` onto `slots`.
  torch::Tensor pushed(const torch::Tensor& slots, const torch::Tensor& obs,
                       const torch::Tensor& fresh) const;
  /// The network input from raw observation slots and action slots.
  torch::Tensor input(const torch::Tensor& obs_slots, const torch::Tensor& action_slots,
                      const Normalize& normalize) const;

  int num_envs_, obs_dim_, action_dim_, obs_length_, action_length_;
  torch::Tensor obs_;      // [N, obs_length, obs_dim] raw, newest first
  torch::Tensor actions_;  // [N, action_length, action_dim], newest first
};

}  // namespace ppo
}  // namespace jetbot_rl
