#pragma once

#include <torch/nn/module.h>

#include <vector>

#include "jetbot_rl/ppo/network_config.h"

namespace jetbot_rl {
namespace ppo {

/**
 * A stack of GRU or LSTM cells (torch::gru_cell / lstm_cell, PyTorch's weights and init) whose
 * state is one flat row per env, [B, stateSize()]: layer by layer, h (GRU) or h then c (LSTM).
 * All zeros is the initial state. The same cells run a step at a time when acting and over whole
 * sequences when learning, so both compute the same numbers.
 */
class RecurrentMemoryImpl : public torch::nn::Module {
 public:
  /// ConfigError unless `type` is gru or lstm and the sizes are >= 1.
  RecurrentMemoryImpl(RnnType type, int input_dim, int hidden_size, int num_layers);

  /// One step: `x` [B, input_dim] with `state` [B, stateSize()], which becomes the new state;
  /// returns the last layer's h [B, hidden_size].
  torch::Tensor step(const torch::Tensor& x, torch::Tensor& state) const;
  /// Steps through `x` [T, B, input_dim] from `state` [B, stateSize()], zeroing the state of the
  /// envs where `starts` [T, B] (float, 0 or 1) is 1 before their step t; returns [T, B, hidden].
  torch::Tensor sequence(const torch::Tensor& x, const torch::Tensor& state,
                         const torch::Tensor& starts) const;

  /// Width of the flat state: layers x hidden (GRU), layers x 2 x hidden (LSTM).
  int stateSize() const;
  int hiddenSize() const { return hidden_size_; }
  RnnType type() const { return type_; }

  /// One cell's weights (PyTorch's layout: gates stacked along the rows).
  struct Layer {
    torch::Tensor w_ih, w_hh, b_ih, b_hh;
  };
  const std::vector<Layer>& layers() const { return layers_; }

 private:
  RnnType type_;
  int hidden_size_;
  std::vector<Layer> layers_;
};
TORCH_MODULE(RecurrentMemory);

/// `state` [N, S] with the rows of the envs that start over zeroed: `starts` [N], bool or 0/1.
torch::Tensor startOver(const torch::Tensor& state, const torch::Tensor& starts);

}  // namespace ppo
}  // namespace jetbot_rl
