#include "jetbot_rl/ppo/recurrent_memory.h"

#include <cmath>
#include <string>

#include "jetbot_rl/errors.h"
#include "jetbot_rl/ppo/torch_api.h"

namespace jetbot_rl {
namespace ppo {

RecurrentMemoryImpl::RecurrentMemoryImpl(RnnType type, int input_dim, int hidden_size,
                                         int num_layers)
    : type_(type), hidden_size_(hidden_size) {
  if (type == RnnType::kNone || input_dim < 1 || hidden_size < 1 || num_layers < 1) {
    throw ConfigError("invalid recurrent memory: rnn_type " + enumName(type) + ", input " +
                      std::to_string(input_dim) + ", rnn_hidden_size " +
                      std::to_string(hidden_size) + ", rnn_num_layers " +
                      std::to_string(num_layers));
  }
  const int gates = (type == RnnType::kGru ? 3 : 4) * hidden_size;
  // PyTorch's init of nn.GRU / nn.LSTM: every weight and bias uniform in +-1/sqrt(hidden).
  const double bound = 1.0 / std::sqrt(static_cast<double>(hidden_size));
  auto uniform = [bound](std::initializer_list<int64_t> shape) {
    return torch::empty(shape).uniform_(-bound, bound);
  };
  for (int l = 0; l < num_layers; ++l) {
    const std::string k = std::to_string(l);
    Layer layer;
    layer.w_ih =
        register_parameter("weight_ih_l" + k, uniform({gates, l == 0 ? input_dim : hidden_size}));
    layer.w_hh = register_parameter("weight_hh_l" + k, uniform({gates, hidden_size}));
    layer.b_ih = register_parameter("bias_ih_l" + k, uniform({gates}));
    layer.b_hh = register_parameter("bias_hh_l" + k, uniform({gates}));
    layers_.push_back(layer);
  }
}

int RecurrentMemoryImpl::stateSize() const {
  return static_cast<int>(layers_.size()) * hidden_size_ * (type_ == RnnType::kLstm ? 2 : 1);
}

torch::Tensor RecurrentMemoryImpl::step(const torch::Tensor& x, torch::Tensor& state) const {
  const int64_t h = hidden_size_;
  std::vector<torch::Tensor> next;
  torch::Tensor input = x;
  for (std::size_t l = 0; l < layers_.size(); ++l) {
    const Layer& w = layers_[l];
    if (type_ == RnnType::kGru) {
      input = torch::gru_cell(input, state.narrow(1, l * h, h), w.w_ih, w.w_hh, w.b_ih, w.b_hh);
      next.push_back(input);
    } else {
      const auto [hy, cy] = torch::lstm_cell(
          input, {state.narrow(1, 2 * l * h, h), state.narrow(1, (2 * l + 1) * h, h)}, w.w_ih,
          w.w_hh, w.b_ih, w.b_hh);
      next.push_back(hy);
      next.push_back(cy);
      input = hy;
    }
  }
  state = torch::cat(next, 1);
  return input;
}

torch::Tensor startOver(const torch::Tensor& state, const torch::Tensor& starts) {
  return state * (1.0 - starts.to(torch::kFloat)).unsqueeze(1);
}

torch::Tensor RecurrentMemoryImpl::sequence(const torch::Tensor& x, const torch::Tensor& state,
                                            const torch::Tensor& starts) const {
  torch::Tensor s = state;
  std::vector<torch::Tensor> out;
  for (int64_t t = 0; t < x.size(0); ++t) {
    s = startOver(s, starts[t]);
    out.push_back(step(x[t], s));
  }
  return torch::stack(out);
}

}  // namespace ppo
}  // namespace jetbot_rl
